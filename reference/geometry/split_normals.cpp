// split_normals.cpp — see split_normals.h.
#include "split_normals.h"

#include <cmath>
#include <cstddef>

#include "crease.h"

namespace vgc {

bool is_edge_sharp(const MeshArrays& mesh, const MeshTopology& t, int e) {
  const MeshEdge& edge = t.edges[static_cast<std::size_t>(e)];
  if (edge.use_count != 2) return true;     // boundary or non-manifold
  if (edge.forward_count != 1) return true;  // opposed winding
  if (mesh.corner_edge_creases.empty()) return false;
  for (int k = t.edge_corner_offsets[static_cast<std::size_t>(e)]; k < t.edge_corner_offsets[static_cast<std::size_t>(e) + 1]; ++k) {
    const auto c = static_cast<std::size_t>(t.edge_corners[static_cast<std::size_t>(k)]);
    if (c < mesh.corner_edge_creases.size() && mesh.corner_edge_creases[c] == kCreaseMax) return true;
  }
  return false;
}

SplitNormals compute_split_normals(const MeshArrays& mesh) { return compute_split_normals(mesh, classify_mesh(mesh)); }

SplitNormals compute_split_normals(const MeshArrays& mesh, const MeshTopology& t) {
  SplitNormals s;
  s.status = t.status;
  s.bad_face = t.bad_face;
  if (t.status != MeshStatus::Ok) return s;
  const auto& fv = mesh.face_vertices;

  s.edge_sharp.resize(t.edges.size());
  for (std::size_t e = 0; e < t.edges.size(); ++e) s.edge_sharp[e] = is_edge_sharp(mesh, t, static_cast<int>(e));
  s.corner_face = t.corner_face;
  s.corner_fan = group_corner_fans(mesh, t, s.edge_sharp, &s.fan_count);

  const std::size_t corners = fv.size();
  const auto fans = static_cast<std::size_t>(s.fan_count);
  s.fan_vertex.assign(fans, -1);
  s.fan_corner_offsets.assign(fans + 1, 0);
  for (std::size_t c = 0; c < corners; ++c) ++s.fan_corner_offsets[static_cast<std::size_t>(s.corner_fan[c]) + 1];
  for (std::size_t f = 0; f < fans; ++f) s.fan_corner_offsets[f + 1] += s.fan_corner_offsets[f];
  s.fan_corners.resize(corners);
  {
    std::vector<int> fill(s.fan_corner_offsets.begin(), s.fan_corner_offsets.end() - 1);
    for (std::size_t c = 0; c < corners; ++c) {
      const auto fan = static_cast<std::size_t>(s.corner_fan[c]);
      s.fan_corners[static_cast<std::size_t>(fill[fan]++)] = static_cast<int>(c);
      s.fan_vertex[fan] = fv[c];
    }
  }

  s.face_normals = face_normals(mesh);
  s.fan_normals.assign(fans, Vec3{0, 0, 0});
  std::vector<bool> has_corner(fans, false);
  std::vector<Vec3> first_face_normal(fans, Vec3{0, 0, 0});
  for (std::size_t c = 0; c < corners; ++c) {
    if (t.corner_face[c] < 0) continue;
    const auto fan = static_cast<std::size_t>(s.corner_fan[c]);
    const Vec3& n = s.face_normals[static_cast<std::size_t>(t.corner_face[c])];
    if (!has_corner[fan]) {
      has_corner[fan] = true;
      first_face_normal[fan] = n;
    }
    const Vec3& p = mesh.positions[static_cast<std::size_t>(fv[c])];
    const Vec3 u = sub(mesh.positions[static_cast<std::size_t>(fv[static_cast<std::size_t>(next_corner(mesh, t, static_cast<int>(c)))])], p);
    const Vec3 w = sub(mesh.positions[static_cast<std::size_t>(fv[static_cast<std::size_t>(prev_corner(mesh, t, static_cast<int>(c)))])], p);
    const double angle = std::atan2(length(cross(u, w)), dot(u, w));
    s.fan_normals[fan] = add(s.fan_normals[fan], scale(n, angle));
  }
  for (std::size_t fan = 0; fan < fans; ++fan) {
    Vec3 n = normalized(s.fan_normals[fan]);
    if (length(n) == 0) n = first_face_normal[fan];
    s.fan_normals[fan] = n;
  }
  s.corner_normals.resize(corners);
  for (std::size_t c = 0; c < corners; ++c) s.corner_normals[c] = s.fan_normals[static_cast<std::size_t>(s.corner_fan[c])];
  return s;
}

FanNormalSpace fan_normal_space(const MeshArrays& mesh, const SplitNormals& s, int fan) {
  FanNormalSpace space;
  const auto fi = static_cast<std::size_t>(fan);
  space.normal = s.fan_normals[fi];
  if (length(space.normal) == 0) return space;
  auto neighbours = [&](int c, int* next, int* prev) {
    const auto f = static_cast<std::size_t>(s.corner_face[static_cast<std::size_t>(c)]);
    const int o = mesh.face_offsets[f], n = mesh.face_sizes[f];
    *next = o + (c - o + 1) % n;
    *prev = o + (c - o + n - 1) % n;
  };
  for (int k = s.fan_corner_offsets[fi]; k < s.fan_corner_offsets[fi + 1] && !space.valid; ++k) {
    const int c = s.fan_corners[static_cast<std::size_t>(k)];
    if (s.corner_face[static_cast<std::size_t>(c)] < 0) continue;
    int next = 0, prev = 0;
    neighbours(c, &next, &prev);
    const Vec3& p = mesh.positions[static_cast<std::size_t>(mesh.face_vertices[static_cast<std::size_t>(c)])];
    for (int other : {next, prev}) {
      const Vec3 edge = sub(mesh.positions[static_cast<std::size_t>(mesh.face_vertices[static_cast<std::size_t>(other)])], p);
      const Vec3 proj = sub(edge, scale(space.normal, dot(edge, space.normal)));
      if (length(proj) > 1e-9 * length(edge) && length(proj) > 0) {
        space.reference = normalized(proj);
        space.bitangent = cross(space.normal, space.reference);
        space.valid = true;
        break;
      }
    }
  }
  return space;
}

CustomNormal encode_custom_normal(const FanNormalSpace& sp, const Vec3& n) {
  const double z = dot(n, sp.normal), x = dot(n, sp.reference), y = dot(n, sp.bitangent);
  CustomNormal c;
  c.theta = std::atan2(std::sqrt(x * x + y * y), z);
  c.phi = std::atan2(y, x);
  return c;
}

Vec3 decode_custom_normal(const FanNormalSpace& sp, const CustomNormal& c) {
  const double st = std::sin(c.theta);
  return add(scale(sp.normal, std::cos(c.theta)),
             add(scale(sp.reference, st * std::cos(c.phi)), scale(sp.bitangent, st * std::sin(c.phi))));
}

std::vector<Vec3> corner_normals_with_custom(const MeshArrays& mesh, const SplitNormals& s,
                                             const std::vector<std::optional<CustomNormal>>& custom) {
  std::vector<Vec3> fan_n = s.fan_normals;
  for (std::size_t fan = 0; fan < custom.size() && fan < fan_n.size(); ++fan) {
    if (!custom[fan]) continue;
    const FanNormalSpace sp = fan_normal_space(mesh, s, static_cast<int>(fan));
    if (sp.valid) fan_n[fan] = decode_custom_normal(sp, *custom[fan]);
  }
  std::vector<Vec3> out(s.corner_fan.size());
  for (std::size_t c = 0; c < out.size(); ++c) out[c] = fan_n[static_cast<std::size_t>(s.corner_fan[c])];
  return out;
}

}  // namespace vgc
