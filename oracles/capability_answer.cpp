// capability_answer.cpp — see capability_answer.h.
#include "capability_answer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "mesh_topology.h"
#include "number_text.h"

namespace vgc::capability_answer {

Finding finding(const char* clause, std::string message, FindingStatus st) {
  return Finding{clause, st, std::move(message)};
}

// A failed call, an "error" answer or a document not of `header`: the finding, else nullopt.
std::optional<Finding> check_answer(const char* clause, const std::string& request, const Document& d,
                                    const char* header) {
  if (d.status != CallStatus::Ok) {
    // A limit of vgc's (time, answer size) is no verdict on the
    // implementation: a timeout naming what to raise, never a fail.
    const FindingStatus st = d.status == CallStatus::Timeout || !d.limit.empty() ? FindingStatus::Timeout
                             : d.status == CallStatus::Crash                     ? FindingStatus::Crash
                                                                                 : FindingStatus::Fail;
    return finding(clause,
                   std::string(call_status_name(d.status)) + " on " + request + ": " + d.detail +
                       (d.limit.empty() ? "" : " (a limit of vgc's, not a verdict: raise " + d.limit + ")"),
                   st);
  }
  if (d.text.rfind(std::string(header) + " 1\n", 0) != 0)
    return finding(clause, "answered " + request + " with \"" + d.text.substr(0, d.text.find('\n')) +
                               "\" although it claims the capability; expected a document starting \"" + header +
                               " 1\"");
  return std::nullopt;
}

// "key value" lines of a document (first word -> rest), header and end
// left out: views into `text` (a level-2 answer holds 10^6 lines; a string
// pair per line was most of reading it).
std::vector<DocumentLine> document_lines(std::string_view text) {
  std::vector<DocumentLine> out;
  std::size_t at = text.find('\n');  // past the header
  at = at == std::string_view::npos ? text.size() : at + 1;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(at, end - at);
    at = end + 1;
    if (line == "end") break;
    const auto sp = line.find(' ');
    out.emplace_back(line.substr(0, sp), sp == std::string_view::npos ? std::string_view() : line.substr(sp + 1));
  }
  return out;
}

// The words of `s` (split on spaces).
std::vector<std::string_view> words_of(std::string_view s) {
  std::vector<std::string_view> out;
  for (std::size_t i = 0; i < s.size();) {
    while (i < s.size() && s[i] == ' ') ++i;
    const std::size_t start = i;
    while (i < s.size() && s[i] != ' ') ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

std::string point_text(const std::array<double, 3>& p) {
  return "(" + format_f64(p[0]) + ", " + format_f64(p[1]) + ", " + format_f64(p[2]) + ")";
}

// Reads `text`; the problem as a message, or nullopt.
std::optional<std::string> read_subdivision(const std::string& text, SubdivisionAnswer* out) {
  for (const auto& [k, v] : document_lines(text)) {
    if (k == "vertex") {
      const std::vector<std::string_view> w = words_of(v);
      std::array<double, 3> p{};
      if (w.size() < 3 || !parse_f64(w[0], &p[0]) || !parse_f64(w[1], &p[1]) || !parse_f64(w[2], &p[2]))
        return "unreadable line \"vertex " + std::string(v) + "\"";
      out->vertices.push_back(p);
    } else if (k == "face") {
      std::vector<int> f;
      for (std::string_view w : words_of(v)) {
        std::uint32_t i = 0;
        if (!parse_uint(w, 32, &i) || i > 0x7FFFFFFFu) return "unreadable line \"face " + std::string(v) + "\"";
        f.push_back(static_cast<int>(i));
      }
      out->face_lines.push_back(std::move(f));
    } else if (k == "faces" || k == "level") {
      // A count or a level: a whole number, read exactly (number_text.h);
      // one that is not is a malformed answer, not a count of 0.
      std::uint32_t n = 0;
      if (!parse_uint(v, 32, &n) || n > 0x7FFFFFFFu)
        return "unreadable line \"" + std::string(k) + " " + std::string(v) + "\"";
      (k == "faces" ? out->faces : out->level) = static_cast<long>(n);
    }
  }
  for (const auto& f : out->face_lines)
    for (int i : f)
      if (static_cast<std::size_t>(i) >= out->vertices.size())
        return "a face line names vertex " + std::to_string(i) + " of " + std::to_string(out->vertices.size());
  return std::nullopt;
}

// Pairs every `want` vertex with the nearest unused `got` vertex within
// `tol` (max norm); got_to_want[g] is the partner of got[g] or -1. The
// first want vertex left without a partner, or nullopt when all have one;
// with `all_unmatched`, goes on and lists every want vertex left without.
// The answer is sorted by (x cell of width tol, y): a want vertex looks in
// three x cells, each by binary search on y, so a mesh whose vertices share
// one x (a plane x = c: every level of a cube's face) costs n log n, not n^2
// as a window on x alone did.
std::optional<std::size_t> match_vertices(const std::vector<std::array<double, 3>>& got,
                                          const std::vector<std::array<double, 3>>& want, double tol,
                                          std::vector<int>* got_to_want,
                                          std::vector<std::size_t>* all_unmatched) {
  auto cell = [tol](double x) { return static_cast<long long>(std::floor(x / tol)); };
  struct Key {
    long long cx;
    double y;
    std::size_t g;
  };
  std::vector<Key> keys(got.size());
  for (std::size_t g = 0; g < got.size(); ++g) keys[g] = {cell(got[g][0]), got[g][1], g};
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.cx != b.cx ? a.cx < b.cx : a.y < b.y; });
  got_to_want->assign(got.size(), -1);
  for (std::size_t w = 0; w < want.size(); ++w) {
    const auto& p = want[w];
    std::size_t best = got.size();
    double best_d = tol;
    const long long c = cell(p[0]);
    for (long long cx = c - 1; cx <= c + 1; ++cx) {
      auto lo = std::lower_bound(keys.begin(), keys.end(), Key{cx, p[1] - tol, 0},
                                 [](const Key& a, const Key& b) { return a.cx != b.cx ? a.cx < b.cx : a.y < b.y; });
      for (auto it = lo; it != keys.end() && it->cx == cx && it->y <= p[1] + tol; ++it) {
        const std::size_t g = it->g;
        if ((*got_to_want)[g] >= 0) continue;
        const double dist =
            std::max({std::fabs(got[g][0] - p[0]), std::fabs(got[g][1] - p[1]), std::fabs(got[g][2] - p[2])});
        if (dist <= best_d) best = g, best_d = dist;
      }
    }
    if (best == got.size()) {
      if (!all_unmatched) return w;
      all_unmatched->push_back(w);
      continue;
    }
    (*got_to_want)[best] = static_cast<int>(w);
  }
  if (all_unmatched && !all_unmatched->empty()) return all_unmatched->front();
  return std::nullopt;
}

bool near(const std::array<double, 3>& a, const std::array<double, 3>& b, double tol) {
  return std::max({std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1]), std::fabs(a[2] - b[2])}) <= tol;
}

// 1e-9 times the largest coordinate magnitude of `positions` (at least 1).
double tolerance_of(const std::vector<std::array<double, 3>>& positions) {
  double scale = 1;
  for (const auto& p : positions)
    for (double c : p) scale = std::max(scale, std::fabs(c));
  return 1e-9 * scale;
}

// Compares an answer's vertices and face count with a refined level: the
// counts, then the vertices as a bijection. The message, or nullopt.
std::optional<std::string> compare_with_level(const SubdivisionAnswer& got, const std::vector<std::array<double, 3>>& want,
                                              long want_faces, const std::string& oracle, std::vector<int>* got_to_want) {
  if (got.faces != want_faces)
    return std::to_string(got.faces) + " faces; " + oracle + " refines to " + std::to_string(want_faces);
  if (got.vertices.size() != want.size())
    return std::to_string(got.vertices.size()) + " vertices; " + oracle + " refines to " + std::to_string(want.size());
  const double tol = tolerance_of(want);
  if (auto w = match_vertices(got.vertices, want, tol, got_to_want))
    return oracle + " has a vertex at " + point_text(want[*w]) + " and the answer has none within " + format_f64(tol) +
           " (not already matched)";
  return std::nullopt;
}

// OpenSubdiv's uniform refinement of `mesh` to `level` with `scheme`, on
// every mesh a node can hold, non-manifold included (the reference follows
// OpenSubdiv's non-manifold rules, catmull_clark.h). nullopt, with *why,
// where OpenSubdiv cannot be asked: polygons that are no valid input
// (check_mesh; a node holds none such) or a mesh OpenSubdiv refuses.
std::optional<OsdResult> oracle_refinement(const MeshArrays& mesh, OsdScheme scheme, int level, std::string* why) {
  int bad_face = -1;
  if (const MeshStatus status = check_mesh(mesh, &bad_face); status != MeshStatus::Ok) {
    *why = std::string("the polygons are no input for OpenSubdiv (") + to_string(status) + " at face " +
           std::to_string(bad_face) + ")";
    return std::nullopt;
  }
  OsdResult osd = osd_refine_uniform(osd_input_from_mesh(mesh, scheme, level));
  if (!osd.ok || osd.levels.size() != static_cast<std::size_t>(level) + 1) {
    *why = "OpenSubdiv refuses the polygons (" + (osd.ok ? std::string("too few levels") : osd.failure);
    for (const auto& m : osd.messages) *why += "; " + m;
    *why += ")";
    return std::nullopt;
  }
  return osd;
}

// A case the oracle cannot judge (FindingStatus::NotJudged).
Finding not_judged(const char* clause, const std::string& message) {
  Finding f;
  f.clause = clause;
  f.status = FindingStatus::NotJudged;
  f.message = message;
  return f;
}

}  // namespace vgc::capability_answer
