// topology_comparison.cpp — see topology_comparison.h.
#include "topology_comparison.h"

#include <algorithm>
#include <array>
#include <set>
#include <sstream>
#include <vector>

namespace vgc {

namespace {

std::string str(const std::vector<int>& v) {
  std::ostringstream o;
  for (int x : v) o << x << ' ';
  return o.str();
}

// A loop as an undirected cycle: starts at its smallest vertex, then goes
// towards the smaller of that vertex's two neighbours.
std::vector<int> undirected(std::vector<int> loop) {
  std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  if (loop.size() > 2 && loop.back() < loop[1]) std::reverse(loop.begin() + 1, loop.end());
  return loop;
}

}  // namespace

std::string compare_topology_with_cgal(const MeshTopology& r, const CgalManifoldReport& c) {
  std::ostringstream why;
  auto fail = [&](const std::string& what) {
    why << what;
    return why.str();
  };
  if (r.status != c.status) return fail(std::string("status ") + to_string(r.status) + " vs " + to_string(c.status));
  if (r.bad_face != c.bad_face) return fail("bad_face");
  if (r.status != MeshStatus::Ok) return "";

  if (r.is_polygon_mesh != c.soup_is_polygon_mesh) return fail("is_polygon_mesh vs is_polygon_soup_a_polygon_mesh");

  std::vector<std::array<int, 3>> nm_edges;
  for (const MeshEdge& e : r.edges)
    if (e.use_count > 2) nm_edges.push_back({e.a, e.b, e.use_count});
  if (nm_edges != c.non_manifold_edges) return fail("non-manifold edges");
  if (static_cast<int>(nm_edges.size()) != r.non_manifold_edge_count) return fail("non_manifold_edge_count");

  // Topologically non-manifold vertices are always singular for CGAL; with
  // no orientation conflict (orientable) the two sets and the fan / link
  // component counts are equal.
  std::set<int> singular;
  for (const auto& [v, n] : c.singular_vertices) singular.insert(v);
  for (int v : r.non_manifold_vertices)
    if (!singular.count(v)) return fail("reference non-manifold vertex " + std::to_string(v) + " not singular for CGAL");
  if (r.orientable) {
    if (std::vector<int>(singular.begin(), singular.end()) != r.non_manifold_vertices)
      return fail("non-manifold vertices: ref " + str(r.non_manifold_vertices));
    for (const auto& [v, n] : c.singular_vertices)
      if (r.vertex_fan_counts[static_cast<std::size_t>(v)] != n) return fail("fan count of vertex " + std::to_string(v));
  }

  if (!c.orientable || !c.consistently_oriented) return fail("CGAL gave no orientability");
  if (*c.orientable != r.orientable) return fail("orientable");
  if (*c.consistently_oriented != r.consistently_oriented) return fail("consistently_oriented");

  if (r.is_manifold && r.orientable && !c.mesh_matches_input) return fail("CGAL built no mesh for a manifold orientable input");
  if (!c.mesh_matches_input) return "";
  if (!r.is_manifold) return fail("CGAL built the input unchanged but the reference says non-manifold");
  if (c.vertex_count - c.isolated_vertex_count != r.used_vertex_count) return fail("used vertex count");
  if (c.isolated_vertex_count != r.isolated_vertex_count) return fail("isolated vertex count");
  if (c.edge_count != r.edge_count) return fail("edge count");
  if (c.face_count != r.face_count) return fail("face count");
  if (c.euler_characteristic != r.euler_characteristic) return fail("Euler characteristic");
  if (c.border_edge_count != r.boundary_edge_count) return fail("boundary edge count");
  if (c.edge_count - c.border_edge_count != r.interior_edge_count) return fail("interior edge count");
  std::vector<std::array<int, 2>> ref_border;
  for (const MeshEdge& e : r.edges)
    if (e.use_count == 1) ref_border.push_back({e.a, e.b});
  if (ref_border != c.border_edges) return fail("boundary edges");
  std::vector<int> half_discs;
  for (std::size_t v = 0; v < r.vertex_kinds.size(); ++v)
    if (r.vertex_kinds[v] == VertexKind::HalfDisc) half_discs.push_back(static_cast<int>(v));
  if (half_discs != c.border_vertices) return fail("half-disc vertices vs CGAL border vertices");
  if (c.closed != r.closed) return fail("closed");
  if (c.valid_polygon_mesh != (r.isolated_vertex_count == 0)) return fail("is_valid_polygon_mesh");
  if (!c.mesh_non_manifold_vertices.empty()) return fail("non_manifold_vertices on the built mesh");
  if (!r.boundary_loops) return fail("no reference boundary loops");
  std::vector<std::vector<int>> ref_loops = *r.boundary_loops, cgal_loops = c.boundary_cycles;
  if (c.reversed_polygon_count != 0) {  // CGAL flipped faces: compare loops undirected
    for (auto& l : ref_loops) l = undirected(l);
    for (auto& l : cgal_loops) l = undirected(l);
    std::sort(ref_loops.begin(), ref_loops.end());
    std::sort(cgal_loops.begin(), cgal_loops.end());
  }
  if (ref_loops != cgal_loops) return fail("boundary loops");
  if (c.component_count != r.component_count) return fail("component count");
  if (c.face_component != r.face_component) return fail("face components");
  return "";
}

}  // namespace vgc
