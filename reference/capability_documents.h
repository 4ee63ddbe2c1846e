// capability_documents.h — the reference's answers to the optional
// capability requests of the exec protocol: ?capabilities, ?classify,
// ?subdivide <level> (docs/adapters.md "Optional capabilities").
//
// Spec: 002 (manifold rules; clause MESH-CLASSIFY-1), 000 section 2.6
// (Catmull/Clark subdivision with creases; clause SUBD-CATMARK-1).
//
// Rationale: one text form for the in-process reference, `vgc serve`, the
// reference plugin and the seeded faults, computed only with the reference
// modules (mesh_topology.h, catmull_clark.h). Standard library only.
#pragma once

#include <optional>
#include <string>

#include "node.h"

namespace vgc {

// Options that make the documents deliberately wrong (seeded faults only).
struct CapabilityDocumentFaults {
  bool ignore_creases = false;        // ?subdivide as if every crease were 0
  bool zero_boundary_loops = false;   // ?classify says boundary_loops 0
};

// "capabilities manifold subdivision\nend\n".
std::string print_capabilities();

// The ?classify document of `node`'s live polygons (classify_mesh of
// extract_mesh): "vgc-classify 1", "polygon_mesh yes|no" and, when yes,
// closed, oriented (consistently oriented), euler (V - E + F, V without
// isolated vertices), components, boundary_loops; then "end".
std::string print_classify(const Node& node, const CapabilityDocumentFaults& faults = {});

// The ?subdivide document: "vgc-subdivision 1", "level N", one
// "vertex x y z" per vertex of the Catmull-Clark refinement at level N of
// the polygons (vertices in no polygon left out), "faces <count>", "end".
// Precondition: 1 <= level <= 3 (else an "error ..." line is returned).
std::string print_subdivision(const Node& node, int level, const CapabilityDocumentFaults& faults = {});

// Answers one request line of the three above; nullopt for any other line.
// A malformed ?subdivide gives "error <message>\n".
std::optional<std::string> answer_capability_request(const Node& node, const std::string& line,
                                                     const CapabilityDocumentFaults& faults = {});

}  // namespace vgc
