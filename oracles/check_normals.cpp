// check_normals.cpp — ?normals: split normals by their properties, then against the reference (capability_checks.h).
//
// Spec: clause NORMALS-SPLIT-1; the document of docs/adapters.md "Optional
// capabilities".
#include "capability_checks.h"

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

#include "capability_answer.h"
#include "crease_sharpness.h"
#include "face_normals.h"
#include "mesh_arrays.h"
#include "number_text.h"
#include "split_normals.h"

namespace vgc {

using namespace capability_answer;

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

}  // namespace vgc
