// capability_checks.h — the checks of the optional capabilities
// (conformance/capability.h) against the oracles: ?classify against CGAL
// (oracles/cgal_manifold.h), ?subdivide against OpenSubdiv
// (oracles/osd_subdivision.h); ?normals against spec 003's properties and
// the reference (no external oracle for split normals is linked);
// ?subdivide-loop against OpenSubdiv's Loop scheme; ?subdivide-edit
// against OpenSubdiv (holes, unedited parts) and the reference.
//
// Spec: clauses MESH-CLASSIFY-1 and SUBD-CATMARK-1 (group "derived"),
// NORMALS-SPLIT-1 (group "normals"), LOOP-TRIANGLE-1 (group "loop"),
// EDIT-HIERARCHY-1 (group "edits");
// docs/adapters.md "Optional capabilities" defines the documents.
//
// Rationale: the conformance layer cannot depend on the oracles, so this
// file registers its checks with the runner (register_capability_checks).
// It includes no CGAL or OpenSubdiv header: only the plain-typed oracle
// headers. The oracles are asked about the same mesh the reference
// extracts (reference/geometry/mesh_arrays.h extract_mesh), with the options the
// reference's Catmull-Clark uses (uniform creasing, edge-only boundaries,
// crease_sharpness.h).
#pragma once

#include <cstdint>
#include <optional>

#include "capability.h"

namespace vgc {

// Compares sut's ?classify with cgal_classify_mesh(extract_mesh(model)):
// polygon_mesh always (when CGAL accepts the soup); closed, oriented,
// euler, components and boundary_loops when CGAL built a mesh that matches
// the input. A failed call, an "error" answer or a malformed document is a
// finding. Precondition: sut holds the state of `model`. Never throws.
std::optional<Finding> check_classify(const Node& model, Implementation& sut);

// Compares sut's ?subdivide <level> (1..3) with osd_refine_uniform of the
// model's polygons (vertices in no polygon left out): vertex and face
// counts, and the vertices as a bijection by nearest position within
// 1e-9 * max(1, largest coordinate magnitude). On every mesh a node can
// hold, non-manifold included (OpenSubdiv's non-manifold rules, which the
// reference follows: reference/geometry/catmull_clark.h); where OpenSubdiv refuses
// the polygons the result is a FindingStatus::NotJudged saying why, not a
// pass. Precondition: as check_classify. Never throws.
std::optional<Finding> check_subdivision(const Node& model, Implementation& sut, int level);

// Checks sut's ?normals (spec 003 split normals): one "corner" line per
// corner of every live polygon; then, independently of the reference,
// (a) the two corners at each end of a smooth edge (two polygons, opposite
// directions, no corner crease 0xFFFFFFFF) have one normal (so every smooth
// fan has one), (b) a corner whose two edges are both sharp has its
// polygon's unit front normal (Newell's, clockwise front, face_normals.h);
// then every corner against reference/geometry/split_normals.h (angle-weighted fan
// normals). All within 1e-9. Not compared when the reference cannot give
// the polygons split normals, or a polygon's vertex has a coordinate beyond
// 1e60 in magnitude. Precondition: as check_classify.
std::optional<Finding> check_normals(const Node& model, Implementation& sut);

// Compares sut's ?subdivide-loop <level> (1..3) with OpenSubdiv's Loop
// scheme on the model's polygons: counts and vertices as check_subdivision;
// then the face lines against the spec 004 triangle tree built on
// OpenSubdiv's levels (tree order, T0 the centre, each triangle in the
// oriented order of reference/geometry/loop_subdivision.h). When a live polygon is
// not a triangle the answer must be one "error" line. Compared on every
// all-triangle mesh, non-manifold included; NotJudged where OpenSubdiv
// refuses it. Precondition: as check_classify.
std::optional<Finding> check_loop(const Node& model, Implementation& sut, int level);

// Checks sut's ?subdivide-edit <level> <edit> (spec 001 hierarchical
// edits) on the model's polygons, with one edit of each kind (hole, set,
// add 0, add), each one's level 0..`level`, path and vertex chosen from
// `draw`; the first finding is returned.
// Oracle-backed (OpenSubdiv Catmark): a hole at level 0 against
// OpenSubdiv's holes (vertices, kept faces as vertex cycles); a deeper hole
// moves nothing and removes exactly its 4^(level - k) descendants, every
// face line being an OpenSubdiv face; add 0 changes nothing; the level just
// above the edit's (when it is >= 1) is the plain refinement; at the edit's
// own level exactly one vertex moves, and "set" puts it at the value
// (where coordinates are at most 1e6).
// Without an oracle: the vertices and kept-face count against the
// reference's hierarchical_edit.h. Compared on every mesh, non-manifold
// included; NotJudged where OpenSubdiv refuses it. Precondition: as
// check_classify.
std::optional<Finding> check_edits(const Node& model, Implementation& sut, int level, std::uint32_t draw);

// Registers the checks ("manifold", "subdivision", "normals", "loop",
// "edits") with the runner.
void register_capability_checks();

}  // namespace vgc
