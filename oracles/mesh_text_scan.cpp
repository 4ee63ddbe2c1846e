// mesh_text_scan.cpp — see mesh_text_scan.h.
#include "mesh_text_scan.h"

#include <charconv>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace vgc {
namespace {

struct Token {
  std::string_view text;
  std::size_t column;  // 1-based
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<Token> split_tokens(std::string_view line) {
  std::vector<Token> out;
  for (std::size_t i = 0; i < line.size();) {
    while (i < line.size() && is_blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i])) ++i;
    if (i > start) out.push_back({line.substr(start, i - start), start + 1});
  }
  return out;
}

// Calls f(line_number, line) for every line of `text` (without its '\n').
template <typename F>
bool for_each_line(std::string_view text, F f) {
  std::size_t n = 1;
  for (std::size_t at = 0; at < text.size(); ++n) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    if (!f(n, text.substr(at, end - at))) return false;
    at = end + 1;
  }
  return true;
}

bool fail(MeshFileError* error, std::size_t line, std::size_t column, std::string message) {
  error->line = line, error->column = column, error->message = std::move(message);
  return false;
}

std::string quoted(std::string_view s) {
  return "'" + std::string(s.substr(0, 40)) + (s.size() > 40 ? "..." : "") + "'";
}

// A whole token as a finite double, correctly rounded (std::from_chars); a
// leading '+' is allowed (iostream reads it too).
bool read_number(const Token& t, std::size_t line, double* out, MeshFileError* error) {
  std::string_view s = t.text;
  if (s.size() > 1 && s[0] == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), *out);
  if (ec == std::errc::result_out_of_range)
    return fail(error, line, t.column, quoted(t.text) + " is beyond the range of a double");
  if (ec != std::errc() || end != s.data() + s.size())
    return fail(error, line, t.column, quoted(t.text) + " is not a number");
  if (!std::isfinite(*out)) return fail(error, line, t.column, quoted(t.text) + " is not a finite number");
  return true;
}

// A whole decimal integer (the text up to `stop` when given).
bool read_integer(const Token& t, std::size_t line, long long* out, MeshFileError* error, char stop = 0) {
  std::string_view s = t.text;
  if (stop) s = s.substr(0, s.find(stop));
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), *out);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty())
    return fail(error, line, t.column, quoted(t.text) + " is not a whole number");
  return true;
}

// The statements CGAL's OBJ reader (CGAL/IO/OBJ.h) skips without error.
const std::set<std::string_view>& obj_ignored() {
  static const std::set<std::string_view> s = {
      "vt",     "vn",      "vp",       "bevel",    "lod",      "ctech",  "c_interp", "usemap", "usemtl",
      "stech",  "d_interp", "mtllib",  "shadow_obj", "trace_obj", "o",    "g",        "s",      "p",
      "cstype", "deg",     "step",     "bmat",     "con",      "curv",   "curv2",    "surf",   "parm",
      "trim",   "hole",    "scrv",     "sp",       "end",      "surf_1", "q0_1",     "q1_1",   "curv2d_1",
      "surf_2", "q0_2",    "q1_2",     "curv2d_2", "bsp",      "bzp",    "cdc",      "cdp",    "res"};
  return s;
}

// Length of the valid UTF-8 sequence at s[i], 0 if none.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((b(i + k) >> 6) != 2) return 0;
  if (n == 2 && c < 0xC2) return 0;                                    // overlong
  if (n == 3 && c == 0xE0 && b(i + 1) < 0xA0) return 0;                // overlong
  if (n == 3 && c == 0xED && b(i + 1) >= 0xA0) return 0;               // surrogate
  if (n == 4 && ((c == 0xF0 && b(i + 1) < 0x90) || c > 0xF4 || (c == 0xF4 && b(i + 1) >= 0x90))) return 0;
  return n;
}

}  // namespace

bool check_text_encoding(std::string_view bytes, MeshFileError* error) {
  if (bytes.empty()) return fail(error, 0, 0, "the file is empty (0 bytes): no mesh to read");
  auto starts = [&](std::string_view p) { return bytes.substr(0, p.size()) == p; };
  if (starts(std::string_view("\xFF\xFE\0\0", 4)) || starts(std::string_view("\0\0\xFE\xFF", 4)))
    return fail(error, 1, 1, "UTF-32 text (a byte-order mark): save the file as UTF-8 or ASCII");
  if (starts("\xFF\xFE") || starts("\xFE\xFF"))
    return fail(error, 1, 1, "UTF-16 text (a byte-order mark): save the file as UTF-8 or ASCII");
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < bytes.size();) {
    const char c = bytes[i];
    if (c == '\0')
      return fail(error, line, column,
                  "a NUL byte: UTF-16 text or binary data, not a text mesh; save the file as UTF-8 or ASCII");
    const std::size_t n = utf8_length(bytes, i);
    if (n == 0)
      return fail(error, line, column,
                  "a byte that is not UTF-8 (another encoding, or binary data): save the file as UTF-8 or ASCII");
    if (c == '\n') ++line, column = 0;
    i += n, ++column;
  }
  return true;
}

bool scan_obj_text(std::string_view text, PolygonSoup* out, MeshFileError* error) {
  out->format = "OBJ";
  struct Pending {
    long long index;
    std::size_t face, corner, line, column;
  };
  std::vector<Pending> forward;  // positive indices, checked against the final count
  const bool ok = for_each_line(text, [&](std::size_t n, std::string_view line) {
    const std::vector<Token> t = split_tokens(line);
    if (t.empty() || t[0].text[0] == '#') return true;
    if (t[0].text == "v") {
      if (t.size() < 4) return fail(error, n, t[0].column, "a vertex of fewer than 3 coordinates");
      std::array<double, 3> p{};
      for (std::size_t k = 1; k < t.size(); ++k) {
        double x = 0;
        if (!read_number(t[k], n, &x, error)) return false;
        if (k <= 3) p[k - 1] = x;
      }
      out->points.push_back(p);
      return true;
    }
    if (t[0].text == "f") {
      const std::size_t face = out->polygons.size();
      if (t.size() == 1) return fail(error, n, t[0].column, "a face with no corners");
      std::vector<std::size_t> corners;
      for (std::size_t k = 1; k < t.size(); ++k) {
        long long i = 0;
        if (!read_integer(t[k], n, &i, error, '/')) return false;
        if (i == 0) return fail(error, n, t[k].column, "corner index 0: OBJ counts vertices from 1");
        const long long have = static_cast<long long>(out->points.size());
        if (i < 0 && -i > have)
          return fail(error, n, t[k].column,
                      "corner " + std::to_string(k) + " is " + std::to_string(i) + ", before the first vertex (" +
                          std::to_string(have) + " so far)");
        if (i > 0) forward.push_back({i, face, k, n, t[k].column});
        corners.push_back(static_cast<std::size_t>(i < 0 ? have + i : i - 1));
      }
      out->polygons.push_back(std::move(corners));
      out->polygon_lines.push_back(n);
      out->polygon_columns.push_back(t[1].column);
      return true;
    }
    if (obj_ignored().count(t[0].text)) return true;
    return fail(error, n, t[0].column,
                "statement " + quoted(t[0].text) +
                    " is not one an OBJ polygon mesh has (CGAL's OBJ reader refuses it; lines 'l' are polylines)");
  });
  if (!ok) return false;
  for (const Pending& p : forward)
    if (static_cast<std::size_t>(p.index) > out->points.size())
      return fail(error, p.line, p.column,
                  "corner " + std::to_string(p.corner) + " names vertex " + std::to_string(p.index) +
                      " and the file has " + std::to_string(out->points.size()));
  return true;
}

namespace {

// OFF records: the lines with something left once '#' comments are cut.
struct Record {
  std::size_t line;
  std::vector<Token> tokens;
};

std::vector<Record> off_records(std::string_view text) {
  std::vector<Record> out;
  for_each_line(text, [&](std::size_t n, std::string_view line) {
    const std::size_t hash = line.find('#');
    std::vector<Token> t = split_tokens(hash == std::string_view::npos ? line : line.substr(0, hash));
    if (!t.empty()) out.push_back({n, std::move(t)});
    return true;
  });
  return out;
}

// The header keyword: [ST][C][N][4][n]OFF; *plain when it is 3D text OFF
// without homogeneous coordinates (what this scan reads).
bool off_keyword(std::string_view k, bool* plain) {
  if (k.size() < 3 || k.substr(k.size() - 3) != "OFF") return false;
  std::string_view prefix = k.substr(0, k.size() - 3);
  *plain = prefix.find('4') == std::string_view::npos && prefix.find('n') == std::string_view::npos;
  for (char c : prefix)
    if (c != 'S' && c != 'T' && c != 'C' && c != 'N' && c != '4' && c != 'n') return false;
  return true;
}

}  // namespace

bool scan_off_text(std::string_view text, PolygonSoup* out, bool* complete, MeshFileError* error) {
  out->format = "OFF";
  *complete = false;
  const std::vector<Record> r = off_records(text);
  if (r.empty()) return fail(error, 0, 0, "no OFF header and no records: nothing but comments or blank lines");
  std::size_t at = 0;
  std::vector<Token> counts = r[0].tokens;
  std::size_t counts_line = r[0].line;
  bool plain = true;
  if (off_keyword(r[0].tokens[0].text, &plain)) {
    for (const Token& t : r[0].tokens)
      if (t.text == "BINARY") plain = false;
    if (!plain) return true;  // CGAL's alone
    counts.erase(counts.begin());
    if (counts.empty()) {
      if (r.size() < 2) return fail(error, r[0].line, 1, "an OFF header with no counts after it");
      counts = r[1].tokens, counts_line = r[1].line, at = 2;
    } else {
      at = 1;
    }
  } else if (r[0].tokens[0].text.find("OFF") != std::string_view::npos) {
    return fail(error, r[0].line, 1, quoted(r[0].tokens[0].text) + " is not an OFF header keyword");
  } else {
    at = 1;  // no header keyword: the counts first
  }
  long long nv = 0, nf = 0;
  if (counts.size() < 2 || !read_integer(counts[0], counts_line, &nv, error) ||
      !read_integer(counts[1], counts_line, &nf, error) || nv < 0 || nf < 0) {
    if (error->message.empty() || counts.size() < 2)
      return fail(error, counts_line, 1, "OFF counts must be 'vertices faces [edges]'");
    return false;
  }
  if (static_cast<std::size_t>(nv + nf) > r.size() - at)
    return fail(error, counts_line, counts[0].column,
                "the counts announce " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                    " faces but the file has " + std::to_string(r.size() - at) + " records after them");
  out->points.reserve(static_cast<std::size_t>(nv));
  for (long long i = 0; i < nv; ++i, ++at) {
    const Record& v = r[at];
    if (v.tokens.size() < 3) return fail(error, v.line, 1, "a vertex of fewer than 3 coordinates");
    std::array<double, 3> p{};
    for (std::size_t k = 0; k < 3; ++k)
      if (!read_number(v.tokens[k], v.line, &p[k], error)) return false;
    out->points.push_back(p);
  }
  for (long long i = 0; i < nf; ++i, ++at) {
    const Record& f = r[at];
    long long n = 0;
    if (!read_integer(f.tokens[0], f.line, &n, error)) return false;
    if (n == 0) return fail(error, f.line, f.tokens[0].column, "a face with no corners");
    if (n < 0 || static_cast<std::size_t>(n) + 1 > f.tokens.size())
      return fail(error, f.line, f.tokens[0].column,
                  "a face announcing " + std::to_string(n) + " corners with " +
                      std::to_string(f.tokens.size() - 1) + " numbers after it");
    std::vector<std::size_t> corners;
    for (long long k = 1; k <= n; ++k) {
      long long vi = 0;
      const Token& t = f.tokens[static_cast<std::size_t>(k)];
      if (!read_integer(t, f.line, &vi, error)) return false;
      if (vi < 0 || vi >= nv)
        return fail(error, f.line, t.column,
                    "corner " + std::to_string(k) + " names vertex " + std::to_string(vi) + " and the file has " +
                        std::to_string(nv) + " (0-based)");
      corners.push_back(static_cast<std::size_t>(vi));
    }
    out->polygons.push_back(std::move(corners));
    out->polygon_lines.push_back(f.line);
    out->polygon_columns.push_back(f.tokens.size() > 1 ? f.tokens[1].column : 1);
  }
  *complete = true;
  return true;
}

}  // namespace vgc
