// mesh_topology.cpp — see mesh_topology.h.
#include "mesh_topology.h"

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <tuple>
#include <utility>

namespace vgc {

const char* to_string(MeshStatus s) {
  switch (s) {
    case MeshStatus::Ok: return "Ok";
    case MeshStatus::BadArrays: return "BadArrays";
    case MeshStatus::TooFewCorners: return "TooFewCorners";
    case MeshStatus::IndexOutOfRange: return "IndexOutOfRange";
    case MeshStatus::RepeatedVertex: return "RepeatedVertex";
  }
  return "?";
}

const char* to_string(VertexKind k) {
  switch (k) {
    case VertexKind::Isolated: return "Isolated";
    case VertexKind::Disc: return "Disc";
    case VertexKind::HalfDisc: return "HalfDisc";
    case VertexKind::NonManifold: return "NonManifold";
  }
  return "?";
}

MeshStatus check_mesh(const MeshArrays& mesh, int* bad_face) {
  if (bad_face) *bad_face = -1;
  const int faces = mesh.face_count();
  const std::size_t corners = mesh.face_vertices.size();
  if (mesh.face_offsets.size() != mesh.face_sizes.size()) return MeshStatus::BadArrays;
  long long running = 0;  // faces must tile face_vertices in order
  for (int f = 0; f < faces; ++f) {
    const long long size = mesh.face_sizes[static_cast<std::size_t>(f)];
    const long long offset = mesh.face_offsets[static_cast<std::size_t>(f)];
    if (size < 0 || offset != running || static_cast<unsigned long long>(offset + size) > corners) {
      if (bad_face) *bad_face = f;
      return MeshStatus::BadArrays;
    }
    running += size;
  }
  if (static_cast<std::size_t>(running) != corners) return MeshStatus::BadArrays;
  const int vertices = mesh.vertex_count();
  std::vector<int> seen;
  for (int f = 0; f < faces; ++f) {
    const int size = mesh.face_sizes[static_cast<std::size_t>(f)];
    const int offset = mesh.face_offsets[static_cast<std::size_t>(f)];
    MeshStatus s = MeshStatus::Ok;
    if (size < 3) {
      s = MeshStatus::TooFewCorners;
    } else {
      seen.assign(mesh.face_vertices.begin() + offset, mesh.face_vertices.begin() + offset + size);
      for (int v : seen)
        if (v < 0 || v >= vertices) s = MeshStatus::IndexOutOfRange;
      if (s == MeshStatus::Ok) {
        std::sort(seen.begin(), seen.end());
        if (std::adjacent_find(seen.begin(), seen.end()) != seen.end()) s = MeshStatus::RepeatedVertex;
      }
    }
    if (s != MeshStatus::Ok) {
      if (bad_face) *bad_face = f;
      return s;
    }
  }
  return MeshStatus::Ok;
}

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
      int& p = parent[static_cast<std::size_t>(x)];
      p = parent[static_cast<std::size_t>(p)];
      x = p;
    }
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b) std::swap(a, b);
    parent[static_cast<std::size_t>(a)] = b;  // the smaller index becomes the root
  }
};

// Numbers the classes of `uf` over 0..n-1 by first appearance.
std::vector<int> number_classes(UnionFind& uf, int n, int* count) {
  std::vector<int> label(static_cast<std::size_t>(n), -1), out(static_cast<std::size_t>(n));
  int next = 0;
  for (int i = 0; i < n; ++i) {
    int& l = label[static_cast<std::size_t>(uf.find(i))];
    if (l < 0) l = next++;
    out[static_cast<std::size_t>(i)] = l;
  }
  *count = next;
  return out;
}

}  // namespace

int next_corner(const MeshArrays& mesh, const MeshTopology& topology, int c) {
  const auto f = static_cast<std::size_t>(topology.corner_face[static_cast<std::size_t>(c)]);
  const int o = mesh.face_offsets[f], n = mesh.face_sizes[f];
  return o + (c - o + 1) % n;
}

int prev_corner(const MeshArrays& mesh, const MeshTopology& topology, int c) {
  const auto f = static_cast<std::size_t>(topology.corner_face[static_cast<std::size_t>(c)]);
  const int o = mesh.face_offsets[f], n = mesh.face_sizes[f];
  return o + (c - o + n - 1) % n;
}

std::vector<int> group_corner_fans(const MeshArrays& mesh, const MeshTopology& t,
                                   const std::vector<bool>& cut_edge, int* fan_count) {
  const int corners = static_cast<int>(t.corner_face.size());
  UnionFind uf(static_cast<std::size_t>(corners));
  const auto& fv = mesh.face_vertices;
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    if (t.edges[e].use_count != 2) continue;
    if (!cut_edge.empty() && cut_edge[e]) continue;
    const int c1 = t.edge_corners[static_cast<std::size_t>(t.edge_corner_offsets[e])];
    const int c2 = t.edge_corners[static_cast<std::size_t>(t.edge_corner_offsets[e]) + 1];
    // The corner of c's face at vertex v, for v an end of c's edge.
    auto at = [&](int c, int v) { return fv[static_cast<std::size_t>(c)] == v ? c : next_corner(mesh, t, c); };
    for (int v : {t.edges[e].a, t.edges[e].b}) uf.unite(at(c1, v), at(c2, v));
  }
  int count = 0;
  std::vector<int> fans = number_classes(uf, corners, &count);
  if (fan_count) *fan_count = count;
  return fans;
}

namespace {

// classify_mesh's phases, in order; each reads what the ones before filled.
// The definitions they implement are mesh_topology.h's (Spec: 002).

// Phase 1, corners: check_mesh made the faces tile face_vertices, so every
// corner has exactly one face (the "< 0" guards of later phases are belt and
// braces).
void assign_corner_faces(const MeshArrays& mesh, MeshTopology& t) {
  const int faces = mesh.face_count();
  const int corners = static_cast<int>(mesh.face_vertices.size());
  t.corner_face.assign(static_cast<std::size_t>(corners), -1);
  t.corner_edge.assign(static_cast<std::size_t>(corners), -1);
  for (int f = 0; f < faces; ++f)
    for (int i = 0; i < mesh.face_sizes[static_cast<std::size_t>(f)]; ++i)
      t.corner_face[static_cast<std::size_t>(mesh.face_offsets[static_cast<std::size_t>(f)] + i)] = f;
}

// Phase 2, edges (winged-edge connectivity, 002): sort (min, max, corner)
// triples and group them; an edge's corners are its uses, ascending.
void build_edges(const MeshArrays& mesh, MeshTopology& t) {
  const auto& fv = mesh.face_vertices;
  const int corners = static_cast<int>(fv.size());
  struct Use {
    int a, b, corner;
  };
  std::vector<Use> uses;
  uses.reserve(fv.size());
  for (int c = 0; c < corners; ++c) {
    if (t.corner_face[static_cast<std::size_t>(c)] < 0) continue;
    const int u = fv[static_cast<std::size_t>(c)], w = fv[static_cast<std::size_t>(next_corner(mesh, t, c))];
    uses.push_back({std::min(u, w), std::max(u, w), c});
  }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return std::tie(x.a, x.b, x.corner) < std::tie(y.a, y.b, y.corner);
  });
  for (std::size_t i = 0; i < uses.size(); ++i) {
    if (i == 0 || uses[i].a != uses[i - 1].a || uses[i].b != uses[i - 1].b) {
      t.edges.push_back({uses[i].a, uses[i].b, 0, 0});
      t.edge_corner_offsets.push_back(static_cast<int>(i));
    }
    MeshEdge& e = t.edges.back();
    ++e.use_count;
    if (fv[static_cast<std::size_t>(uses[i].corner)] == e.a) ++e.forward_count;
    t.edge_corners.push_back(uses[i].corner);
    t.corner_edge[static_cast<std::size_t>(uses[i].corner)] = static_cast<int>(t.edges.size()) - 1;
  }
  t.edge_corner_offsets.push_back(static_cast<int>(uses.size()));
}

// Phase 3, corners per vertex (counting sort keeps them ascending).
void build_vertex_corners(const MeshArrays& mesh, MeshTopology& t) {
  const int vertices = mesh.vertex_count();
  const auto& fv = mesh.face_vertices;
  const int corners = static_cast<int>(fv.size());
  t.vertex_corner_offsets.assign(static_cast<std::size_t>(vertices) + 1, 0);
  for (int c = 0; c < corners; ++c)
    if (t.corner_face[static_cast<std::size_t>(c)] >= 0) ++t.vertex_corner_offsets[static_cast<std::size_t>(fv[static_cast<std::size_t>(c)]) + 1];
  for (int v = 0; v < vertices; ++v)
    t.vertex_corner_offsets[static_cast<std::size_t>(v) + 1] += t.vertex_corner_offsets[static_cast<std::size_t>(v)];
  t.vertex_corners.resize(static_cast<std::size_t>(t.vertex_corner_offsets.back()));
  std::vector<int> fill(t.vertex_corner_offsets.begin(), t.vertex_corner_offsets.end() - 1);
  for (int c = 0; c < corners; ++c)
    if (t.corner_face[static_cast<std::size_t>(c)] >= 0)
      t.vertex_corners[static_cast<std::size_t>(fill[static_cast<std::size_t>(fv[static_cast<std::size_t>(c)])]++)] = c;
}

// Phase 4, edge classes (002: "each edge ... can be the edge of either one
// or two polygons") and orientation consistency (000 2.6: a consistently
// oriented mesh uses each interior edge once in each direction).
void classify_edges(MeshTopology& t) {
  for (const MeshEdge& e : t.edges) {
    if (e.use_count == 1) ++t.boundary_edge_count;
    else if (e.use_count == 2) ++t.interior_edge_count;
    else ++t.non_manifold_edge_count;
    if (e.use_count == 2 && e.forward_count != 1) t.consistently_oriented = false;
  }
}

// Phase 5, vertex kinds from fans (corners joined across 2-use edges; 002:
// a neighbourhood "equivalent to a disc ... or a half disc"), then the
// mesh-wide manifold flags.
void classify_vertices(const MeshArrays& mesh, MeshTopology& t) {
  const int vertices = mesh.vertex_count();
  int fan_total = 0;
  const std::vector<int> corner_fan = group_corner_fans(mesh, t, {}, &fan_total);
  t.vertex_kinds.assign(static_cast<std::size_t>(vertices), VertexKind::Isolated);
  t.vertex_fan_counts.assign(static_cast<std::size_t>(vertices), 0);
  std::vector<int> fans_here;
  for (int v = 0; v < vertices; ++v) {
    const int begin = t.vertex_corner_offsets[static_cast<std::size_t>(v)];
    const int end = t.vertex_corner_offsets[static_cast<std::size_t>(v) + 1];
    if (begin == end) {
      ++t.isolated_vertex_count;
      continue;
    }
    fans_here.clear();
    bool over_used = false, boundary = false;
    for (int k = begin; k < end; ++k) {
      const int c = t.vertex_corners[static_cast<std::size_t>(k)];
      fans_here.push_back(corner_fan[static_cast<std::size_t>(c)]);
      for (int e : {t.corner_edge[static_cast<std::size_t>(c)], t.corner_edge[static_cast<std::size_t>(prev_corner(mesh, t, c))]}) {
        const int n = t.edges[static_cast<std::size_t>(e)].use_count;
        if (n > 2) over_used = true;
        if (n == 1) boundary = true;
      }
    }
    std::sort(fans_here.begin(), fans_here.end());
    const int fan_count = static_cast<int>(std::unique(fans_here.begin(), fans_here.end()) - fans_here.begin());
    t.vertex_fan_counts[static_cast<std::size_t>(v)] = fan_count;
    VertexKind k = VertexKind::Disc;
    if (over_used || fan_count > 1) k = VertexKind::NonManifold;
    else if (boundary) k = VertexKind::HalfDisc;
    t.vertex_kinds[static_cast<std::size_t>(v)] = k;
    if (k == VertexKind::NonManifold) t.non_manifold_vertices.push_back(v);
  }

  t.is_manifold = t.non_manifold_edge_count == 0 && t.non_manifold_vertices.empty();
  t.is_polygon_mesh = t.is_manifold && t.consistently_oriented;
  t.closed = t.boundary_edge_count == 0;
}

// Phase 6, orientability: propagate a flip sign across 2-use edges; the
// mesh is not orientable when a face would need both signs.
void check_orientability(const MeshArrays& mesh, MeshTopology& t) {
  const int faces = mesh.face_count();
  const auto& fv = mesh.face_vertices;
  std::vector<int> sign(static_cast<std::size_t>(faces), 0);
  std::vector<int> stack;
  for (int seed = 0; seed < faces && t.orientable; ++seed) {
    if (sign[static_cast<std::size_t>(seed)] != 0) continue;
    sign[static_cast<std::size_t>(seed)] = 1;
    stack.push_back(seed);
    while (!stack.empty() && t.orientable) {
      const int f = stack.back();
      stack.pop_back();
      const int o = mesh.face_offsets[static_cast<std::size_t>(f)];
      for (int c = o; c < o + mesh.face_sizes[static_cast<std::size_t>(f)]; ++c) {
        const auto e = static_cast<std::size_t>(t.corner_edge[static_cast<std::size_t>(c)]);
        if (t.edges[e].use_count != 2) continue;
        const int c1 = t.edge_corners[static_cast<std::size_t>(t.edge_corner_offsets[e])];
        const int c2 = t.edge_corners[static_cast<std::size_t>(t.edge_corner_offsets[e]) + 1];
        const int other = c1 == c ? c2 : c1;
        const int g = t.corner_face[static_cast<std::size_t>(other)];
        // Same direction of use means the two faces need opposite signs.
        const bool same_dir = fv[static_cast<std::size_t>(c)] == fv[static_cast<std::size_t>(other)];
        const int want = same_dir ? -sign[static_cast<std::size_t>(f)] : sign[static_cast<std::size_t>(f)];
        if (sign[static_cast<std::size_t>(g)] == 0) {
          sign[static_cast<std::size_t>(g)] = want;
          stack.push_back(g);
        } else if (sign[static_cast<std::size_t>(g)] != want) {
          t.orientable = false;
          break;
        }
      }
    }
  }
}

// Phase 7, components: faces joined through shared edges (any use count);
// then the counts of the Euler characteristic V - E + F (V: used vertices).
void find_components(const MeshArrays& mesh, MeshTopology& t) {
  const int faces = mesh.face_count();
  UnionFind uf(static_cast<std::size_t>(faces));
  for (std::size_t e = 0; e < t.edges.size(); ++e)
    for (int k = t.edge_corner_offsets[e] + 1; k < t.edge_corner_offsets[e + 1]; ++k)
      uf.unite(t.corner_face[static_cast<std::size_t>(t.edge_corners[static_cast<std::size_t>(t.edge_corner_offsets[e])])],
               t.corner_face[static_cast<std::size_t>(t.edge_corners[static_cast<std::size_t>(k)])]);
  t.face_component = number_classes(uf, faces, &t.component_count);

  t.face_count = faces;
  t.edge_count = static_cast<int>(t.edges.size());
  t.used_vertex_count = mesh.vertex_count() - t.isolated_vertex_count;
  t.euler_characteristic = static_cast<long>(t.used_vertex_count) - t.edge_count + t.face_count;
}

// Phase 8, boundary loops of a manifold mesh: every boundary vertex has
// exactly two boundary edges. Each loop starts at its smallest vertex and
// runs along the border half-edges (opposite to the faces' use), or towards
// the start's smaller neighbour where the faces disagree.
void trace_boundary_loops(const MeshArrays& mesh, MeshTopology& t) {
  const int vertices = mesh.vertex_count();
  const auto& fv = mesh.face_vertices;
  std::vector<std::array<int, 2>> vb(static_cast<std::size_t>(vertices), {-1, -1});
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    if (t.edges[e].use_count != 1) continue;
    for (int v : {t.edges[e].a, t.edges[e].b}) {
      auto& slot = vb[static_cast<std::size_t>(v)];
      (slot[0] < 0 ? slot[0] : slot[1]) = static_cast<int>(e);
    }
  }
  auto other_end = [&](int e, int v) {
    const MeshEdge& me = t.edges[static_cast<std::size_t>(e)];
    return me.a == v ? me.b : me.a;
  };
  // True when the border half-edge of boundary edge e leaves v, i.e. the
  // face uses e towards v.
  auto border_leaves = [&](int e, int v) {
    const int c = t.edge_corners[static_cast<std::size_t>(t.edge_corner_offsets[static_cast<std::size_t>(e)])];
    return fv[static_cast<std::size_t>(next_corner(mesh, t, c))] == v;
  };
  std::vector<bool> done(t.edges.size(), false);
  std::vector<std::vector<int>> loops;
  for (int s = 0; s < vertices; ++s) {
    const auto sb = vb[static_cast<std::size_t>(s)];
    if (sb[0] < 0 || done[static_cast<std::size_t>(sb[0])]) continue;
    const bool l0 = border_leaves(sb[0], s), l1 = border_leaves(sb[1], s);
    int e = sb[0];
    if (l0 != l1) e = l0 ? sb[0] : sb[1];
    else if (other_end(sb[1], s) < other_end(sb[0], s)) e = sb[1];
    std::vector<int> loop{s};
    int v = s;
    while (true) {
      done[static_cast<std::size_t>(e)] = true;
      v = other_end(e, v);
      if (v == s) break;
      loop.push_back(v);
      const auto b = vb[static_cast<std::size_t>(v)];
      e = b[0] == e ? b[1] : b[0];
    }
    loops.push_back(std::move(loop));
  }
  t.boundary_loops = std::move(loops);
}

}  // namespace

MeshTopology classify_mesh(const MeshArrays& mesh) {
  MeshTopology t;
  t.status = check_mesh(mesh, &t.bad_face);
  if (t.status != MeshStatus::Ok) return t;
  assign_corner_faces(mesh, t);
  build_edges(mesh, t);
  build_vertex_corners(mesh, t);
  classify_edges(t);
  classify_vertices(mesh, t);
  check_orientability(mesh, t);
  find_components(mesh, t);
  if (t.is_manifold) trace_boundary_loops(mesh, t);
  return t;
}

}  // namespace vgc
