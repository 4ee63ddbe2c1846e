// capability_run.h — running an optional capability's check as a request
// says, and the clauses a capability's properties declare.
//
// Spec: the capabilities' clauses (capability.h): MESH-CLASSIFY-1,
// SUBD-CATMARK-1, NORMALS-SPLIT-1, LOOP-TRIANGLE-1, EDIT-HIERARCHY-1.
//
// Rationale: a certify case (property_case.h), a replay (replay_program.h)
// and the mesh path (mesh_certification.h) judge a capability request the
// same way, and a finding carries what the implementation was asked and
// answered (report.html draws a capability finding from it).
#pragma once

#include <optional>
#include <string>

#include "capability.h"
#include "finding.h"
#include "implementation.h"
#include "node.h"
#include "program.h"

namespace vgc {

// The clause ids the properties of `capability` declare, comma-separated
// ("SUBD-CATMARK-1"); empty for a capability no property checks.
std::string capability_clauses(const std::string& capability);

// Runs `check` as `request` says (check_drawn with the drawn value for a
// check that draws), recording the last capability request and its answer
// into the finding (Finding::shown_by, observed_document) when the check
// did not: what report.html draws a capability finding from.
std::optional<Finding> run_capability_check(const CapabilityCheck& check, const Node& model, Implementation& sut,
                                            const CapabilityRequest& request);

}  // namespace vgc
