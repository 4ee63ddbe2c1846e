// runner.h — runs the properties against an implementation and turns what
// they find into per-clause results.
//
// Spec: the clause catalog (clause.h) and the properties (property.h).
//
// Rationale: certification must be reproducible and must survive the
// implementation. Each property gets its own seed derived from the run's
// seed and its id, so adding a property or splitting a run into shards does
// not change another property's cases. A case that crashes or hangs the
// implementation is a finding like any other. The budget bounds the wall
// time; a property it cuts short is reported as stopped, never as a pass.
//
// A run lists every deviation it can show (issue 9). When a property finds
// a deviation in clause X, RapidCheck shrinks it, the counterexample is
// kept, and the property runs on for its remaining cases with X tolerated:
// a case whose first divergence is a tolerated clause is set aside
// (counted, not judged). Baseline clauses are tolerated from the first
// case. A property whose set-aside cases dominate stops; the clauses it
// declares are then `unchecked`, never `pass`. A clause is `pass` only when
// judged steps exercised it (exercised_clauses.h) and every property that
// declares it ran all its cases.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "capability_run.h"  // capability_clauses, run_capability_check: for the runner's callers
#include "check_step.h"
#include "clause.h"
#include "clause_selection.h"
#include "implementation.h"
#include "program.h"
#include "replay_program.h"  // replay_program: for the runner's callers
#include "run_result.h"

namespace vgc {

// The settings and what the caller wants to hear while the run goes on.
struct RunOptions : RunSettings {
  std::function<void(const RunProgress&)> progress;  // called often; may be empty
  // Called once per property that ran, when it has finished (a log line per
  // property for CI); may be empty.
  std::function<void(const PropertyOutcome&, const RunProgress&)> property_done;
};

// Runs the selected properties. Never throws for anything the
// implementation does.
RunResult run_certification(Implementation& sut, const RunOptions& options);

// The seed a property runs with (the run's seed mixed with the property id).
std::uint64_t property_seed(std::uint64_t run_seed, std::string_view property_id);

}  // namespace vgc
