// topology_comparison.h — the reference's connectivity answers
// (reference/geometry/mesh_topology.h) against CGAL's (oracles/cgal_manifold.h),
// field by field for every question both answer.
//
// Spec: 002 (manifold rules), 000 section 2.6 (consistent front side).
//
// Rationale: one comparison, used by tests/oracles_manifold and by the
// fuzz target fuzz_mesh_manifold, so that the fuzzer checks exactly what
// the tests check. Plain types only (no CGAL header).
// What is compared, and where CGAL can only answer for some inputs:
//  - status and bad_face always; nothing else unless status == Ok;
//  - is_polygon_mesh == is_polygon_soup_a_polygon_mesh; the non-manifold
//    edges with their use counts;
//  - every reference non-manifold vertex is singular for CGAL; when the
//    mesh is orientable, the two sets and the fan / link counts are equal
//    (CGAL also cuts orientation-conflict edges, so for non-orientable
//    input its set may be larger);
//  - orientable and consistently_oriented;
//  - when CGAL built a mesh that matches the input (no point duplicated;
//    required for a manifold orientable input): the counts, Euler
//    characteristic, boundary edges, half-disc vs border vertices, closed,
//    is_valid_polygon_mesh vs no isolated vertex, boundary loops (compared
//    undirected where CGAL reversed faces), components and per-face
//    component numbers.
#pragma once

#include <string>

#include "cgal_manifold.h"
#include "mesh_topology.h"

namespace vgc {

// The first disagreement between `reference` and `cgal` as text, or "" if
// none. Precondition: both describe the same MeshArrays. Never throws
// except bad_alloc.
std::string compare_topology_with_cgal(const MeshTopology& reference, const CgalManifoldReport& cgal);

}  // namespace vgc
