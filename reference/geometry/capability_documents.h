// capability_documents.h — the reference's answers to the optional
// capability requests of the exec protocol: ?capabilities, ?classify,
// ?subdivide <level>, ?normals, ?subdivide-loop <level>, ?subdivide-edit
// <level> <edit> (docs/adapters.md "Optional capabilities").
//
// Spec: 002 (manifold rules; clause MESH-CLASSIFY-1), 000 section 2.6
// (Catmull/Clark subdivision with creases; clause SUBD-CATMARK-1), 003
// (split normals; clause NORMALS-SPLIT-1), 004 (Loop triangle tree; clause
// LOOP-TRIANGLE-1), 001 (hierarchical edits; clause EDIT-HIERARCHY-1).
//
// Rationale: one text form for the in-process reference, `vgc serve`, the
// reference plugin and the seeded faults, computed only with the reference
// modules (mesh_topology.h, catmull_clark.h, split_normals.h,
// loop_subdivision.h, hierarchical_edit.h). Standard library only.
#pragma once

#include <optional>
#include <string>

#include "node.h"

namespace vgc {

// Options that make the documents deliberately wrong (seeded faults only).
struct CapabilityDocumentFaults {
  bool ignore_creases = false;        // ?subdivide as if every crease were 0
  bool zero_boundary_loops = false;   // ?classify says boundary_loops 0
  bool flat_normals = false;          // ?normals gives every corner its face normal
  bool perturb_fan_normals = false;   // ?normals adds 1e-6 to x of every corner of a fan of 2+ corners
  bool negate_lone_corners = false;   // ?normals negates the normal of every one-corner fan
  bool loop_warren_weights = false;   // ?subdivide-loop with Warren's vertex weights (LoopFaults)
  bool loop_tree_rotated = false;     // ?subdivide-loop face lines start at their second vertex
  bool loop_answers_quads = false;    // ?subdivide-loop answers an empty document when a polygon is a quad
  bool edit_holes_ignored = false;    // ?subdivide-edit lists the faces of holes too
  bool edit_at_base_level = false;    // ?subdivide-edit applies the edit to the base polygon's vertex
  bool edit_hole_wrong_face = false;  // ?subdivide-edit holes the next sibling (or base polygon) instead
  bool edit_truncated_path = false;   // ?subdivide-edit applies a deeper edit at the asked level, path cut
  bool edit_add_zero_as_set = false;  // ?subdivide-edit treats "add" of (0, 0, 0) as "set" (to the origin)
  bool non_manifold_smooth = false;   // ?subdivide without the non-manifold rule (CatmullClarkFaults)
  bool loop_edges_by_vertex_pair = false;  // ?subdivide-loop merges child edges by vertex pair (LoopFaults)
};

// The document header a capability request is answered with
// ("capabilities", "vgc-classify", "vgc-subdivision", "vgc-normals"), or
// nullptr when `request_line` is no capability request (judged by its
// first word only).
const char* capability_document_header(const std::string& request_line);

// "capabilities manifold subdivision normals loop edits\nend\n".
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

// The ?normals document: "vgc-normals 1", then for every live polygon in
// ascending id order and each of its corners "corner <polygon id>
// <corner index> x y z", the corner's split normal (compute_split_normals
// of extract_mesh; numbers as in the snapshot), then "end". Failure: when
// the polygons cannot be given split normals (split status not Ok) the
// answer is one line "error ...".
std::string print_normals(const Node& node, const CapabilityDocumentFaults& faults = {});

// The ?subdivide-loop document (spec 004): as ?subdivide, for `level` uniform
// Loop steps (loop_subdivision.h), plus one "face a b c" line per refined
// triangle before "faces": indices into the vertex lines, in the triangle
// tree order of spec 004 (the children T0..T3 of each parent consecutively,
// parents in order; base triangles in polygon id order) and in each
// triangle's oriented order (T0 = [s0 s1 s2], T(j+1) = [vj' s(j+2) s(j+1)],
// vertex j and sub-vertex j named from the parent's own order).
// Failure: "error ..." when a live polygon is not a triangle or the level
// is not 1..3.
std::string print_loop_subdivision(const Node& node, int level, const CapabilityDocumentFaults& faults = {});

// The ?subdivide-edit document (spec 001 hierarchical edits): as
// ?subdivide for `level` Catmull-Clark steps (hierarchical_edit.h) with one
// edit applied, plus one "face a b c d" line per refined face that is not a
// hole (indices into the vertex lines, the level's order) before "faces",
// which counts those lines. `edit`: "hole (<polygon id> <child>...)" or
// "set|add (<polygon id> <child>... <vertex>) <x> <y> <z>": the path of
// spec 001 with the polygon's id in place of the base face index, at most
// 3 children (the edit's level). A level coarser than the edit's is the
// plain refinement. Failure: "error ..." for a malformed edit, a level
// outside 1..3, or a path that names no face or vertex.
std::string print_edit_subdivision(const Node& node, int level, const std::string& edit,
                                   const CapabilityDocumentFaults& faults = {});

// Answers one request line of the three above; nullopt for any other line.
// A malformed ?subdivide gives "error <message>\n".
std::optional<std::string> answer_capability_request(const Node& node, const std::string& line,
                                                     const CapabilityDocumentFaults& faults = {});

}  // namespace vgc
