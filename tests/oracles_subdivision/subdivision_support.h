// subdivision_support.h — meshes and the by-parent comparison shared by the
// subdivision oracle tests.
//
// Meshes: grids (quads, or quads split into triangles) with manifold holes
// cut in them, closed shapes (cube, octahedron, torus grids), with random
// vertex renumbering and random vertex and edge creases (smooth, fractional,
// infinite), all from explicit seeds.
//
// Comparison: reference levels (reference/geometry/catmull_clark.h, loop_subdivision.h)
// against OpenSubdiv levels (oracles/osd_subdivision.h), vertex by vertex,
// matched by parent component: the child of a parent vertex, of a parent
// edge (matched through the faces using it), of a parent face; child faces
// matched to OpenSubdiv's GetFaceChildFaces up to rotation
// (oracles/subdivision_comparison.h). Returns the first disagreement as
// text, empty if none.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "catmull_clark.h"
#include "command_text.h"
#include "crease_sharpness.h"
#include "mesh_arrays.h"
#include "node.h"
#include "osd_subdivision.h"
#include "subdivision_comparison.h"

namespace vgc::test {

inline MeshArrays make_mesh(std::vector<std::array<double, 3>> positions, std::vector<std::vector<int>> faces) {
  MeshArrays m;
  m.positions = std::move(positions);
  m.vertex_creases.assign(m.positions.size(), 0);
  for (std::size_t i = 0; i < m.positions.size(); ++i) m.vertex_ids.push_back(static_cast<std::uint32_t>(i));
  for (std::size_t f = 0; f < faces.size(); ++f) {
    m.polygon_ids.push_back(static_cast<std::uint32_t>(f));
    m.face_sizes.push_back(static_cast<int>(faces[f].size()));
    for (int v : faces[f]) m.face_vertices.push_back(v);
  }
  m.corner_edge_creases.assign(m.face_vertices.size(), 0);
  update_face_offsets(m);
  return m;
}

inline std::vector<std::vector<int>> faces_of(const MeshArrays& m) {
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < m.face_count(); ++f)
    faces.emplace_back(m.face_vertices.begin() + m.face_offsets[f],
                       m.face_vertices.begin() + m.face_offsets[f] + m.face_sizes[f]);
  return faces;
}

// The spec's cube through the reference node (corpora/examples/cube.vgc).
inline MeshArrays cube_from_corpus() {
  std::ifstream in(VGC_SOURCE_DIR "/corpora/examples/cube.vgc", std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  std::vector<Command> commands;
  TextError error;
  Node node;
  if (parse_commands(ss.str(), &commands, &error))
    for (const auto& c : commands) node.apply(c);
  return extract_mesh(node);
}

// True if every vertex is used and has 0 or 2 boundary edges and no edge
// has more than 2 faces (a manifold surface with boundary, as far as
// boundary vertices go).
inline bool boundary_is_manifold(const std::vector<std::vector<int>>& faces, int nv) {
  std::map<std::pair<int, int>, int> count;
  std::vector<int> used(static_cast<std::size_t>(nv), 0);
  for (const auto& f : faces)
    for (std::size_t i = 0; i < f.size(); ++i) {
      int a = f[i], b = f[(i + 1) % f.size()];
      ++used[static_cast<std::size_t>(a)];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<int> boundary(static_cast<std::size_t>(nv), 0);
  for (const auto& [e, n] : count) {
    if (n > 2) return false;
    if (n == 1) ++boundary[static_cast<std::size_t>(e.first)], ++boundary[static_cast<std::size_t>(e.second)];
  }
  for (int v = 0; v < nv; ++v)
    if (used[static_cast<std::size_t>(v)] == 0 || (boundary[static_cast<std::size_t>(v)] != 0 && boundary[static_cast<std::size_t>(v)] != 2))
      return false;
  return true;
}

// Removes unused vertices and renumbers the rest by a random permutation.
inline MeshArrays compact_and_shuffle(const std::vector<std::array<double, 3>>& pos,
                                      std::vector<std::vector<int>> faces, std::mt19937& rng) {
  std::vector<int> used(pos.size(), 0);
  for (const auto& f : faces)
    for (int v : f) used[static_cast<std::size_t>(v)] = 1;
  std::vector<int> live;
  for (std::size_t v = 0; v < pos.size(); ++v)
    if (used[v]) live.push_back(static_cast<int>(v));
  std::vector<int> perm(live.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<int> remap(pos.size(), -1);
  std::vector<std::array<double, 3>> out(live.size());
  for (std::size_t i = 0; i < live.size(); ++i) {
    remap[static_cast<std::size_t>(live[i])] = perm[i];
    out[static_cast<std::size_t>(perm[i])] = pos[static_cast<std::size_t>(live[i])];
  }
  for (auto& f : faces)
    for (int& v : f) v = remap[static_cast<std::size_t>(v)];
  return make_mesh(out, faces);
}

// An nx x ny grid with a wavy, jittered height; each quad is kept, or (with
// probability tri_fraction) split into two triangles; then faces are cut
// out at random as holes as long as the surface stays manifold.
inline MeshArrays grid_with_holes(int nx, int ny, double tri_fraction, int holes, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<std::array<double, 3>> pos;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) pos.push_back({i + jitter(rng), j + jitter(rng), std::sin(i * 0.7) * std::cos(j * 0.5) + jitter(rng)});
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  std::bernoulli_distribution tri(tri_fraction);
  std::vector<std::vector<int>> faces;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (tri(rng)) {
        faces.push_back({a, b, c});
        faces.push_back({a, c, d});
      } else {
        faces.push_back({a, b, c, d});
      }
    }
  for (int h = 0, tries = 0; h < holes && tries < 50 * holes; ++tries) {
    std::uniform_int_distribution<std::size_t> pick(0, faces.size() - 1);
    auto trial = faces;
    trial.erase(trial.begin() + static_cast<std::ptrdiff_t>(pick(rng)));
    std::vector<int> used(pos.size(), 0);
    for (const auto& f : trial)
      for (int v : f) used[static_cast<std::size_t>(v)] = 1;
    // Judge manifoldness on the used vertices only (a cut may free a corner vertex).
    std::vector<int> remap(pos.size(), -1);
    int n = 0;
    for (std::size_t v = 0; v < pos.size(); ++v)
      if (used[v]) remap[v] = n++;
    auto renum = trial;
    for (auto& f : renum)
      for (int& v : f) v = remap[static_cast<std::size_t>(v)];
    if (!boundary_is_manifold(renum, n)) continue;
    faces = std::move(trial);
    ++h;
  }
  return compact_and_shuffle(pos, faces, rng);
}

// A torus of nu x nv quads (some split into triangles).
inline MeshArrays torus(int nu, int nv, double tri_fraction, std::mt19937& rng) {
  std::vector<std::array<double, 3>> pos;
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      pos.push_back({(3 + std::cos(v)) * std::cos(u) + jitter(rng), (3 + std::cos(v)) * std::sin(u) + jitter(rng),
                     std::sin(v) + jitter(rng)});
    }
  std::bernoulli_distribution tri(tri_fraction);
  std::vector<std::vector<int>> faces;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = j * nu + i, b = j * nu + (i + 1) % nu, c = ((j + 1) % nv) * nu + (i + 1) % nu, d = ((j + 1) % nv) * nu + i;
      if (tri(rng)) {
        faces.push_back({a, b, c});
        faces.push_back({a, c, d});
      } else {
        faces.push_back({a, b, c, d});
      }
    }
  return compact_and_shuffle(pos, faces, rng);
}

inline MeshArrays octahedron(std::mt19937& rng) {
  std::vector<std::array<double, 3>> p{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::vector<int>> f{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return compact_and_shuffle(p, f, rng);
}

inline MeshArrays cube_with_triangles(std::mt19937& rng) {
  MeshArrays c = cube_from_corpus();
  auto faces = faces_of(c);
  // Split the top quad into two triangles and the front quad into four around a new centre.
  std::vector<std::vector<int>> out;
  auto pos = c.positions;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const auto& q = faces[i];
    if (i == 0) {
      out.push_back({q[0], q[1], q[2]});
      out.push_back({q[0], q[2], q[3]});
    } else if (i == 2) {
      const int m = static_cast<int>(pos.size());
      pos.push_back({0, 0, 1.0});
      for (int k = 0; k < 4; ++k) out.push_back({q[static_cast<std::size_t>(k)], q[static_cast<std::size_t>((k + 1) % 4)], m});
    } else {
      out.push_back(q);
    }
  }
  return compact_and_shuffle(pos, out, rng);
}

// A random crease value: smooth, fractional below 1, semi-sharp 1..5, or maximal.
inline std::uint32_t random_crease(std::mt19937& rng) {
  std::uniform_int_distribution<int> kind(0, 5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  switch (kind(rng)) {
    case 0:
    case 1: return 0;
    case 2: return static_cast<std::uint32_t>(u(rng) * 0.1 * 4294967295.0);        // sharpness < 1
    case 3: return static_cast<std::uint32_t>((0.1 + u(rng) * 0.4) * 4294967295.0);  // 1 .. 5
    case 4: return static_cast<std::uint32_t>(0.1 * 4294967295.0 * (1 + (rng() % 3)));  // about 1, 2, 3
    default: return 0xFFFFFFFFu;
  }
}

// Random creases: vertex creases with probability p_vertex, edge creases per
// corner with probability p_edge (the two sides of an edge chosen independently).
inline void add_random_creases(MeshArrays& m, double p_vertex, double p_edge, std::mt19937& rng) {
  std::bernoulli_distribution bv(p_vertex), be(p_edge);
  for (auto& c : m.vertex_creases) c = bv(rng) ? random_crease(rng) : 0;
  for (auto& c : m.corner_edge_creases) c = be(rng) ? random_crease(rng) : 0;
}

// OpenSubdiv's input for `m`: edge creases combined by the reference's
// shared-edge rule and mapped to sharpness, vertex creases as corners; the
// boundary rule is left to OpenSubdiv.
inline OsdInput to_osd_input(const MeshArrays& m, OsdScheme scheme, int levels) {
  return osd_input_from_mesh(m, scheme, levels);
}

inline double mesh_scale(const MeshArrays& m) {
  double s = 1.0;
  for (const auto& p : m.positions)
    for (double x : p) s = std::max(s, std::abs(x));
  return s;
}

// Compares every vertex of every level, matched by parent component
// (oracles/subdivision_comparison.h). `tolerance` is absolute. Empty
// result: all agree.
inline std::string compare_by_parent(const std::vector<SubdivisionLevel>& ref, const OsdResult& osd, double tolerance,
                                     bool face_points) {
  return compare_subdivision_by_parent(ref, osd, tolerance, face_points);
}

}  // namespace vgc::test
