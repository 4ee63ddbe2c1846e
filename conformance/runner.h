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
// time; a property it cuts short is reported as incomplete, never as a pass.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "check_step.h"
#include "clause.h"
#include "implementation.h"

namespace vgc {

struct RunProgress {
  std::string property;
  int property_index = 0;
  int property_count = 0;
  int cases_done = 0;
  int cases_total = 0;
  bool shrinking = false;
  int failures = 0;
  double elapsed_seconds = 0;
};

struct RunOptions {
  std::uint64_t seed = 1;
  int cases = 100;               // cases per property
  int max_size = 40;             // RapidCheck size: command sequences grow up to about this length
  double budget_seconds = 120;   // wall time for the whole run
  std::string clause_glob = "*"; // which clauses (fnmatch pattern, comma-separated alternatives)
  int shard_index = 0;           // this run's shard, 0-based
  int shard_count = 1;
  std::function<void(const RunProgress&)> progress;  // called often; may be empty
};

// A check of an optional capability (capability.h) to repeat after a
// program's commands: the registered check for `capability`, with the
// variant the case chose (1..3, e.g. the subdivision level) and, for a
// check that draws more (CapabilityCheck::check_drawn, e.g. the edit of
// "edits"), the value drawn (absent: 0).
struct CapabilityRequest {
  std::string capability;  // "manifold", "subdivision", ... (a registry name)
  int variant = 1;
  std::optional<std::uint32_t> draw;
};

struct Program {
  std::vector<Command> commands;  // from a fresh node
  // Set when the finding is a capability check's: it is shown by that check
  // on the state after the commands, not by a command.
  std::optional<CapabilityRequest> request;
};

struct PropertyOutcome {
  std::string id;
  std::string status;       // "pass", "fail", "crash", "timeout", "skipped", "incomplete"
  std::string note;         // why skipped / incomplete
  std::uint64_t seed = 0;
  int cases = 0;
  double seconds = 0;
  std::optional<Finding> finding;  // for fail / crash / timeout
  Program program;                 // the shrunk counterexample
  std::vector<std::pair<Finding, Program>> notes;  // SHOULD-level findings, one per clause
};

struct ClauseOutcome {
  const Clause* clause = nullptr;
  // "pass", "fail", "crash", "timeout", "skipped", or "not-claimed" (an
  // optional capability the implementation does not claim: neither a
  // failure nor a gap in completeness)
  std::string status;
  std::string note;
  std::vector<std::string> properties;  // that declare it and ran
  std::string found_by;     // property that found the failure
  std::uint64_t seed = 0;
  std::optional<Finding> finding;
  Program program;
};

struct RunResult {
  std::string implementation;
  RunOptions options;
  std::vector<PropertyOutcome> properties;
  std::vector<ClauseOutcome> clauses;  // catalog order; selected clauses and any clause with a finding
  bool conformant = false;  // no MUST / IMPLEMENTATION-DEFINED clause failed, crashed or timed out
  bool complete = false;    // every selected clause was checked (nothing skipped or incomplete)
  double seconds = 0;
};

// Runs the selected properties. Never throws for anything the
// implementation does.
RunResult run_certification(Implementation& sut, const RunOptions& options);

// True when `id` matches the comma-separated fnmatch patterns in `glob`.
bool clause_selected(const std::string& glob, std::string_view id);

// The seed a property runs with (the run's seed mixed with the property id).
std::uint64_t property_seed(std::uint64_t run_seed, std::string_view property_id);

// Replays `program` from a fresh node, then repeats its capability request
// if it has one, as certify checks it: the first finding, if any, and the
// index of the command it was found on (-1 for the fresh-node check,
// commands.size() for the capability request). A request that cannot be
// judged (sut does not claim the capability, or no check is registered for
// it) is no finding: `not_judged` says why, naming the clause(s). Never
// throws for anything the implementation does.
struct ReplayResult {
  std::optional<Finding> failure;
  int failed_at = -1;
  std::vector<Finding> notes;
  std::string not_judged;  // empty, or why program.request could not be judged
};
ReplayResult replay_program(const Program& program, Implementation& sut);

// The clause ids the properties of `capability` declare, comma-separated
// ("SUBD-CATMARK-1"); empty for a capability no property checks.
std::string capability_clauses(const std::string& capability);

}  // namespace vgc
