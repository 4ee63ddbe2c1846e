// manifold_shapes.h — meshes for the manifold and normal tests: closed
// shapes, grids, a torus, a Moebius strip, random soups, and the edits that
// turn them non-manifold, non-orientable or invalid. All randomness comes
// from a caller's std::mt19937 (explicit seeds).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "mesh_arrays.h"

namespace vgc::test {

using P3 = std::array<double, 3>;
using Faces = std::vector<std::vector<int>>;

inline MeshArrays make_mesh(const std::vector<P3>& positions, const Faces& faces) {
  MeshArrays m;
  m.positions = positions;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    m.vertex_ids.push_back(static_cast<std::uint32_t>(i));
    m.vertex_creases.push_back(0);
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    m.polygon_ids.push_back(static_cast<std::uint32_t>(f));
    m.face_sizes.push_back(static_cast<int>(faces[f].size()));
    for (int v : faces[f]) {
      m.face_vertices.push_back(v);
      m.corner_edge_creases.push_back(0);
    }
  }
  update_face_offsets(m);
  return m;
}

inline Faces faces_of(const MeshArrays& m) {
  Faces out;
  for (int f = 0; f < m.face_count(); ++f)
    out.emplace_back(m.face_vertices.begin() + m.face_offsets[static_cast<std::size_t>(f)],
                     m.face_vertices.begin() + m.face_offsets[static_cast<std::size_t>(f)] + m.face_sizes[static_cast<std::size_t>(f)]);
  return out;
}

// The spec's cube (000 section 2.6.4), as its tables give it.
inline MeshArrays spec_cube() {
  return make_mesh({{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, {-1, -1, -1}},
                   {{0, 1, 2, 3}, {4, 5, 6, 7}, {3, 2, 5, 4}, {2, 1, 6, 5}, {1, 0, 7, 6}, {0, 3, 4, 7}});
}

// Orders each face of a convex solid around the origin clockwise seen from
// outside (right-handed cross product pointing inwards), independently of
// the code under test.
inline Faces clockwise_from_outside(const std::vector<P3>& p, Faces faces) {
  for (auto& f : faces) {
    const P3 &a = p[static_cast<std::size_t>(f[0])], &b = p[static_cast<std::size_t>(f[1])], &c = p[static_cast<std::size_t>(f[2])];
    const P3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const P3 n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double out = n[0] * (a[0] + b[0] + c[0]) + n[1] * (a[1] + b[1] + c[1]) + n[2] * (a[2] + b[2] + c[2]);
    if (out > 0) std::reverse(f.begin(), f.end());
  }
  return faces;
}

inline MeshArrays octahedron() {
  std::vector<P3> p{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  Faces f;
  for (int x : {0, 1})
    for (int y : {2, 3})
      for (int z : {4, 5}) f.push_back({x, y, z});
  return make_mesh(p, clockwise_from_outside(p, f));
}

inline MeshArrays tetrahedron() {
  std::vector<P3> p{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  return make_mesh(p, clockwise_from_outside(p, {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}));
}

// w x h quads (or 2 triangles each) in the z = height plane, clockwise seen
// from +z.
inline MeshArrays grid(int w, int h, bool triangles, std::mt19937* rng = nullptr) {
  std::vector<P3> p;
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (int j = 0; j <= h; ++j)
    for (int i = 0; i <= w; ++i) p.push_back({double(i), double(j), rng ? jitter(*rng) : 0.0});
  auto id = [w](int i, int j) { return j * (w + 1) + i; };
  Faces f;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      if (triangles) {
        f.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
        f.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
      } else {
        f.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
      }
    }
  return make_mesh(p, f);
}

// A w x h quad torus (w, h >= 3): closed, orientable, Euler characteristic 0.
inline MeshArrays torus(int w, int h) {
  std::vector<P3> p;
  const double pi = std::acos(-1.0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double u = 2 * pi * i / w, v = 2 * pi * j / h;
      p.push_back({(3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)});
    }
  auto id = [w, h](int i, int j) { return (j % h) * w + (i % w); };
  Faces f;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) f.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
  return make_mesh(p, f);
}

// A Moebius strip of n >= 3 quads: top vertices 0..n-1, bottom n..2n-1;
// the last quad joins column n-1 to column 0 with a half twist.
// Non-orientable, one boundary loop of 2n vertices, Euler characteristic 0.
inline MeshArrays moebius(int n) {
  std::vector<P3> p;
  const double pi = std::acos(-1.0);
  for (int s : {1, -1})
    for (int i = 0; i < n; ++i) {
      const double u = 2 * pi * i / n, t = 0.5 * s;
      p.push_back({(2 + t * std::cos(u / 2)) * std::cos(u), (2 + t * std::cos(u / 2)) * std::sin(u), t * std::sin(u / 2)});
    }
  Faces f;
  for (int i = 0; i + 1 < n; ++i) f.push_back({i, i + 1, n + i + 1, n + i});
  f.push_back({n - 1, n, 0, 2 * n - 1});
  return make_mesh(p, f);
}

// A w x h quad Klein bottle (w, h >= 3): the torus grid with column w glued
// to column 0 upside down. Closed, non-orientable, Euler characteristic 0.
inline MeshArrays klein_bottle(int w, int h) {
  std::vector<P3> p;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) p.push_back({double(i), double(j), double((i * 7 + j * 3) % 5) * 0.1});
  auto id = [w, h](int i, int j) {
    j %= h;
    if (i == w) return ((h - j) % h) * w;
    return j * w + i;
  };
  Faces f;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) f.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
  return make_mesh(p, f);
}

// Random polygons (3 or 4 distinct corners) over `vertices` vertices.
inline MeshArrays random_soup(std::mt19937& rng, int vertices, int faces) {
  std::vector<P3> p;
  std::uniform_real_distribution<double> coord(-1, 1);
  for (int i = 0; i < vertices; ++i) p.push_back({coord(rng), coord(rng), coord(rng)});
  std::vector<int> ids(static_cast<std::size_t>(vertices));
  std::iota(ids.begin(), ids.end(), 0);
  Faces f;
  for (int k = 0; k < faces; ++k) {
    std::shuffle(ids.begin(), ids.end(), rng);
    const int n = std::min(vertices, 3 + static_cast<int>(rng() % 2));
    f.emplace_back(ids.begin(), ids.begin() + n);
  }
  return make_mesh(p, f);
}

// ---- edits ----

inline MeshArrays renumber_vertices(const MeshArrays& m, std::mt19937& rng) {
  std::vector<int> perm(static_cast<std::size_t>(m.vertex_count()));
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<P3> p(m.positions.size());
  for (std::size_t v = 0; v < p.size(); ++v) p[static_cast<std::size_t>(perm[v])] = m.positions[v];
  Faces f = faces_of(m);
  for (auto& face : f)
    for (int& v : face)
      if (v >= 0 && v < m.vertex_count()) v = perm[static_cast<std::size_t>(v)];
  return make_mesh(p, f);
}

inline MeshArrays rotate_and_shuffle_faces(const MeshArrays& m, std::mt19937& rng) {
  Faces f = faces_of(m);
  for (auto& face : f)
    if (!face.empty()) std::rotate(face.begin(), face.begin() + static_cast<long>(rng() % face.size()), face.end());
  std::shuffle(f.begin(), f.end(), rng);
  return make_mesh(m.positions, f);
}

inline MeshArrays flip_face(const MeshArrays& m, int face) {
  Faces f = faces_of(m);
  std::reverse(f[static_cast<std::size_t>(face)].begin(), f[static_cast<std::size_t>(face)].end());
  return make_mesh(m.positions, f);
}

inline MeshArrays add_isolated_vertex(const MeshArrays& m) {
  std::vector<P3> p = m.positions;
  p.push_back({5, 5, 5});
  return make_mesh(p, faces_of(m));
}

inline MeshArrays disjoint_union(const MeshArrays& a, const MeshArrays& b) {
  std::vector<P3> p = a.positions;
  for (const auto& q : b.positions) p.push_back({q[0] + 10, q[1], q[2]});
  Faces f = faces_of(a);
  for (auto face : faces_of(b)) {
    for (int& v : face) v += a.vertex_count();
    f.push_back(face);
  }
  return make_mesh(p, f);
}

// Union of a and b with b's vertex vb merged into a's vertex va: the two
// surfaces touch at one vertex only (a "bow-tie" vertex).
inline MeshArrays glue_at_vertex(const MeshArrays& a, const MeshArrays& b, int va, int vb) {
  std::vector<P3> p = a.positions;
  std::vector<int> map(static_cast<std::size_t>(b.vertex_count()));
  for (int v = 0; v < b.vertex_count(); ++v) {
    if (v == vb) {
      map[static_cast<std::size_t>(v)] = va;
    } else {
      map[static_cast<std::size_t>(v)] = static_cast<int>(p.size());
      const auto& q = b.positions[static_cast<std::size_t>(v)];
      p.push_back({q[0] + 10, q[1], q[2]});
    }
  }
  Faces f = faces_of(a);
  for (auto face : faces_of(b)) {
    for (int& v : face) v = map[static_cast<std::size_t>(v)];
    f.push_back(face);
  }
  return make_mesh(p, f);
}

// Adds a triangle on the edge from corner k of face `face` to the next
// corner, with a new vertex: that edge gets one more use (3 on an interior
// edge: non-manifold).
inline MeshArrays add_fin(const MeshArrays& m, int face, int k) {
  Faces f = faces_of(m);
  const auto& g = f[static_cast<std::size_t>(face)];
  const int a = g[static_cast<std::size_t>(k) % g.size()], b = g[(static_cast<std::size_t>(k) + 1) % g.size()];
  std::vector<P3> p = m.positions;
  p.push_back({7, 7, 7});
  f.push_back({a, b, static_cast<int>(p.size()) - 1});
  return make_mesh(p, f);
}

}  // namespace vgc::test
