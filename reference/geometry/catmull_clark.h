// catmull_clark.h — uniform Catmull-Clark subdivision of a node's mesh, with
// semi-sharp and infinitely sharp vertex and edge creases and boundaries.
//
// Spec: 000 section 2.6 ("Verse has a single primitive ...: Catmull/Clark
// subdivision surfaces"; "creases with which one can control the degree of
// subdivision allowed for each vertex and edge"), 2.6.2 (crease values, via
// crease_sharpness.h), 2.6.4 (the cube, all creases maximal, is a cube);
// 001 (the child numbering: "the sub-face labeled n has one incident vertex
// that is the result of the subdivision of the parent vertex also labeled n";
// in a quad the child of parent vertex n has index n in sub-face n, in any
// other polygon it has index 0).
//
// Rationale: a small, readable reference that names the parent of every
// child vertex (child of a face, of an edge, of a vertex), so its results
// are matched to OpenSubdiv (oracles/osd_subdivision.h) by parent
// component, never by order. The rules are OpenSubdiv's Sdc Catmark rules
// with CREASE_UNIFORM creasing, VTX_BOUNDARY_EDGE_ONLY boundaries and
// TRI_SUB_CATMARK triangles (see crease_sharpness.h for the sharpness rules):
//   face point  = average of the face's vertices;
//   edge point  = smooth: (a + b)/4 + (F0 + F1)/4 (faces: child face points);
//                 sharpness >= 1: (a + b)/2; 0 < s < 1: s*sharp + (1-s)*smooth;
//   vertex point = smooth/dart: ((n-2)/n) v + (1/n^2) sum(opposite vertices)
//                                + (1/n^2) sum(child face points);
//                 crease (2 sharp edges): 3/4 v + 1/8 (each sharp neighbour);
//                 corner (sharp vertex or > 2 sharp edges): v;
//                 when the rule changes from parent to child, the parent
//                 rule's mask weighted by fractional_weight_at_vertex and the
//                 child rule's mask by the rest.
// Holes (spec 001 face "hole" edits) are a per-face flag inherited by every
// child face; they change no position.
// Non-manifold input (a mesh a node can hold need not be a polygon mesh:
// fins, bow-ties, pillows, faces running the same direction) follows
// OpenSubdiv's rules, read from its Vtr::Level::completeTopologyFromFaceVertices
// and Far::TopologyRefinerFactory (issue 11): see build_base_level and
// non_manifold_tags below; the tags act only through sharpness, which
// children inherit as usual.
// Decision: a vertex in no polygon keeps its position at every level (the
// smooth rule is undefined for valence 0; OpenSubdiv, which tags it
// non-manifold and so infinitely sharp, is not compared there).
#pragma once

#include <array>
#include <vector>

#include "mesh_arrays.h"

namespace vgc {

// One level of a subdivision hierarchy (Catmull-Clark or Loop).
struct SubdivisionLevel {
  std::vector<std::array<double, 3>> positions;  // per vertex
  std::vector<float> vertex_sharpness;           // per vertex
  std::vector<int> face_sizes;                   // corners per face
  std::vector<int> face_offsets;                 // first corner of each face
  std::vector<int> face_vertices;                // vertex per corner, faces concatenated
  std::vector<int> face_edges;                   // per corner: the edge from this corner to the next
  std::vector<std::array<int, 2>> edges;         // per edge: its two vertices
  std::vector<float> edge_sharpness;             // per edge, after the boundary rule
  std::vector<int> edge_face_count;              // per edge: polygons using it
  std::vector<unsigned char> face_hole;          // per face: 1 if a hole (or child of one)

  // Relation to the parent level; empty at level 0. Indexed by the PARENT
  // level's component, giving this level's index.
  std::vector<int> child_of_parent_vertex;   // parent vertex -> its child vertex
  std::vector<int> child_of_parent_edge;     // parent edge -> its child (edge point)
  std::vector<int> child_of_parent_face;     // parent face -> its face point (Catmull-Clark only)
  std::vector<int> first_child_of_parent_face;  // parent face -> its first child face
  std::vector<int> parent_face;              // this level's face -> its parent face

  int vertex_count() const { return static_cast<int>(positions.size()); }
  int face_count() const { return static_cast<int>(face_sizes.size()); }
  int edge_count() const { return static_cast<int>(edges.size()); }
};

// Level 0 of `mesh`: positions, faces, edges (numbered by first appearance
// walking the faces in order, corner by corner; an edge's vertices in the
// direction its first face uses it), and sharpness from the creases by
// crease_sharpness.h (shared edges: maximum), then OpenSubdiv's rules for
// boundaries and non-manifold topology (Far::TopologyRefinerFactory,
// Vtr::Level::completeTopologyFromFaceVertices; see
// non_manifold_sharpness below): boundary and non-manifold edges are
// infinitely sharp, and so are non-manifold vertices except on a
// non-manifold crease. With non_manifold_rule false (a seeded fault for
// tests) only edges with other than two faces are sharpened, as before
// issue 11. Precondition: none; failure (a face with < 3 corners, a corner
// out of range, a vertex repeated in a face, arrays of the wrong length):
// returns false and leaves *out unspecified.
bool build_base_level(const MeshArrays& mesh, SubdivisionLevel* out, bool non_manifold_rule = true);

// OpenSubdiv's non-manifold rules on a valid mesh (check_mesh Ok), per the
// level-0 edges of build_base_level (face_edges numbering):
//  - an edge is non-manifold when more than two faces use it, or when its
//    second face uses it in the same direction as its first;
//  - a vertex is non-manifold when it ends a non-manifold edge, is in no
//    face, or its faces do not form one fan (two fans touching at it: a
//    "bow-tie"); OpenSubdiv's orderVertexFacesAndEdges fails exactly there;
//  - a non-manifold vertex is made infinitely sharp unless it lies on an
//    interior non-manifold crease: exactly two non-manifold incident edges,
//    no boundary edge, and more incident faces than edges (the spine of a
//    "fin" of three or more sheets), where the crease rule applies.
struct NonManifoldTags {
  std::vector<unsigned char> edge;            // per level-0 edge: 1 if non-manifold
  std::vector<unsigned char> vertex;          // per vertex: 1 if non-manifold
  std::vector<unsigned char> vertex_sharpened;  // per vertex: 1 if made infinitely sharp
};
NonManifoldTags non_manifold_tags(const MeshArrays& mesh, const SubdivisionLevel& base);

// Recomputes edges, face_edges and edge_face_count from the faces (used by
// both schemes after building a child level's faces).
void build_level_edges(SubdivisionLevel* level);

// Deliberately wrong rules, for tests that show the oracle comparison can
// fail. All false in real use.
struct CatmullClarkFaults {
  bool pin_boundary_vertices = false;  // boundary vertices use the corner rule (EDGE_AND_CORNER everywhere)
  bool no_fractional_blend = false;    // sharpness < 1 acts as smooth (no blend)
  bool wrong_crease_weights = false;   // crease vertex rule 2/3 v + 1/6 each
  bool no_non_manifold_rule = false;   // non-manifold vertices and same-direction edges left smooth
};

// One uniform Catmull-Clark step. Child numbering: the child of parent
// vertex v is v; then one face point per parent face in face order; then one
// edge point per parent edge in edge order. A parent face with n corners has
// n child quads, consecutive, child i next to parent corner i (spec 001):
// a quad [v0 v1 v2 v3] gives [v0' e0 F e3], [e0 v1' e1 F], [F e1 v2' e2],
// [e3 F e2 v3']; any other n-gon gives [vi' ei F e(i-1)].
// Precondition: `parent` is a level made by build_base_level or this
// function (possibly edited); failure: none.
SubdivisionLevel refine_catmull_clark(const SubdivisionLevel& parent, const CatmullClarkFaults& faults = {});

// Levels 0..levels of `mesh`. Precondition: as build_base_level, and
// 0 <= levels <= 6 (a level has 4x the faces of its parent); failure:
// returns an empty vector.
std::vector<SubdivisionLevel> subdivide_catmull_clark(const MeshArrays& mesh, int levels,
                                                      const CatmullClarkFaults& faults = {});

}  // namespace vgc
