// subdivision_comparison.h — reference subdivision levels
// (reference/geometry/catmull_clark.h, loop_subdivision.h) against OpenSubdiv's
// (oracles/osd_subdivision.h), matched by parent component.
//
// Spec: 000 section 2.6 (Catmull/Clark with vertex and edge creases), 004
// (Loop), 001 (child numbering by parent).
//
// Rationale: one comparison, used by tests/oracles_subdivision and by the
// fuzz target fuzz_mesh_subdivision, so that the fuzzer checks exactly what
// the tests check. Plain types only (no OpenSubdiv header).
// Level by level: vertex, face and edge counts equal; the child of a parent
// vertex, of a parent edge, of a parent face (Catmull-Clark: face_points)
// is mapped to OpenSubdiv's; every child face of a parent face equals one of
// OpenSubdiv's GetFaceChildFaces up to rotation; edges are matched through
// the faces using them (corner k of a face to the corresponding corner of
// OpenSubdiv's face, GetFaceEdges), never by vertex pair, since two edges
// may join the same two vertices (a Loop "pillow"), and the edge map must
// be one to one; the vertex map is a bijection; positions agree within
// `tolerance` (absolute, max norm); vertex and edge sharpness are equal;
// hole flags are equal.
#pragma once

#include <string>
#include <vector>

#include "catmull_clark.h"
#include "osd_subdivision.h"

namespace vgc {

// The first disagreement as text, or "" if every level agrees. `osd` not ok
// is a disagreement ("oracle failed: ..."). Precondition: both start from
// the same mesh (level 0 numbered alike). Never throws except bad_alloc.
std::string compare_subdivision_by_parent(const std::vector<SubdivisionLevel>& reference, const OsdResult& osd,
                                          double tolerance, bool face_points);

}  // namespace vgc
