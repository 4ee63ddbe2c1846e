// attribution.h — which clause a divergence from the reference breaks.
//
// Spec: the clause catalog (clause.h), which cites 000 section 2.6.
//
// Rationale: a differential check knows *that* an implementation differs
// from the reference after a command; a person needs to know *which rule*
// it broke. These functions answer that from the command, the reference's
// verdict on it and the state before it, by the same rules node.cpp
// applies. Each returns a clause id that exists in the catalog (a test
// checks this for every command kind and reason).
#pragma once

#include <string>
#include <string_view>

#include "command.h"
#include "document_diff.h"
#include "node.h"
#include "reason.h"

namespace vgc {

// The reference rejected `c` with `why`; the implementation applied it.
std::string_view clause_for_rejection(const Command& c, Reason why, const Node& before);

// The reference applied `c`; the implementation rejected it (or crashed,
// or timed out on it).
std::string_view clause_for_acceptance(const Command& c, const Node& before);

// Both applied `c` but the implementation's snapshot differs from the
// reference's at a line whose first word is `line_kind` ("layer", "slot",
// "vertex", "polygon", "crease_vertex", "crease_edge", "bone", ...).
// `missing_or_extra` is true when a line is absent on one side rather than
// changed.
std::string_view clause_for_snapshot(const Command& c, const Node& before, const Node& after,
                                     std::string_view line_kind, bool missing_or_extra);

// The derived documents differ at a line of `line_kind` ("vertex_crease",
// "edge_crease", "bone_pose") in the state `after`; `bone_id` is the bone
// of a bone_pose line.
std::string_view clause_for_derived(const Node& after, std::string_view line_kind, long bone_id);

// The same from the whole difference `d` (kind d.kind): edge_crease lines
// that name different edges (or one side lacking the line) mean the two
// sides disagree on a polygon's corners (POLY-TRIANGLE-1: a fourth corner
// that is a vertex reference makes a quad), not on a crease.
std::string_view clause_for_derived(const Node& after, const DocumentDifference& d, long bone_id);

// The bone id of a derived document's "bone_pose <id> ..." line, or -1.
long bone_id_of(const std::string& line);

}  // namespace vgc
