// finding_cause.h — findings of several clauses that one cause explains, for
// the reports to show together with the cause said once (issue 27 item 5:
// "findings with one cause are grouped in the report").
//
// Spec: clauses VERTEX-SET-1, POLY-TRIANGLE-1 and ID-BOUND-1 (one storage
// bound of the r6 host is a finding of each), POLY-DELETE-1 and
// LAYER-STACK-1 (r6's grown polygon storage, whose unused ids are live
// polygons, is a finding of each), and every clause whose finding is a
// command the implementation took and dropped.
//
// Rationale: the criterion is sound only where the shrunk counterexamples
// show one behaviour, so it is narrow. Two findings share a cause when the
// last command of each counterexample (where it differed) was answered as
// a success and stored nothing ("dropped", or the model's line missing
// after it), and either (a) the two commands are of the same kind, or (b)
// both create a vertex or polygon at an id of 4,096 or more (a storage
// bound: r6 drops ids more than 4,096 past its storage). A wrong verdict
// on a refused command is not grouped: two clauses refused for two
// reasons (LAYER-BASE-2's base id, LAYER-NAME-1's name) are two checks the
// implementation lacks, even on the same command kind. A second key: the
// difference is at a polygon id of 32 or more that was never live while
// the counterexample ran on the reference, though a polygon at 32 or more
// was (the delete of it applied, a slot or a polygon line for it): the
// implementation took an id its storage grew by for a live polygon (r6
// fills grown polygon storage with corners 0, not its unused marker).
// Both shapes show on the wire and through an exec wrapper alike. Statuses
// are unchanged: grouping is only how the reports show them.
#pragma once

#include <string>
#include <vector>

#include "run_result.h"

namespace vgc {

struct CauseGroup {
  std::string cause;                  // one sentence, said once for the group
  std::vector<std::string> clauses;   // two or more clause ids, in catalog order
};

// The groups of two or more findings in `run` that share a cause.
std::vector<CauseGroup> group_findings_by_cause(const RunResult& run);

// The group `clause_id` is in, or nullptr.
const CauseGroup* cause_group_of(const std::vector<CauseGroup>& groups, const std::string& clause_id);

}  // namespace vgc
