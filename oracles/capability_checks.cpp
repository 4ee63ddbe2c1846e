// capability_checks.cpp — see capability_checks.h.
#include "capability_checks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "cgal_manifold.h"
#include "crease_sharpness.h"
#include "hierarchical_edit.h"
#include "mesh_arrays.h"
#include "mesh_topology.h"
#include "number_text.h"
#include "osd_subdivision.h"
#include "split_normals.h"

namespace vgc {
namespace {

Finding finding(const char* clause, std::string message, FindingStatus st = FindingStatus::Fail) {
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
using DocumentLine = std::pair<std::string_view, std::string_view>;
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

// A ?subdivide-like document: "level", "vertex x y z" lines, optional
// "face i j k ..." lines (indices into the vertex lines), "faces <count>".
struct SubdivisionAnswer {
  long level = -1, faces = -1;
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::vector<int>> face_lines;
};

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
    } else if (k == "faces") {
      out->faces = std::strtol(std::string(v).c_str(), nullptr, 10);
    } else if (k == "level") {
      out->level = std::strtol(std::string(v).c_str(), nullptr, 10);
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
                                          std::vector<std::size_t>* all_unmatched = nullptr) {
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

}  // namespace

std::optional<Finding> check_classify(const Node& model, Implementation& sut) {
  static const char* kClause = "MESH-CLASSIFY-1";
  const Document d = sut.request("?classify");
  if (auto f = check_answer(kClause, "?classify", d, "vgc-classify")) return f;
  std::map<std::string, std::string> got;
  for (const auto& [k, v] : document_lines(d.text)) got[std::string(k)] = std::string(v);

  const MeshArrays mesh = extract_mesh(model);
  const CgalManifoldReport cgal = cgal_classify_mesh(mesh);
  if (cgal.status != MeshStatus::Ok) return std::nullopt;  // CGAL cannot answer for this soup
  std::vector<std::pair<std::string, std::string>> expected;
  const bool pm = cgal.soup_is_polygon_mesh;
  expected.emplace_back("polygon_mesh", pm ? "yes" : "no");
  if (pm && cgal.mesh_built && cgal.mesh_matches_input) {
    expected.emplace_back("closed", cgal.closed ? "yes" : "no");
    if (cgal.consistently_oriented) expected.emplace_back("oriented", *cgal.consistently_oriented ? "yes" : "no");
    expected.emplace_back("euler", std::to_string(cgal.euler_characteristic));
    expected.emplace_back("components", std::to_string(cgal.component_count));
    expected.emplace_back("boundary_loops", std::to_string(cgal.boundary_cycles.size()));
  }
  for (const auto& [key, want] : expected) {
    auto it = got.find(key);
    const std::string have = it == got.end() ? "(missing)" : it->second;
    if (have != want)
      return finding(kClause, "?classify says " + key + " " + have + "; CGAL Polygon Mesh Processing says " + want +
                                  " for the node's " + std::to_string(mesh.face_count()) + " polygons");
  }
  return std::nullopt;
}

std::optional<Finding> check_subdivision(const Node& model, Implementation& sut, int level) {
  static const char* kClause = "SUBD-CATMARK-1";
  const std::string request = "?subdivide " + std::to_string(level);
  const Document d = sut.request(request);
  if (auto f = check_answer(kClause, request, d, "vgc-subdivision")) return f;
  SubdivisionAnswer got;
  if (auto problem = read_subdivision(d.text, &got)) return finding(kClause, request + ": " + *problem);
  if (got.level != level) return finding(kClause, request + ": the document says level " + std::to_string(got.level));

  const MeshArrays mesh = remove_unused_vertices(extract_mesh(model));
  if (mesh.face_count() == 0) {
    if (!got.vertices.empty() || got.faces != 0)
      return finding(kClause, request + ": no polygons, yet " + std::to_string(got.vertices.size()) + " vertices and " +
                                  std::to_string(got.faces) + " faces");
    return std::nullopt;
  }
  std::string why;
  const std::optional<OsdResult> osd = oracle_refinement(mesh, OsdScheme::CatmullClark, level, &why);
  if (!osd) return not_judged(kClause, request + ": " + why);
  const OsdLevel& want = osd->levels.back();
  std::vector<int> got_to_want;
  if (auto problem = compare_with_level(got, want.positions, static_cast<long>(want.face_sizes.size()), "OpenSubdiv",
                                        &got_to_want))
    return finding(kClause, request + ": " + *problem);
  return std::nullopt;
}

namespace {

// A mesh's corners as check_normals reads them (face_offsets order): each
// corner's polygon and place in it, and the corners using each edge.
// Corner c carries the edge c -> next. The corners using each edge: corners
// sorted by edge key, each corner's run of that order (sorting, not a map of
// vectors: linear-ish in the mesh).
struct NormalsCorners {
  const MeshArrays& mesh;
  std::vector<int> corner_face, corner_index;
  std::vector<std::size_t> sorted_corner, run_start, run_size;

  explicit NormalsCorners(const MeshArrays& m) : mesh(m) {
    const std::size_t corners = mesh.face_vertices.size();
    corner_face.resize(corners);
    corner_index.resize(corners);
    for (int f = 0; f < mesh.face_count(); ++f)
      for (int k = 0; k < mesh.face_sizes[static_cast<std::size_t>(f)]; ++k) {
        const auto c = static_cast<std::size_t>(mesh.face_offsets[static_cast<std::size_t>(f)] + k);
        corner_face[c] = f, corner_index[c] = k;
      }
    group_by_edge();
  }

  void group_by_edge() {
    const std::size_t corners = mesh.face_vertices.size();
    std::vector<std::pair<std::uint64_t, std::size_t>> by_edge(corners);
    for (std::size_t c = 0; c < corners; ++c) by_edge[c] = {edge_key(c), c};
    std::sort(by_edge.begin(), by_edge.end());
    sorted_corner.resize(corners);
    run_start.resize(corners);
    run_size.resize(corners);
    for (std::size_t i = 0; i < corners;) {
      std::size_t j = i;
      while (j < corners && by_edge[j].first == by_edge[i].first) ++j;
      for (std::size_t k = i; k < j; ++k) {
        sorted_corner[k] = by_edge[k].second;
        run_start[by_edge[k].second] = i, run_size[by_edge[k].second] = j - i;
      }
      i = j;
    }
  }

  std::string name(std::size_t c) const {
    return "corner " + std::to_string(corner_index[c]) + " of polygon " +
           std::to_string(mesh.polygon_ids[static_cast<std::size_t>(corner_face[c])]);
  }
  std::size_t corner_at(std::size_t c, int step) const {
    const auto f = static_cast<std::size_t>(corner_face[c]);
    const int n = mesh.face_sizes[f];
    return static_cast<std::size_t>(mesh.face_offsets[f] + (corner_index[c] + step + n) % n);
  }
  std::uint64_t edge_key(std::size_t c) const {
    const auto a = static_cast<std::uint32_t>(mesh.face_vertices[c]);
    const auto b = static_cast<std::uint32_t>(mesh.face_vertices[corner_at(c, 1)]);
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
  }
  std::vector<std::size_t> uses_of(std::size_t c) const {
    return std::vector<std::size_t>(sorted_corner.begin() + static_cast<std::ptrdiff_t>(run_start[c]),
                                    sorted_corner.begin() + static_cast<std::ptrdiff_t>(run_start[c] + run_size[c]));
  }
  // The edges, as spec 003 defines sharpness: tagged (a corner crease
  // 0xFFFFFFFF on either side), not used by exactly two faces, or used by
  // two faces in the same direction.
  bool sharp(std::size_t c) const {
    const auto u = uses_of(c);
    if (u.size() != 2 || mesh.face_vertices[u[0]] == mesh.face_vertices[u[1]]) return true;
    for (std::size_t x : u)
      if (x < mesh.corner_edge_creases.size() && mesh.corner_edge_creases[x] == 0xFFFFFFFFu) return true;
    return false;
  }
};

constexpr const char* kNormalsClause = "NORMALS-SPLIT-1";
constexpr double kNormalsTolerance = 1e-9;

bool normals_differ(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::max({std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1]), std::fabs(a[2] - b[2])}) > kNormalsTolerance;
}

// The answer's "corner POLYGON CORNER X Y Z" lines, per corner of the mesh
// (face_offsets order): a finding for an unreadable line, a corner of no
// live polygon, a corner given twice or a corner without a line.
std::optional<Finding> read_corner_normals(const std::string& request, const Document& d, const NormalsCorners& at,
                                           std::vector<std::array<double, 3>>* got) {
  const MeshArrays& mesh = at.mesh;
  std::unordered_map<std::uint32_t, int> face_of_id;
  for (int f = 0; f < mesh.face_count(); ++f) face_of_id[mesh.polygon_ids[static_cast<std::size_t>(f)]] = f;
  const std::size_t corners = mesh.face_vertices.size();
  got->assign(corners, {});
  std::vector<char> seen(corners, 0);
  for (const auto& [k, v] : document_lines(d.text)) {
    const std::vector<std::string_view> w = words_of(v);
    std::uint32_t id = 0, corner = 0;
    std::array<double, 3> n{};
    if (k != "corner" || w.size() < 5 || !parse_uint(w[0], 32, &id) || !parse_uint(w[1], 32, &corner) ||
        !parse_f64(w[2], &n[0]) || !parse_f64(w[3], &n[1]) || !parse_f64(w[4], &n[2]))
      return finding(kNormalsClause, request + ": unreadable line \"" + std::string(k) + " " + std::string(v) + "\"");
    auto it = face_of_id.find(id);
    if (it == face_of_id.end() || static_cast<int>(corner) >= mesh.face_sizes[static_cast<std::size_t>(it->second)])
      return finding(kNormalsClause, request + ": \"corner " + std::string(v) + "\" names no corner of a live polygon");
    const auto c = static_cast<std::size_t>(mesh.face_offsets[static_cast<std::size_t>(it->second)]) + corner;
    if (seen[c])
      return finding(kNormalsClause, request + ": corner " + std::string(w[0]) + " " + std::string(w[1]) + " is given twice");
    seen[c] = 1;
    (*got)[c] = n;
  }
  for (std::size_t c = 0; c < corners; ++c)
    if (!seen[c]) return finding(kNormalsClause, request + ": no line for " + at.name(c));
  return std::nullopt;
}

// (a) Across a smooth edge a -> b (corner c) / b -> a (corner o), the
// corners at a (c and next(o)) and at b (next(c) and o) share a fan (spec
// 003: a smooth fan has one normal).
std::optional<Finding> check_smooth_fans(const std::string& request, const NormalsCorners& at,
                                         const std::vector<std::array<double, 3>>& got) {
  for (std::size_t c = 0; c < got.size(); ++c) {
    if (at.sharp(c)) continue;
    const auto u = at.uses_of(c);
    const std::size_t o = u[0] == c ? u[1] : u[0];
    for (const auto& [p, q] : {std::make_pair(c, at.corner_at(o, 1)), std::make_pair(at.corner_at(c, 1), o)})
      if (normals_differ(got[p], got[q]))
        return finding(kNormalsClause, request + ": " + at.name(p) + " has normal " + point_text(got[p]) + " and " +
                                           at.name(q) + " has " + point_text(got[q]) +
                                           "; they are one smooth fan (joined by a smooth "
                                           "edge of polygon " +
                                           std::to_string(at.mesh.polygon_ids[static_cast<std::size_t>(at.corner_face[c])]) +
                                           ") and spec 003 gives a smooth fan one normal");
  }
  return std::nullopt;
}

// (b) A corner between two sharp edges is a fan of its own: its normal is
// its polygon's front normal (clockwise front: minus Newell's area vector).
std::optional<Finding> check_sharp_corners(const std::string& request, const NormalsCorners& at,
                                           const std::vector<std::array<double, 3>>& got) {
  const MeshArrays& mesh = at.mesh;
  for (std::size_t c = 0; c < got.size(); ++c) {
    if (!at.sharp(c) || !at.sharp(at.corner_at(c, -1))) continue;
    std::array<double, 3> area{0, 0, 0};
    for (int k = 0; k < mesh.face_sizes[static_cast<std::size_t>(at.corner_face[c])]; ++k) {
      const std::size_t here = at.corner_at(c, k);
      const auto& p = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[here])];
      const auto& q = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[at.corner_at(here, 1)])];
      area[0] -= p[1] * q[2] - p[2] * q[1];
      area[1] -= p[2] * q[0] - p[0] * q[2];
      area[2] -= p[0] * q[1] - p[1] * q[0];
    }
    const double len = std::sqrt(area[0] * area[0] + area[1] * area[1] + area[2] * area[2]);
    if (!(len > 1e-12)) continue;  // degenerate polygon: no face normal to compare with
    for (double& x : area) x /= len;
    if (normals_differ(got[c], area))
      return finding(kNormalsClause, request + ": " + at.name(c) + " lies between two sharp edges, so its normal is its "
                                         "polygon's front normal " + point_text(area) + "; the answer says " +
                                         point_text(got[c]));
  }
  return std::nullopt;
}

}  // namespace

std::optional<Finding> check_normals(const Node& model, Implementation& sut) {
  const MeshArrays mesh = extract_mesh(model);
  const SplitNormals ref = compute_split_normals(mesh);
  if (ref.status != MeshStatus::Ok) return std::nullopt;  // no reading of spec 003 for such polygons
  // Products of coordinates beyond 1e60 overflow the normal's length in
  // doubles; the spec says nothing of such meshes: not compared.
  for (int v : mesh.face_vertices)
    for (double c : mesh.positions[static_cast<std::size_t>(v)])
      if (!(std::fabs(c) <= 1e60)) return std::nullopt;
  const std::string request = "?normals";
  const Document d = sut.request(request);
  if (auto f = check_answer(kNormalsClause, request, d, "vgc-normals")) return f;

  const NormalsCorners at(mesh);
  std::vector<std::array<double, 3>> got;
  if (auto f = read_corner_normals(request, d, at, &got)) return f;
  if (auto f = check_smooth_fans(request, at, got)) return f;
  if (auto f = check_sharp_corners(request, at, got)) return f;
  // Then every corner against the reference's reading (angle-weighted fans).
  for (std::size_t c = 0; c < got.size(); ++c)
    if (normals_differ(got[c], ref.corner_normals[c]))
      return finding(kNormalsClause, request + ": " + at.name(c) + " has normal " + point_text(got[c]) +
                                         "; the reference's split normal (angle-weighted over its smooth fan) is " +
                                         point_text(ref.corner_normals[c]));
  return std::nullopt;
}

std::optional<Finding> check_loop(const Node& model, Implementation& sut, int level) {
  static const char* kClause = "LOOP-TRIANGLE-1";
  const std::string request = "?subdivide-loop " + std::to_string(level);
  const MeshArrays mesh = remove_unused_vertices(extract_mesh(model));
  const Document d = sut.request(request);
  bool triangles = true;
  for (int size : mesh.face_sizes) triangles = triangles && size == 3;
  if (!triangles) {
    // Loop subdivides triangles only (OpenSubdiv's SCHEME_LOOP refuses other faces).
    if (d.status == CallStatus::Ok && (d.text == "error\n" || d.text.rfind("error ", 0) == 0)) return std::nullopt;
    if (auto f = check_answer(kClause, request, d, "vgc-subdivision")) return f;
    return finding(kClause, request + ": answered a document although a live polygon is a quad; the answer must be "
                                "one line \"error ...\"");
  }
  if (auto f = check_answer(kClause, request, d, "vgc-subdivision")) return f;
  SubdivisionAnswer got;
  if (auto problem = read_subdivision(d.text, &got)) return finding(kClause, request + ": " + *problem);
  if (got.level != level) return finding(kClause, request + ": the document says level " + std::to_string(got.level));
  if (mesh.face_count() == 0) {
    if (!got.vertices.empty() || got.faces != 0 || !got.face_lines.empty())
      return finding(kClause, request + ": no polygons, yet " + std::to_string(got.vertices.size()) + " vertices and " +
                                  std::to_string(got.faces) + " faces");
    return std::nullopt;
  }
  std::string why;
  const std::optional<OsdResult> refined = oracle_refinement(mesh, OsdScheme::Loop, level, &why);
  if (!refined) return not_judged(kClause, request + ": " + why);
  const OsdResult& osd = *refined;
  std::vector<int> got_to_want;
  if (auto problem = compare_with_level(got, osd.levels.back().positions,
                                        static_cast<long>(osd.levels.back().face_sizes.size()), "OpenSubdiv Loop",
                                        &got_to_want))
    return finding(kClause, request + ": " + *problem);

  // The triangle tree (spec 004), built on OpenSubdiv's levels: base
  // triangles in order; the children of [v0 v1 v2] are T0 = [s0 s1 s2] (the
  // centre) and T(j+1) = [vj' s(j+2) s(j+1)] (nearest vertex j), sk the
  // child of the edge opposite vertex k, vj' the child of vertex j. Each
  // must be one of OpenSubdiv's child faces of the parent, same orientation.
  struct Tri {
    int face;
    std::array<int, 3> v;
  };
  std::vector<Tri> tree;
  const OsdLevel& base = osd.levels.front();
  for (int f = 0; f < static_cast<int>(base.face_sizes.size()); ++f)
    tree.push_back({f, {base.face_vertices[3 * f], base.face_vertices[3 * f + 1], base.face_vertices[3 * f + 2]}});
  for (int l = 1; l <= level; ++l) {
    const OsdLevel& parent = osd.levels[static_cast<std::size_t>(l - 1)];
    const OsdLevel& child = osd.levels[static_cast<std::size_t>(l)];
    std::vector<Tri> next;
    for (const Tri& t : tree) {
      std::array<int, 3> s{}, vc{};
      for (int k = 0; k < 3; ++k) {
        // The edge opposite vertex k, through the parent face's own edges
        // (GetFaceEdges; never by vertex pair: a Loop "pillow" has two
        // edges on one pair).
        const int a = t.v[static_cast<std::size_t>((k + 1) % 3)], b = t.v[static_cast<std::size_t>((k + 2) % 3)];
        int edge = -1;
        for (int c = 0; c < 3; ++c)
          if (parent.face_vertices[static_cast<std::size_t>(3 * t.face + c)] == a &&
              parent.face_vertices[static_cast<std::size_t>(3 * t.face + (c + 1) % 3)] == b)
            edge = parent.face_edges[static_cast<std::size_t>(3 * t.face + c)];
        if (edge < 0)
          return not_judged(kClause, request + ": OpenSubdiv's level " + std::to_string(l - 1) +
                                         " is not what the triangle tree assumes");
        s[static_cast<std::size_t>(k)] = child.child_of_parent_edge[static_cast<std::size_t>(edge)];
        vc[static_cast<std::size_t>(k)] = child.child_of_parent_vertex[static_cast<std::size_t>(t.v[static_cast<std::size_t>(k)])];
      }
      const std::array<std::array<int, 3>, 4> kids = {{{s[0], s[1], s[2]},
                                                       {vc[0], s[2], s[1]},
                                                       {vc[1], s[0], s[2]},
                                                       {vc[2], s[1], s[0]}}};
      for (const auto& kid : kids) {
        int found = -1;
        for (int cf : child.child_faces_of_parent_face[static_cast<std::size_t>(t.face)])
          for (int r = 0; r < 3; ++r) {
            bool same = true;
            for (int k = 0; k < 3; ++k)
              same = same && child.face_vertices[static_cast<std::size_t>(3 * cf + (k + r) % 3)] == kid[static_cast<std::size_t>(k)];
            if (same) found = cf;
          }
        if (found < 0)
          return not_judged(kClause, request + ": OpenSubdiv's children at level " + std::to_string(l) +
                                         " are not what the triangle tree assumes");
        next.push_back({found, kid});
      }
    }
    tree = std::move(next);
  }
  if (got.face_lines.size() != tree.size())
    return finding(kClause, request + ": " + std::to_string(got.face_lines.size()) + " face lines; the triangle tree "
                                "has " + std::to_string(tree.size()) + " triangles at level " + std::to_string(level));
  static const char* kChild[] = {"T0 (the centre)", "T1 (nearest vertex 0)", "T2 (nearest vertex 1)",
                                 "T3 (nearest vertex 2)"};
  // By position (the vertices already matched one to one): coinciding
  // vertices make any pairing by index arbitrary. One tolerance for the
  // level (it was computed per face line: faces x vertices).
  const double tol = tolerance_of(osd.levels.back().positions);
  for (std::size_t i = 0; i < tree.size(); ++i) {
    const auto& line = got.face_lines[i];
    bool same = line.size() == 3;
    for (std::size_t k = 0; same && k < 3; ++k)
      same = near(got.vertices[static_cast<std::size_t>(line[k])],
                  osd.levels.back().positions[static_cast<std::size_t>(tree[i].v[k])], tol);
    if (!same) {
      std::string have, want;
      for (int x : line) have += " " + point_text(got.vertices[static_cast<std::size_t>(x)]);
      for (int x : tree[i].v) want += " " + point_text(osd.levels.back().positions[static_cast<std::size_t>(x)]);
      return finding(kClause, request + ": face line " + std::to_string(i) + " should be child " + kChild[i % 4] +
                                  " of its parent, in the order [vj' s(j+2) s(j+1)] / [s0 s1 s2]:" + want +
                                  "; the answer has" + have);
    }
  }
  return std::nullopt;
}

namespace {

constexpr const char* kEditClause = "EDIT-HIERARCHY-1";

// The four kinds of edit check_edits draws, one each per case.
enum DrawnEditKind { kHole, kSet, kAddZero, kAdd };

// An edit drawn for check_one_edit: the edit, its level, and how the
// ?subdivide-edit request spells it.
struct DrawnEdit {
  HierarchicalEdit edit;
  int level = 0;
  std::string text;
};

// The edit of `kind` from the drawn value (splitmix64, so every bit
// counts): a level up to `level`, a face path from a base polygon of
// `mesh`, a corner, and for set and add a value.
DrawnEdit draw_edit(const MeshArrays& mesh, int level, std::uint32_t draw, int kind) {
  std::uint64_t r = draw + 0x9E3779B97F4A7C15ull;
  r = (r ^ (r >> 30)) * 0xBF58476D1CE4E5B9ull;
  r = (r ^ (r >> 27)) * 0x94D049BB133111EBull;
  r ^= r >> 31;
  auto take = [&r](std::uint64_t n) {
    const std::uint64_t v = r % n;
    r /= n;
    return static_cast<int>(v);
  };
  DrawnEdit d;
  HierarchicalEdit& e = d.edit;
  d.level = take(static_cast<std::uint64_t>(level) + 1);
  e.face.base_face = take(static_cast<std::uint64_t>(mesh.face_count()));
  const int base_size = mesh.face_sizes[static_cast<std::size_t>(e.face.base_face)];
  for (int l = 0; l < d.level; ++l) e.face.children.push_back(take(l == 0 ? static_cast<std::uint64_t>(base_size) : 4));
  e.index = take(d.level == 0 ? static_cast<std::uint64_t>(base_size) : 4);
  e.kind = kind == kHole ? EditKind::FaceHole : EditKind::VertexValue;
  e.op = kind == kSet ? EditOp::Set : EditOp::Add;
  if (kind == kSet) e.value = {take(41) * 0.25 - 5, take(41) * 0.25 - 5, take(41) * 0.25 + 3};
  if (kind == kAdd) e.value = {0.5, -0.25, 1 + take(8) * 0.125};
  std::string path = "(" + std::to_string(mesh.polygon_ids[static_cast<std::size_t>(e.face.base_face)]);
  for (int c : e.face.children) path += " " + std::to_string(c);
  if (kind == kHole) {
    d.text = "hole " + path + ")";
  } else {
    d.text = std::string(kind == kSet ? "set " : "add ") + path + " " + std::to_string(e.index) + ") " +
             format_f64(e.value[0]) + " " + format_f64(e.value[1]) + " " + format_f64(e.value[2]);
  }
  return d;
}

// Asks ?subdivide-edit AT EDIT and reads the answer into *got: a finding
// when the call fails, the document is unreadable, of another level, or its
// face lines disagree with its face count.
std::optional<Finding> ask_edit(Implementation& sut, int at, const std::string& edit, SubdivisionAnswer* got,
                                std::string* request) {
  *request = "?subdivide-edit " + std::to_string(at) + " " + edit;
  const Document d = sut.request(*request);
  if (auto f = check_answer(kEditClause, *request, d, "vgc-subdivision")) return f;
  if (auto problem = read_subdivision(d.text, got)) return finding(kEditClause, *request + ": " + *problem);
  if (got->level != at) return finding(kEditClause, *request + ": the document says level " + std::to_string(got->level));
  if (static_cast<long>(got->face_lines.size()) != got->faces)
    return finding(kEditClause, *request + ": " + std::to_string(got->face_lines.size()) + " face lines but faces " +
                                    std::to_string(got->faces));
  return std::nullopt;
}

// Each face line must be a face of the level (`positions`, `sizes`,
// `corners`) whose flag in `allowed` is set, compared by the positions of
// its corners (same cycle, any starting corner, within the tolerance:
// coinciding vertices make a pairing by index arbitrary), each face used
// once.
std::optional<Finding> faces_among(const SubdivisionAnswer& got, const std::vector<std::array<double, 3>>& positions,
                                   const std::vector<int>& sizes, const std::vector<int>& corners,
                                   const std::vector<char>& allowed, const std::string& request,
                                   const std::string& source) {
  const double tol = tolerance_of(positions);
  std::vector<std::size_t> offset(sizes.size() + 1, 0);
  for (std::size_t f = 0; f < sizes.size(); ++f) offset[f + 1] = offset[f] + static_cast<std::size_t>(sizes[f]);
  auto same_cycle = [&](const std::vector<int>& line, std::size_t f) {
    const std::size_t n = line.size();
    if (n != static_cast<std::size_t>(sizes[f])) return false;
    for (std::size_t r = 0; r < n; ++r) {
      bool same = true;
      for (std::size_t k = 0; same && k < n; ++k)
        same = near(got.vertices[static_cast<std::size_t>(line[k])],
                    positions[static_cast<std::size_t>(corners[offset[f] + (k + r) % n])], tol);
      if (same) return true;
    }
    return false;
  };
  std::vector<char> used(sizes.size(), 0);
  for (std::size_t i = 0; i < got.face_lines.size(); ++i) {
    std::size_t hit = used.size();
    bool removed = false;
    for (std::size_t f = 0; f < used.size() && hit == used.size(); ++f) {
      if (used[f] || !same_cycle(got.face_lines[i], f)) continue;
      if (allowed[f]) hit = f;
      else removed = true;
    }
    if (hit == used.size())
      return finding(kEditClause, request + ": face line " + std::to_string(i) + " is " +
                                      (removed ? "a face the hole removes (it or an ancestor is the hole) in " + source
                                               : "no face of " + source + " (or one given twice)"));
    used[hit] = 1;
  }
  return std::nullopt;
}

// An edit changes its own level and the finer ones: the level just above
// it is OpenSubdiv's plain refinement.
std::optional<Finding> check_level_above_edit(const OsdResult& osd, Implementation& sut, const DrawnEdit& d) {
  SubdivisionAnswer got;
  std::string request;
  if (auto f = ask_edit(sut, d.level - 1, d.text, &got, &request)) return f;
  const OsdLevel& plain = osd.levels[static_cast<std::size_t>(d.level - 1)];
  std::vector<int> g2w;
  if (auto problem = compare_with_level(got, plain.positions, static_cast<long>(plain.face_sizes.size()),
                                        "OpenSubdiv (the edit is at level " + std::to_string(d.level) +
                                            ", so this level is untouched)",
                                        &g2w))
    return finding(kEditClause, request + ": " + *problem);
  return std::nullopt;
}

// Holes at level 0: OpenSubdiv's own holes (TopologyDescriptor holeIndices).
std::optional<Finding> check_base_hole(const MeshArrays& mesh, int level, const DrawnEdit& d,
                                       const SubdivisionAnswer& got, const std::string& request) {
  OsdInput in = osd_input_from_mesh(mesh, OsdScheme::CatmullClark, level);
  in.hole_faces.push_back(d.edit.face.base_face);
  const OsdResult holed = osd_refine_uniform(in);
  if (!holed.ok || holed.levels.size() != static_cast<std::size_t>(level) + 1) return std::nullopt;
  const OsdLevel& want = holed.levels.back();
  std::vector<char> allowed(want.face_sizes.size(), 1);
  long kept = 0;
  for (std::size_t f = 0; f < allowed.size(); ++f) {
    allowed[f] = f < want.face_hole.size() && want.face_hole[f] ? 0 : 1;
    kept += allowed[f];
  }
  std::vector<int> g2w;
  if (auto problem = compare_with_level(got, want.positions, kept, "OpenSubdiv with the hole", &g2w))
    return finding(kEditClause, request + ": " + *problem);
  return faces_among(got, want.positions, want.face_sizes, want.face_vertices, allowed, request,
                     "OpenSubdiv's refinement with the hole");
}

// A hole deeper down removes exactly its descendants at this level (4 per
// level below it: they are quads) and moves nothing; add 0 changes nothing.
std::optional<Finding> check_nothing_moved(const OsdLevel& plain, int level, int kind, const DrawnEdit& d,
                                           const SubdivisionAnswer& got, const std::string& request) {
  long removed = 0;
  if (kind == kHole) {
    removed = 1;
    for (int l = d.level; l < level; ++l) removed *= 4;
  }
  std::vector<int> g2w;
  if (auto problem = compare_with_level(got, plain.positions, static_cast<long>(plain.face_sizes.size()) - removed,
                                        kind == kHole ? "OpenSubdiv (a hole at level " + std::to_string(d.level) +
                                                            " moves nothing and removes " + std::to_string(removed) +
                                                            " faces here)"
                                                      : std::string("OpenSubdiv (add 0 changes nothing)"),
                                        &g2w))
    return finding(kEditClause, request + ": " + *problem);
  return faces_among(got, plain.positions, plain.face_sizes, plain.face_vertices,
                     std::vector<char>(plain.face_sizes.size(), 1), request, "OpenSubdiv's refinement");
}

// At the edit's own level only the edited vertex moved (OpenSubdiv's plain
// vertices for all the others), and "set" puts it at the value.
std::optional<Finding> check_one_vertex_moved(const OsdLevel& plain, int kind, const DrawnEdit& d,
                                              const SubdivisionAnswer& got, const std::string& request) {
  std::vector<int> w2g;
  std::vector<std::size_t> unmatched;
  match_vertices(plain.positions, got.vertices, tolerance_of(plain.positions), &w2g, &unmatched);
  if (got.vertices.size() != plain.positions.size() || unmatched.size() != 1)
    return finding(kEditClause, request + ": " + std::to_string(unmatched.size()) + " of " +
                                    std::to_string(got.vertices.size()) + " vertices are not OpenSubdiv's (of " +
                                    std::to_string(plain.positions.size()) +
                                    "); an edit at the answer's own level moves exactly one");
  if (kind == kSet && got.vertices[unmatched[0]] != d.edit.value)
    return finding(kEditClause, request + ": the moved vertex is at " + point_text(got.vertices[unmatched[0]]) +
                                    "; \"set\" puts it at " + point_text(d.edit.value));
  return std::nullopt;
}

// The rest has no external oracle (OpenSubdiv 3 dropped hierarchical
// edits): the reference's reading (hierarchical_edit.h).
std::optional<Finding> check_reference_edit(const MeshArrays& mesh, int level, const DrawnEdit& d,
                                            const SubdivisionAnswer& got, const std::string& request) {
  std::vector<SubdivisionLevel> ref;
  if (subdivide_with_edits(mesh, level, {d.edit}, &ref) != EditStatus::Ok) return std::nullopt;
  const SubdivisionLevel& want = ref.back();
  long kept = 0;
  for (unsigned char h : want.face_hole) kept += h ? 0 : 1;
  std::vector<int> g2w;
  if (auto problem = compare_with_level(got, want.positions, kept, "the reference's hierarchical edit", &g2w))
    return finding(kEditClause, request + ": " + *problem);
  std::vector<char> kept_faces(want.face_hole.size());
  for (std::size_t f = 0; f < kept_faces.size(); ++f) kept_faces[f] = want.face_hole[f] ? 0 : 1;
  return faces_among(got, want.positions, want.face_sizes, want.face_vertices, kept_faces, request,
                     "the reference's hierarchical edit");
}

// One edit of `kind` (0 hole, 1 set, 2 add 0, 3 add) chosen from `draw`;
// see check_edits.
// `mesh` is the model's polygons without unused vertices, `osd` its
// OpenSubdiv refinement to `level` (oracle_refinement).
std::optional<Finding> check_one_edit(const MeshArrays& mesh, const OsdResult& osd, Implementation& sut, int level,
                                      std::uint32_t draw, int kind) {
  const DrawnEdit d = draw_edit(mesh, level, draw, kind);
  if (d.level >= 2)
    if (auto f = check_level_above_edit(osd, sut, d)) return f;
  SubdivisionAnswer got;
  std::string request;
  if (auto f = ask_edit(sut, level, d.text, &got, &request)) return f;
  const OsdLevel& plain = osd.levels.back();
  if (kind == kHole && d.level == 0) return check_base_hole(mesh, level, d, got, request);
  if (kind == kHole || kind == kAddZero) {
    if (auto f = check_nothing_moved(plain, level, kind, d, got, request)) return f;
    if (kind == kAddZero) return std::nullopt;
  }
  // Only where the tolerance is far below the move: coordinates up to 1e6.
  if (d.level == level && kind != kHole && tolerance_of(plain.positions) <= 1e-3)
    if (auto f = check_one_vertex_moved(plain, kind, d, got, request)) return f;
  return check_reference_edit(mesh, level, d, got, request);
}

}  // namespace

std::optional<Finding> check_edits(const Node& model, Implementation& sut, int level, std::uint32_t draw) {
  // Every kind in each case, each with its own path from the same draw, so
  // that a fault in one kind does not hide behind the others' cases.
  const MeshArrays mesh = remove_unused_vertices(extract_mesh(model));
  if (mesh.face_count() == 0) return std::nullopt;  // no face for an edit to name
  std::string why;
  const std::optional<OsdResult> osd = oracle_refinement(mesh, OsdScheme::CatmullClark, level, &why);
  if (!osd) return not_judged("EDIT-HIERARCHY-1", "?subdivide-edit " + std::to_string(level) + ": " + why);
  for (int kind = 0; kind < 4; ++kind)
    if (auto f = check_one_edit(mesh, *osd, sut, level, draw + 0x632BE5ABu * static_cast<std::uint32_t>(kind), kind))
      return f;
  return std::nullopt;
}

void register_capability_checks() {
  auto add = [](const char* name, decltype(CapabilityCheck::check) check) {
    CapabilityCheck c;
    c.capability = name;
    c.check = std::move(check);
    register_capability_check(std::move(c));
  };
  add("manifold", [](const Node& m, Implementation& s, int) { return check_classify(m, s); });
  add("subdivision", [](const Node& m, Implementation& s, int level) { return check_subdivision(m, s, level); });
  add("normals", [](const Node& m, Implementation& s, int) { return check_normals(m, s); });
  add("loop", [](const Node& m, Implementation& s, int level) { return check_loop(m, s, level); });
  CapabilityCheck edits;
  edits.capability = "edits";
  edits.check_drawn = [](const Node& m, Implementation& s, int level, std::uint32_t draw) {
    return check_edits(m, s, level, draw);
  };
  register_capability_check(std::move(edits));
}

}  // namespace vgc
