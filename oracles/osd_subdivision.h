// osd_subdivision.h — OpenSubdiv 3 as an oracle for uniform subdivision.
//
// Spec: 000 section 2.6 (Catmull/Clark subdivision surfaces with vertex and
// edge creases), 004 (Loop subdivision of triangles), 001 (face holes).
//
// Rationale: an independent implementation of the subdivision the reference
// computes (reference/geometry/catmull_clark.h, reference/geometry/loop_subdivision.h). Plain
// types only: OpenSubdiv's headers are included by osd_subdivision.cpp and
// nowhere else. Options are set explicitly to what the reference
// implements: Sdc VTX_BOUNDARY_EDGE_ONLY, CREASE_UNIFORM, TRI_SUB_CATMARK.
// Every level exposes its child vertices by PARENT component (vertex, edge,
// face) so results are matched by parent, never by numbering. Input
// sharpness is given as OpenSubdiv takes it: OpenSubdiv applies its own
// boundary rule, which is what makes the reference's boundary rule checked.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mesh_arrays.h"

namespace vgc {

enum class OsdScheme { CatmullClark, Loop };

struct OsdInput {
  OsdScheme scheme = OsdScheme::CatmullClark;
  std::vector<std::array<double, 3>> positions;
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;                // faces concatenated
  std::vector<std::array<int, 2>> crease_edges;  // vertex pairs naming existing edges
  std::vector<float> crease_sharpness;           // per crease edge (10 = infinite)
  std::vector<int> corner_vertices;
  std::vector<float> corner_sharpness;           // per corner vertex
  std::vector<int> hole_faces;
  int levels = 1;                                // 1..10
};

struct OsdLevel {
  std::vector<std::array<double, 3>> positions;
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;
  std::vector<std::array<int, 2>> edges;  // per edge: its vertices
  std::vector<int> face_edges;            // per corner: GetFaceEdges, faces concatenated
  std::vector<float> edge_sharpness;
  std::vector<float> vertex_sharpness;
  std::vector<unsigned char> face_hole;
  // Relation to the parent level (empty at level 0), by parent component:
  std::vector<int> child_of_parent_vertex;  // GetVertexChildVertex
  std::vector<int> child_of_parent_edge;    // GetEdgeChildVertex
  std::vector<int> child_of_parent_face;    // GetFaceChildVertex (Catmull-Clark only; empty for Loop)
  std::vector<std::vector<int>> child_faces_of_parent_face;  // GetFaceChildFaces
};

struct OsdResult {
  bool ok = false;
  std::string failure;                // why not ok
  std::vector<std::string> messages;  // OpenSubdiv's error and warning callbacks
  std::vector<OsdLevel> levels;       // 0..levels
};

// Refines uniformly to `input.levels` and interpolates positions level by
// level (PrimvarRefinerReal<double>). Never throws; checks every index
// before OpenSubdiv sees it (an out-of-range one is `failure`, not a
// crash). Not thread-safe: OpenSubdiv's callbacks are global.
OsdResult osd_refine_uniform(const OsdInput& input);

// OpenSubdiv's input for a node's mesh with the reference's crease mapping
// (reference/geometry/crease_sharpness.h): an edge's sharpness comes from the stored
// creases of its polygons combined by combine_edge_creases, a vertex's from
// its crease (as a corner); the boundary rule is left to OpenSubdiv.
// Precondition: `m` passes check_mesh (indices in range).
OsdInput osd_input_from_mesh(const MeshArrays& m, OsdScheme scheme, int levels);

}  // namespace vgc
