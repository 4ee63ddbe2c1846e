// coverage_record.cpp — see coverage_record.h.
#include "coverage_record.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace vgc::fuzz {
namespace {

constexpr std::size_t kMaxCounters = std::size_t{1} << 26;

std::string to_hex_bits(const std::vector<std::uint8_t>& bytes) {
  static const char digits[] = "0123456789abcdef";
  std::string out;
  out.reserve(bytes.size() / 4 + 1);
  for (std::size_t i = 0; i < bytes.size(); i += 4) {
    unsigned nibble = 0;
    for (std::size_t b = 0; b < 4 && i + b < bytes.size(); ++b)
      if (bytes[i + b]) nibble |= 1u << b;
    out += digits[nibble];
  }
  return out;
}

bool from_hex_bits(const std::string& hex, std::size_t n, std::vector<std::uint8_t>* out) {
  if (hex.size() != (n + 3) / 4) return false;
  out->assign(n, 0);
  for (std::size_t i = 0; i < hex.size(); ++i) {
    const char c = hex[i];
    const int v = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (v < 0) return false;
    for (std::size_t b = 0; b < 4; ++b)
      if (v & (1 << b)) {
        if (i * 4 + b >= n) return false;
        (*out)[i * 4 + b] = 1;
      }
  }
  return true;
}

bool parse_size(const std::string& s, std::size_t* out) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), *out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

}  // namespace

std::string module_path(const std::string& module_line) {
  const auto paren = module_line.rfind(" (");
  return paren == std::string::npos ? module_line : module_line.substr(0, paren);
}

std::string format_coverage_record(const CoverageRecord& r) {
  std::string out = "vgc-implementation-coverage 1\n";
  out += "mode " + r.mode + "\n";
  out += std::string("seen ") + (r.seen ? "1" : "0") + "\n";
  out += "counters " + std::to_string(r.counters) + "\n";
  out += "dropped " + std::to_string(r.dropped) + "\n";
  out += "function_entries " + std::to_string(r.function_entries) + "\n";
  for (const std::string& m : r.modules) out += "module " + m + "\n";
  for (const auto& [t, n] : r.timeline) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", t);
    out += std::string("timeline ") + buf + " " + std::to_string(n) + "\n";
  }
  if (!r.reached.empty()) out += "reached " + to_hex_bits(r.reached) + "\n";
  if (!r.entries.empty()) out += "entries " + to_hex_bits(r.entries) + "\n";
  char hex[16];
  for (const CoverageRecord::Function& f : r.functions) {
    std::snprintf(hex, sizeof hex, "%x", f.offset);
    out += "function " + std::to_string(f.index) + " " + std::to_string(f.module) + " " + hex + "\n";
  }
  return out;
}

bool parse_coverage_record(const std::string& text, CoverageRecord* out, std::string* error) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != "vgc-implementation-coverage 1") {
    *error = "not an implementation coverage record (first line)";
    return false;
  }
  CoverageRecord r;
  std::string reached_hex, entries_hex;
  int number = 1;
  while (std::getline(in, line)) {
    ++number;
    const auto space = line.find(' ');
    const std::string key = line.substr(0, space), value = space == std::string::npos ? "" : line.substr(space + 1);
    bool ok = true;
    if (key == "mode") r.mode = value;
    else if (key == "seen") {
      ok = value == "0" || value == "1";
      r.seen = value == "1";
    }
    else if (key == "counters") ok = parse_size(value, &r.counters) && r.counters <= kMaxCounters;
    else if (key == "dropped") ok = parse_size(value, &r.dropped);
    else if (key == "function_entries") ok = parse_size(value, &r.function_entries);
    else if (key == "module") r.modules.push_back(value);
    else if (key == "timeline") {
      const auto sp = value.find(' ');
      double t = 0;
      std::size_t n = 0;
      const std::string ts = value.substr(0, sp);
      const auto pr = std::from_chars(ts.data(), ts.data() + ts.size(), t);
      ok = sp != std::string::npos && pr.ec == std::errc() && pr.ptr == ts.data() + ts.size() &&
           parse_size(value.substr(sp + 1), &n);
      if (ok) r.timeline.emplace_back(t, n);
    } else if (key == "function") {
      std::istringstream fields(value);
      std::string index, module, offset;
      CoverageRecord::Function f;
      ok = bool(fields >> index >> module >> offset) && parse_size(index, &f.index) && parse_size(module, &f.module);
      if (ok) {
        const auto pr = std::from_chars(offset.data(), offset.data() + offset.size(), f.offset, 16);
        ok = pr.ec == std::errc() && pr.ptr == offset.data() + offset.size() && r.functions.size() < 65536;
      }
      if (ok) r.functions.push_back(f);
    } else if (key == "reached") reached_hex = value;
    else if (key == "entries") entries_hex = value;
    if (!ok) {
      *error = "line " + std::to_string(number) + ": " + line.substr(0, 80);
      return false;
    }
  }
  if ((!reached_hex.empty() && !from_hex_bits(reached_hex, r.counters, &r.reached)) ||
      (!entries_hex.empty() && !from_hex_bits(entries_hex, r.counters, &r.entries))) {
    *error = "a counter map does not match 'counters " + std::to_string(r.counters) + "'";
    return false;
  }
  *out = std::move(r);
  return true;
}

bool write_coverage_record(const std::string& path, const CoverageRecord& r) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) return false;
    f << format_coverage_record(r);
    if (!f.flush()) return false;
  }
  return std::rename(tmp.c_str(), path.c_str()) == 0;
}

CoverageTotals merge_coverage_records(const std::string& dir) {
  namespace fs = std::filesystem;
  CoverageTotals t;
  std::error_code ec;
  std::vector<std::uint8_t> reached, entries;
  std::map<std::size_t, ImplementationFunction> functions;  // by counter
  std::vector<std::pair<double, std::size_t>> points;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (e.path().extension() != ".txt") continue;
    std::ifstream f(e.path(), std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    CoverageRecord r;
    std::string error;
    if (!parse_coverage_record(ss.str(), &r, &error)) continue;
    t.recorded = true;
    if (t.mode.empty()) t.mode = r.mode;
    if (!r.seen) continue;
    t.seen = true;
    if (r.counters > t.counters) {
      t.counters = r.counters;
      t.modules = r.modules;
    }
    t.dropped = std::max(t.dropped, r.dropped);
    points.insert(points.end(), r.timeline.begin(), r.timeline.end());
    if (reached.size() < r.reached.size()) reached.resize(r.reached.size(), 0);
    for (std::size_t i = 0; i < r.reached.size(); ++i) reached[i] |= r.reached[i];
    if (entries.size() < r.entries.size()) entries.resize(r.entries.size(), 0);
    for (std::size_t i = 0; i < r.entries.size(); ++i) entries[i] |= r.entries[i];
    for (const CoverageRecord::Function& f : r.functions)
      if (f.module < r.modules.size()) functions.try_emplace(f.index, ImplementationFunction{module_path(r.modules[f.module]), f.offset, false});
  }
  std::sort(points.begin(), points.end());
  for (const auto& [when, n] : points)
    if (t.timeline.empty() || n > t.timeline.back().second) t.timeline.emplace_back(when, n);
  for (std::size_t i = 0; i < reached.size(); ++i) t.reached += reached[i] != 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    t.function_entries += entries[i] != 0;
    t.functions_entered += entries[i] != 0 && i < reached.size() && reached[i];
  }
  for (auto& [index, f] : functions) {
    f.entered = index < reached.size() && reached[index];
    t.functions.push_back(std::move(f));
  }
  return t;
}

}  // namespace vgc::fuzz
