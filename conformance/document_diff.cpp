// document_diff.cpp — see document_diff.h.
#include "document_diff.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "command.h"
#include "number_text.h"
#include "snapshot.h"

namespace vgc {

std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  std::string w;
  while (in >> w) out.push_back(w);
  return out;
}

namespace {

std::string first_word(const std::string& line) {
  const auto w = split_words(line);
  return w.empty() ? std::string() : w[0];
}

bool close(double a, double b) {
  if (a == b) return true;
  const double scale = std::max({1.0, std::fabs(a), std::fabs(b)});
  return std::fabs(a - b) <= kPoseTolerance * scale;
}

// "bone_pose <id> px py pz qx qy qz qw": same id, positions close, and the
// rotations close up to sign.
bool poses_match(const std::string& a, const std::string& b) {
  const auto wa = split_words(a), wb = split_words(b);
  if (wa.size() != 9 || wb.size() != 9 || wa[0] != "bone_pose" || wb[0] != "bone_pose" || wa[1] != wb[1])
    return false;
  double va[7], vb[7];
  for (int i = 0; i < 7; ++i)
    if (!parse_f64(wa[2 + i], &va[i]) || !parse_f64(wb[2 + i], &vb[i])) return false;
  for (int i = 0; i < 3; ++i)
    if (!close(va[i], vb[i])) return false;
  bool same = true, opposite = true;
  for (int i = 3; i < 7; ++i) {
    same = same && close(va[i], vb[i]);
    opposite = opposite && close(va[i], -vb[i]);
  }
  return same || opposite;
}

// A snapshot "layer" line reduced to what the spec gives meaning to
// (snapshot.h used_defaults, docs/commands.md 6.1): a default the layer's
// type does not use becomes "-" whatever was printed, and a
// POLYGON_FACE_UINT8 layer's def_uint keeps its low 8 bits (all its slots
// take, LAYER-DEFAULT-1). Any other line, or a layer line that does not
// parse, is returned unchanged (and then differs as printed).
std::string comparable_line(const std::string& line) {
  static const std::string kHead = "layer ";
  if (line.rfind(kHead, 0) != 0) return line;
  const std::size_t id_end = line.find(' ', kHead.size());
  if (id_end == std::string::npos) return line;
  std::uint32_t id = 0;
  if (!parse_uint(std::string_view(line).substr(kHead.size(), id_end - kHead.size()), 16, &id)) return line;
  std::string name;
  std::size_t used = 0, error_at = 0;
  if (!parse_quoted(std::string_view(line).substr(id_end + 1), &name, &used, &error_at)) return line;
  const std::size_t name_end = id_end + 1 + used;
  auto w = split_words(line.substr(name_end));
  if (w.size() != 4 || name_end >= line.size() || line[name_end] != ' ') return line;
  std::uint8_t raw = 0;
  if (!parse_layer_type_name(w[0], &raw)) return line;
  const LayerType type = static_cast<LayerType>(raw);
  const UsedDefaults meaning = used_defaults(static_cast<std::uint16_t>(id), type);
  if (!meaning.def_uint) {
    w[1] = "-";
  } else if (type == LayerType::PolygonFaceUint8) {
    std::uint32_t v = 0;
    if (parse_uint(w[1], 32, &v)) w[1] = format_uint(v & 0xFFu, 32);
  }
  if (!meaning.def_real) w[2] = "-";
  return line.substr(0, name_end) + " " + w[0] + " " + w[1] + " " + w[2] + " " + w[3];
}

bool lines_match(const std::string& expected, const std::string& observed) {
  if (expected == observed) return true;
  return first_word(expected) == "bone_pose" && poses_match(expected, observed);
}

}  // namespace

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t nl = text.find('\n', start);
    if (nl == std::string::npos) nl = text.size();
    std::string line = text.substr(start, nl - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = nl + 1;
  }
  return lines;
}

std::string without_subscriptions(const std::string& snapshot) {
  std::string out;
  out.reserve(snapshot.size());
  std::size_t start = 0;
  while (start < snapshot.size()) {
    std::size_t nl = snapshot.find('\n', start);
    const bool has_nl = nl != std::string::npos;
    if (!has_nl) nl = snapshot.size();
    std::string_view line(snapshot.data() + start, nl - start);
    const std::size_t last = line.rfind(' ');
    if (line.rfind("layer ", 0) == 0 && last != std::string_view::npos) {
      out.append(line.substr(0, last + 1));
      out += '-';
    } else {
      out.append(line);
    }
    if (has_nl) out += '\n';
    start = nl + 1;
  }
  return out;
}

std::string line_key(const std::string& line) {
  const std::string kind = first_word(line);
  std::size_t words = 2;
  if (kind == "slot" || kind == "edge_crease") words = 3;
  if (kind == "crease_vertex" || kind == "crease_edge") words = 1;
  std::size_t pos = 0;
  for (std::size_t w = 0; w < words; ++w) {
    pos = line.find(' ', w == 0 ? 0 : pos + 1);
    if (pos == std::string::npos) return line;
  }
  return line.substr(0, pos);
}

std::string without_keys(const std::string& document, const std::set<std::string>& keys) {
  if (keys.empty()) return document;
  std::string out;
  out.reserve(document.size());
  for (const std::string& line : split_lines(document)) {
    if (keys.count(line_key(line)) > 0) continue;
    out += line;
    out += '\n';
  }
  return out;
}

std::vector<DocumentDifference> all_differences(const std::string& expected, const std::string& observed,
                                                std::size_t max) {
  std::vector<DocumentDifference> out;
  std::set<std::string> seen;
  while (out.size() < max) {
    auto d = diff_documents(without_keys(expected, seen), without_keys(observed, seen));
    if (!d) break;
    const std::size_t before = seen.size();
    if (!d->expected_line.empty()) seen.insert(line_key(d->expected_line));
    if (!d->observed_line.empty()) seen.insert(line_key(d->observed_line));
    out.push_back(std::move(*d));
    if (seen.size() == before) break;  // a line with no key of its own: nothing more to tell apart
  }
  return out;
}

std::string DocumentDifference::describe() const {
  if (observed_line.empty()) return "missing line: expected \"" + expected_line + "\"";
  if (expected_line.empty()) return "unexpected line: \"" + observed_line + "\"";
  return "expected \"" + expected_line + "\", observed \"" + observed_line + "\"";
}

std::optional<DocumentDifference> diff_documents(const std::string& expected, const std::string& observed) {
  if (expected == observed) return std::nullopt;
  const auto e_printed = split_lines(expected), o_printed = split_lines(observed);
  std::vector<std::string> e, o;  // compared as comparable_line; reported as printed
  for (const auto& l : e_printed) e.push_back(comparable_line(l));
  for (const auto& l : o_printed) o.push_back(comparable_line(l));
  // Walk both in order. Lines of a canonical document are unique and
  // sorted within each section, so a line present on one side only is a
  // missing or extra line; a changed line shows up as a pair that share
  // their key (first two words).
  const std::multiset<std::string> eset(e.begin(), e.end()), oset(o.begin(), o.end());
  std::size_t i = 0, j = 0;
  while (i < e.size() || j < o.size()) {
    if (i < e.size() && j < o.size() && lines_match(e[i], o[j])) {
      ++i, ++j;
      continue;
    }
    DocumentDifference d;
    const auto key = [](const std::string& l) {
      const auto w = split_words(l);
      return w.size() >= 2 ? w[0] + " " + w[1] : l;
    };
    if (i < e.size() && j < o.size() && key(e[i]) == key(o[j])) {
      d.expected_line = e_printed[i];
      d.observed_line = o_printed[j];
    } else if (i < e.size() && (j >= o.size() || oset.count(e[i]) == 0)) {
      d.expected_line = e_printed[i];  // the implementation lacks it
    } else if (j < o.size()) {
      d.observed_line = o_printed[j];  // the implementation has an extra line
    } else {
      d.expected_line = e_printed[i];
    }
    d.kind = first_word(d.expected_line.empty() ? d.observed_line : d.expected_line);
    return d;
  }
  return std::nullopt;  // equal up to tolerance
}

}  // namespace vgc
