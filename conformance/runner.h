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

#include "check_step.h"
#include "clause.h"
#include "clause_selection.h"
#include "implementation.h"
#include "program.h"
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

// Replays `program` from a fresh node, then repeats its capability request
// if it has one, as certify checks it: the first finding, if any, and the
// index of the command it was found on (-1 for the fresh-node check,
// commands.size() for the capability request). A request that cannot be
// judged (sut does not claim the capability, no check is registered for
// it, or the check's oracle cannot be asked about this state:
// FindingStatus::NotJudged) is no finding: `not_judged` says why, naming
// the clause(s). Never
// throws for anything the implementation does.
struct ReplayResult {
  std::optional<Finding> failure;
  int failed_at = -1;
  std::vector<Finding> notes;
  std::string not_judged;  // empty, or why program.request could not be judged
  // Other failures the program's end shows besides `failure` (the late
  // view's: a document difference and a subscription kept in two formats;
  // certify reports whichever its tolerated clauses leave first).
  std::vector<Finding> also_failed;
};
ReplayResult replay_program(const Program& program, Implementation& sut);

// The clause ids the properties of `capability` declare, comma-separated
// ("SUBD-CATMARK-1"); empty for a capability no property checks.
std::string capability_clauses(const std::string& capability);

// Runs `check` as `request` says (check_drawn with the drawn value for a
// check that draws), recording the last capability request and its answer
// into the finding (Finding::shown_by, observed_document) when the check
// did not: what report.html draws a capability finding from.
struct CapabilityCheck;
std::optional<Finding> run_capability_check(const CapabilityCheck& check, const Node& model, Implementation& sut,
                                            const CapabilityRequest& request);

}  // namespace vgc
