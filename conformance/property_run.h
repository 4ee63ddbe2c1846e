// property_run.h — one property's run: rounds of RapidCheck over its cases
// until they are done, each finding confirmed, shrunk and then tolerated,
// and the property's outcome.
//
// Spec: the clauses the property declares (property.h); docs/certify.md
// "How a run proceeds past findings".
//
// Rationale: a run lists every deviation it can show (runner.h). A round
// ends at its first finding (RapidCheck shrinks it); the next round runs
// the cases left with that clause tolerated, so there is at most one round
// per catalog clause. The cases themselves are property_case.h's.
#pragma once

#include "implementation.h"
#include "property.h"
#include "property_case.h"
#include "run_result.h"
#include "runner.h"

namespace vgc {

// Runs property `spec` against `sut`: its cases in this shard, its findings
// (each confirmed on a fresh instance), its tolerated divergences and its
// status. `run` holds what earlier properties found and the run-wide
// tallies this property adds to; `progress` is reported as cases finish.
PropertyOutcome run_property(const PropertySpec& spec, Implementation& sut, const RunOptions& o,
                             Clock::time_point deadline, RunProgress* progress, Clock::time_point run_start,
                             RunResult* run);

}  // namespace vgc
