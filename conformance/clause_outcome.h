// clause_outcome.h — a run's per-clause outcome: the finding chosen for
// each clause from every property that ran, and its status.
//
// Spec: the clause catalog (clause.h) and its statuses (docs/certify.md
// "Clause statuses").
//
// Rationale: the finding shown for a clause is the worst kind, the shortest
// program, whichever property found it (prefer_finding); its status is
// decided from the evidence by one function (clause_status.h), the same in
// one run and in `vgc merge`.
#pragma once

#include "implementation.h"
#include "run_result.h"

namespace vgc {

// Per clause: the findings of every property that ran, whoever declared
// it, and the evidence clause_status.h decides its status from; appended to
// run->clauses, in catalog order.
void decide_clauses(const RunSettings& o, const RouteLimits& limits, RunResult* run);

}  // namespace vgc
