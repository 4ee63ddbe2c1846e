// capability_checks.h — the checks of the optional capabilities
// (conformance/capability.h) against the oracles: ?classify against CGAL
// (oracles/cgal_manifold.h), ?subdivide against OpenSubdiv
// (oracles/osd_subdivision.h).
//
// Spec: clauses MESH-CLASSIFY-1 and SUBD-CATMARK-1 (group "derived");
// docs/adapters.md "Optional capabilities" defines the documents.
//
// Rationale: the conformance layer cannot depend on the oracles, so this
// file registers its checks with the runner (register_capability_checks).
// It includes no CGAL or OpenSubdiv header: only the plain-typed oracle
// headers. The oracles are asked about the same mesh the reference
// extracts (reference/mesh_arrays.h extract_mesh), with the options the
// reference's Catmull-Clark uses (uniform creasing, edge-only boundaries,
// crease_sharpness.h).
#pragma once

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
// 1e-9 * max(1, largest coordinate magnitude). Only where the polygons
// form a polygon mesh (reference mesh_topology.h) and OpenSubdiv refines
// them. Precondition: as check_classify. Never throws.
std::optional<Finding> check_subdivision(const Node& model, Implementation& sut, int level);

// Registers both checks ("manifold", "subdivision") with the runner.
void register_capability_checks();

}  // namespace vgc
