// loop_subdivision.h — uniform Loop subdivision of an all-triangle mesh,
// with the same creases and boundaries as catmull_clark.h.
//
// Spec: 004 (the MeshEd triangle tree: each triangle has four children,
// T0 in the centre; named as in triangle_tree.h); 000 2.6.2 creases (via
// crease_sharpness.h). The spec's primitive is Catmull-Clark; Loop is the
// triangle scheme of spec 004 and of OpenSubdiv's SCHEME_LOOP.
//
// Rationale: the rules are OpenSubdiv's Sdc Loop rules with CREASE_UNIFORM
// creasing and VTX_BOUNDARY_EDGE_ONLY boundaries, so the result is checked
// against OpenSubdiv by parent component:
//   edge point   = smooth: 3/8 (a + b) + 1/8 (each opposite vertex);
//                  sharpness >= 1: (a + b)/2; 0 < s < 1: s*sharp + (1-s)*smooth;
//   vertex point = smooth/dart: (1 - n*beta) v + beta * sum(neighbours), with
//                  Loop's beta = (5/8 - (3/8 + 1/4 cos(2 pi/n))^2) / n
//                  (1/16 for n = 6);
//                  crease: 3/4 v + 1/8 (each sharp neighbour); corner: v;
//                  rule changes blended as in catmull_clark.h.
// There are no face points (SubdivisionLevel::child_of_parent_face stays empty).
#pragma once

#include <vector>

#include "catmull_clark.h"

namespace vgc {

// Deliberately wrong rules, for tests that show the oracle comparison can
// fail. All false in real use.
struct LoopFaults {
  bool warren_weights = false;       // Warren's beta = 3/(8n) (3/16 for n = 3) instead of Loop's
  bool no_fractional_blend = false;  // sharpness < 1 acts as smooth
  bool no_non_manifold_rule = false;   // non-manifold vertices and same-direction edges left smooth
  bool edges_by_vertex_pair = false;   // child edges merged by vertex pair (the rule before issue 11)
};

// One uniform Loop step. Child numbering: the child of parent vertex v is v,
// then one edge point per parent edge in edge order. Each parent triangle
// has 4 consecutive child triangles T0..T3 (triangle_tree.h): T0 =
// [s0 s1 s2], T(j+1) = [vj' s(j+2) s(j+1)] (indices mod 3), where sk is the
// edge point of the edge opposite corner k; every child keeps the parent's
// orientation. Child edges come from the parent's topology, as
// OpenSubdiv's Vtr::TriRefinement builds them, never from vertex pairs:
// edge 2e and 2e + 1 are the halves of parent edge e (at its first and
// second vertex), then three per parent face f, 2 * ne + 3f + j joining
// s(j+1) and s(j+2). So two triangles on the same three vertices (a closed
// "pillow") keep distinct child edges although their T0s share vertices.
// Precondition: every face of `parent` is a triangle
// (else returns an empty level).
SubdivisionLevel refine_loop(const SubdivisionLevel& parent, const LoopFaults& faults = {});

// Levels 0..levels. Precondition: as build_base_level, all faces triangles,
// 0 <= levels <= 6; failure: an empty vector.
std::vector<SubdivisionLevel> subdivide_loop(const MeshArrays& mesh, int levels, const LoopFaults& faults = {});

}  // namespace vgc
