// face_normals.cpp — see face_normals.h.
#include "face_normals.h"

#include <cmath>
#include <cstddef>

namespace vgc {

Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 normalized(const Vec3& a) {
  const double l = length(a);
  return l > 1e-300 ? scale(a, 1.0 / l) : Vec3{0, 0, 0};
}

Vec3 triangle_normal_anticlockwise(const Vec3& a, const Vec3& b, const Vec3& c) {
  return cross(sub(c, b), sub(a, b));
}

Vec3 polygon_area_vector(const std::vector<Vec3>& p) {
  Vec3 n{0, 0, 0};
  const std::size_t count = p.size();
  if (count < 3) return n;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3& u = p[i];
    const Vec3& w = p[(i + 1) % count];
    n[0] += (u[1] - w[1]) * (u[2] + w[2]);
    n[1] += (u[2] - w[2]) * (u[0] + w[0]);
    n[2] += (u[0] - w[0]) * (u[1] + w[1]);
  }
  // Newell's sum is twice the anti-clockwise vector area; the front side is
  // clockwise, hence the sign.
  return scale(n, -0.5);
}

Vec3 face_area_vector(const MeshArrays& mesh, int f) {
  const auto fi = static_cast<std::size_t>(f);
  std::vector<Vec3> corners;
  corners.reserve(static_cast<std::size_t>(mesh.face_sizes[fi]));
  for (int i = 0; i < mesh.face_sizes[fi]; ++i)
    corners.push_back(mesh.positions[static_cast<std::size_t>(mesh.face_vertices[static_cast<std::size_t>(mesh.face_offsets[fi] + i)])]);
  return polygon_area_vector(corners);
}

Vec3 face_normal(const MeshArrays& mesh, int f) { return normalized(face_area_vector(mesh, f)); }

std::vector<Vec3> face_normals(const MeshArrays& mesh) {
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(mesh.face_count()));
  for (int f = 0; f < mesh.face_count(); ++f) out.push_back(face_normal(mesh, f));
  return out;
}

}  // namespace vgc
