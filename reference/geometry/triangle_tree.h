// triangle_tree.h — the MeshEd naming of the Loop triangle tree.
//
// Spec: 004 "MeshEd Basics", TTree ("TTree* children[4]; Vertex*
// vertices[3]"; "We have affectionate names for the children; we call them
// T0, T1, T2, and T3") and "Naming Conventions":
//   "Edges are named for their opposite vertex."
//   "Sub-triangles are named according to their nearest vertex, with T0 in
//    the center"
//   "Sub-vertices are named for their opposite vertex."
//   "The vertex numbers of the subtriangles are the same as the nearest
//    vertex or sub-vertex of the parent triangle."
//   "Note that orientation is not implied in the vertex naming"
//
// Decision: the diagram the text refers to is not part of the spec. A
// triangle's vertices are numbered 0, 1, 2 (TTree::vertices[3]); since T0 is
// the centre, the corner child nearest vertex i is T(i+1). Edge k and
// sub-vertex k are opposite vertex k: edge k joins vertices k+1 and k+2
// (mod 3), and sub-vertex k is the child vertex of edge k. By the last rule
// above, vertex slot k of every child is the parent vertex k (for the corner
// child of vertex k) or sub-vertex k (otherwise): T0 = (s0, s1, s2) and
// T(j+1) has vj at slot j and sk at the other slots k. As the spec warns,
// this naming does not keep orientation (the corner children's named order
// is reversed); the oriented faces are in SubdivisionLevel (loop_subdivision.h).
#pragma once

#include <array>

#include "catmull_clark.h"

namespace vgc {

inline constexpr int kCentreChild = 0;  // T0

// The corner child nearest parent vertex `vertex` (0..2): T(vertex+1).
// Precondition: 0 <= vertex < 3; failure: returns -1.
int corner_child_of_vertex(int vertex);
// The parent vertex child `child` is nearest: 0..2 for T1..T3, -1 for T0 or
// an invalid child.
int nearest_vertex_of_child(int child);
// The two vertices of edge `edge` (the edge opposite vertex `edge`).
// Precondition: 0 <= edge < 3; failure: {-1, -1}.
std::array<int, 2> edge_vertices(int edge);

// What a child's vertex slot names: parent vertex `index`, or sub-vertex `index`.
struct TreeCorner {
  bool sub_vertex = false;
  int index = -1;
};
// The names of the three vertex slots of child `child` (0..3).
// Precondition: 0 <= child < 4; failure: all {false, -1}.
std::array<TreeCorner, 3> child_corner_names(int child);

// On a parent level and its child made by refine_loop:
// the child-level face index of child `child` (0..3) of triangle
// `parent_face`; -1 if out of range.
int child_triangle(const SubdivisionLevel& child_level, int parent_face, int child);
// The child-level vertex of sub-vertex k (0..2) of triangle `parent_face`;
// -1 if out of range.
int sub_vertex(const SubdivisionLevel& parent, const SubdivisionLevel& child_level, int parent_face, int k);
// The child-level vertices of child `child` of `parent_face` in named slot
// order (child_corner_names); {-1,-1,-1} if out of range.
std::array<int, 3> named_child_vertices(const SubdivisionLevel& parent, const SubdivisionLevel& child_level,
                                        int parent_face, int child);

}  // namespace vgc
