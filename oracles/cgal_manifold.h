// cgal_manifold.h — connectivity and manifoldness answered by CGAL 5.5
// Polygon Mesh Processing, as an oracle for reference/geometry/mesh_topology.h.
//
// Spec: 002 (manifold rules: each edge in one or two polygons; disc /
// half-disc neighbourhoods), 000 section 2.6 (consistent front side).
//
// Rationale: CGAL is an independent implementation of the same questions.
// This header has no CGAL type (the only file that includes CGAL headers is
// cgal_manifold.cpp); it reports what CGAL says, named after the CGAL call
// that said it, and marks with std::optional / flags the answers CGAL can
// only give for some inputs (CGAL 5.5: is_polygon_soup_a_polygon_mesh checks
// no index against the point count, and polygon_soup_to_polygon_mesh needs a
// valid soup, its preconditions being off under NDEBUG).
//
// How each answer is obtained (polygon soup: point i is (i, 0, 0), so any
// vertex CGAL creates maps back to its input index):
//  - status: checked here by hand (CGAL checks no index range), with the
//    precedence of reference check_mesh (BadArrays over all faces; then the
//    first failing face: TooFewCorners, IndexOutOfRange, RepeatedVertex).
//    CGAL is not called unless status == Ok.
//  - soup_is_polygon_mesh: PMP::is_polygon_soup_a_polygon_mesh(input).
//  - non_manifold_edges, singular_vertices, reversed_polygon_count,
//    orient_duplicated_points: PMP::orient_polygon_soup on a copy, with a
//    visitor (non_manifold_edge, non_manifold_vertex,
//    polygon_orientation_reversed). CGAL's "non-manifold vertex" is a vertex
//    whose corners fall apart after CGAL cuts every edge with > 2 uses AND
//    every edge where its re-orientation met a conflict; so it contains the
//    topologically non-manifold vertices and, for non-orientable input, may
//    contain more (which ones depends on CGAL's traversal).
//  - oriented_soup_is_polygon_mesh: is_polygon_soup_a_polygon_mesh on the
//    re-oriented (and possibly vertex-duplicated) soup; only then is
//    PMP::polygon_soup_to_polygon_mesh called (mesh_built).
//  - orientable (faces compared across edges with exactly two uses, as in
//    the reference): false when the re-oriented soup is not a polygon mesh
//    (an orientation conflict whose ends were not duplicated leaves a
//    directed edge used twice), or when an input edge that CGAL did not
//    report as non-manifold became several edges of the built mesh (a
//    conflict edge cut open by duplicating an end); true otherwise.
//    consistently_oriented == orientable && no polygon reversed (CGAL keeps
//    each component's first polygon and reverses only disagreeing ones).
//    Both are set whenever status == Ok (std::optional kept so that a
//    comparison states which answers it relies on).
//  - mesh answers (Surface_mesh built from the oriented soup, isolated points
//    inserted): CGAL::is_closed, CGAL::is_valid_polygon_mesh,
//    PMP::non_manifold_vertices, PMP::extract_boundary_cycles (as source
//    vertex cycles, rotated to start at their smallest vertex),
//    PMP::connected_components (face i of the mesh is polygon i), counts of
//    vertices/edges/faces/border edges; euler = V - E + F over non-isolated
//    vertices. They describe the INPUT only when mesh_matches_input (no
//    point was duplicated: then the oriented soup has the input's vertices
//    and edges, possibly with faces reversed).
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "mesh_arrays.h"
#include "mesh_topology.h"

namespace vgc {

struct CgalManifoldReport {
  MeshStatus status = MeshStatus::Ok;
  int bad_face = -1;

  bool soup_is_polygon_mesh = false;
  std::vector<std::array<int, 3>> non_manifold_edges;  // {a, b, uses}, a < b, sorted
  std::vector<std::pair<int, int>> singular_vertices;  // {vertex, link components}, sorted
  int reversed_polygon_count = 0;
  bool orient_duplicated_points = false;
  bool oriented_soup_is_polygon_mesh = false;
  std::optional<bool> orientable;
  std::optional<bool> consistently_oriented;

  bool mesh_built = false;
  bool mesh_matches_input = false;
  int vertex_count = 0;           // all Surface_mesh vertices, isolated included
  int isolated_vertex_count = 0;
  int edge_count = 0;
  int face_count = 0;
  int border_edge_count = 0;
  std::vector<std::array<int, 2>> border_edges;   // {a, b}, a < b, sorted (Surface_mesh::is_border(e))
  std::vector<int> border_vertices;               // sorted (Surface_mesh::is_border(v)), isolated excluded
  long euler_characteristic = 0;  // (vertex_count - isolated) - edges + faces
  bool closed = false;
  bool valid_polygon_mesh = false;
  std::vector<int> mesh_non_manifold_vertices;     // expected empty on a built mesh
  std::vector<std::vector<int>> boundary_cycles;   // sorted by first vertex
  std::vector<int> face_component;                 // renumbered by first appearance
  int component_count = 0;
};

// Asks CGAL about `mesh` (see above). Precondition: none. Failure: invalid
// input gives status != Ok and nothing else filled. Never throws except
// std::bad_alloc; CGAL is only given soups that passed its preconditions.
CgalManifoldReport cgal_classify_mesh(const MeshArrays& mesh);

}  // namespace vgc
