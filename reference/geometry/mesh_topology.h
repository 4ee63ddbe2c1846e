// mesh_topology.h — connectivity and manifoldness of a polygon mesh.
//
// Spec: 002 (winged-edge connectivity: per edge its end vertices and the
// polygons on either side; the manifold rules: "each edge in the polygon mesh
// can be the edge of either one or two polygons", the neighbourhood of every
// point "topologically equivalent to a disc ... or a half disc"; exercise 2:
// "a polygon has at least three vertices"); 000 section 2.6 (polygons
// reference vertices; front side clockwise, so a consistently oriented mesh
// traverses each interior edge once in each direction).
//
// Rationale: MeshArrays is a polygon soup. This file builds, once, the
// corner/edge/vertex incidences every derived computation needs (normals,
// subdivision checks, the CGAL comparison) and classifies the mesh with
// definitions chosen to be checkable against CGAL Polygon Mesh Processing
// (oracles/cgal_manifold.h). Corners play the part of half-edges: corner c
// of a face starts the directed edge from its vertex to the next corner's
// vertex (the same corner-to-edge rule as edge creases, crease.h).
//
// Definitions (all for valid input, status == Ok):
//  - edge: an unordered pair {a, b} of distinct vertices joined by at least
//    one corner. use_count = corners using it (either direction);
//    boundary: 1, interior: 2, non-manifold: > 2.
//  - fan of a vertex v: the corners at v, joined when two of them share an
//    edge at v that has exactly two uses (orientation ignored).
//  - vertex kind: Isolated (no corner), NonManifold (an incident edge with
//    > 2 uses, or more than one fan: e.g. two fans touching at v, a
//    "bow-tie"), HalfDisc (one fan, some incident boundary edge), Disc.
//  - consistently_oriented: every edge with 2 uses is used once in each
//    direction (edges with 1 or > 2 uses impose nothing).
//  - orientable: faces can be flipped so that the above holds (faces
//    compared only across edges with exactly 2 uses).
//  - is_manifold: no non-manifold edge and no non-manifold vertex
//    (isolated vertices are allowed and counted separately).
//  - is_polygon_mesh: is_manifold and consistently_oriented; this equals
//    CGAL's is_polygon_soup_a_polygon_mesh for valid input.
//  - closed: no boundary edge (an empty mesh is closed).
//  - Euler characteristic: V - E + F with V = vertices used by at least one
//    face (isolated vertices NOT counted; see isolated_vertex_count).
//  - components: faces joined through shared edges (any use count); two
//    fans meeting only at a vertex are two components.
//  - boundary loops (only for a manifold mesh, where the boundary edges form
//    disjoint cycles): each loop starts at its smallest vertex and runs in
//    the direction opposite to the faces' use of its edges (the border
//    half-edge direction of CGAL/OpenMesh); where the faces disagree (not
//    consistently oriented) it runs towards the start's smaller neighbour.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "mesh_arrays.h"

namespace vgc {

// Validity of a MeshArrays as input to the derived-geometry functions.
enum class MeshStatus {
  Ok,
  BadArrays,        // face_offsets/face_sizes/face_vertices disagree (see check_mesh)
  TooFewCorners,    // a face with fewer than 3 corners
  IndexOutOfRange,  // a corner names no vertex (< 0 or >= vertex_count())
  RepeatedVertex,   // a face names one vertex twice
};
const char* to_string(MeshStatus s);

enum class VertexKind { Isolated, Disc, HalfDisc, NonManifold };
const char* to_string(VertexKind k);

// Checks `mesh` without building anything. BadArrays is checked over all
// faces first: face_offsets.size() must equal face_sizes.size(), and the
// faces must tile face_vertices in order (size >= 0, offset = the sum of the
// sizes before it, as update_face_offsets makes it; the sizes sum to
// face_vertices.size()); bad_face is the first face breaking that, or -1
// when only the array lengths disagree. Then
// faces in order, the first face failing wins, testing TooFewCorners,
// IndexOutOfRange, RepeatedVertex in that order. *bad_face (if given)
// receives that face, or -1. Never throws.
MeshStatus check_mesh(const MeshArrays& mesh, int* bad_face = nullptr);

struct MeshEdge {
  int a = 0, b = 0;       // a < b
  int use_count = 0;      // corners using the edge, either direction
  int forward_count = 0;  // corners using it from a to b
};

struct MeshTopology {
  MeshStatus status = MeshStatus::Ok;
  int bad_face = -1;  // the face that made status != Ok
  // Everything below is filled only when status == Ok.

  // Winged-edge incidences. Corner c belongs to corner_face[c] and starts
  // edge corner_edge[c]. Edges are sorted by (a, b).
  std::vector<int> corner_face;
  std::vector<int> corner_edge;
  std::vector<MeshEdge> edges;
  std::vector<int> edge_corner_offsets;    // edges.size() + 1 entries
  std::vector<int> edge_corners;           // corners using each edge, ascending
  std::vector<int> vertex_corner_offsets;  // vertex_count + 1 entries
  std::vector<int> vertex_corners;         // corners at each vertex, ascending

  // Per vertex.
  std::vector<VertexKind> vertex_kinds;
  std::vector<int> vertex_fan_counts;      // fans (see above) at each vertex
  std::vector<int> non_manifold_vertices;  // ascending
  int isolated_vertex_count = 0;

  // Per edge, counted.
  int boundary_edge_count = 0;
  int interior_edge_count = 0;
  int non_manifold_edge_count = 0;

  bool consistently_oriented = true;
  bool orientable = true;
  bool is_manifold = true;
  bool is_polygon_mesh = true;
  bool closed = true;

  std::optional<std::vector<std::vector<int>>> boundary_loops;  // only if is_manifold

  int used_vertex_count = 0;  // V of the Euler characteristic
  int edge_count = 0;
  int face_count = 0;
  long euler_characteristic = 0;

  std::vector<int> face_component;  // numbered by first appearance in face order
  int component_count = 0;
};

// Builds the connectivity of `mesh` and classifies it (definitions above).
// Precondition: none; any MeshArrays may be given. Failure: invalid input
// (check_mesh) returns status != Ok, bad_face set, and nothing else filled.
// Cost O(C log C) for C corners. Never throws except std::bad_alloc.
MeshTopology classify_mesh(const MeshArrays& mesh);

// Corner navigation inside its face. Precondition: check_mesh(mesh) == Ok
// and 0 <= c < face_vertices.size(); topology from classify_mesh(mesh).
int next_corner(const MeshArrays& mesh, const MeshTopology& topology, int c);
int prev_corner(const MeshArrays& mesh, const MeshTopology& topology, int c);

// Groups the corners at each vertex into fans: two corners at the same
// vertex are joined when they share an edge at that vertex that has exactly
// two uses and is not cut (cut_edge[e] true). Returns, per corner, its fan
// index; fans are numbered by their smallest corner, in ascending order.
// Preconditions: topology.status == Ok for `mesh`; cut_edge is empty (no
// cuts) or has topology.edges.size() entries. Failure: none.
std::vector<int> group_corner_fans(const MeshArrays& mesh, const MeshTopology& topology,
                                   const std::vector<bool>& cut_edge, int* fan_count);

}  // namespace vgc
