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
#include "costly_class.h"
#include "implementation.h"

namespace vgc {

struct RunProgress {
  std::string property;
  int property_index = 0;
  int property_count = 0;
  int cases_done = 0;
  int cases_total = 0;
  bool shrinking = false;
  int failures = 0;     // findings so far in this property
  int set_aside = 0;    // cases set aside so far in this property
  double elapsed_seconds = 0;
};

struct PropertyOutcome;

struct RunOptions {
  std::uint64_t seed = 1;
  int cases = 100;               // cases per property
  int max_size = 40;             // RapidCheck size: command sequences grow up to about this length
  double budget_seconds = 120;   // wall time for the whole run
  std::string clause_glob = "*"; // which clauses (fnmatch pattern, comma-separated alternatives)
  int shard_index = 0;           // this run's shard, 0-based
  int shard_count = 1;
  // Clauses tolerated from the first case (a baseline's known deviations):
  // a case whose first divergence is one of them is set aside, so the rest
  // of the catalog is judged in full.
  std::set<std::string> tolerated;
  std::function<void(const RunProgress&)> progress;  // called often; may be empty
  // Called once per property that ran, when it has finished (a log line per
  // property for CI); may be empty.
  std::function<void(const PropertyOutcome&, const RunProgress&)> property_done;
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
  Program() = default;
  Program(std::vector<Command> c, std::optional<CapabilityRequest> r = std::nullopt)
      : commands(std::move(c)), request(std::move(r)) {}

  std::vector<Command> commands;  // from a fresh node
  // Set when the finding is a capability check's: it is shown by that check
  // on the state after the commands, not by a command.
  std::optional<CapabilityRequest> request;
  // Set when the program reproduces a finding that depends on the
  // implementation's history (confirm_finding.h): the kind of failure it
  // brings about ("crash", "timeout", "protocol-error", "wrong-answer").
  // `vgc replay` then blames what it shows as certify did: on STABLE-1
  // (ACCEPT-1 for a protocol error), not on the command it came on.
  std::string history_kind;
};

// One deviation a property showed: the finding and its counterexample.
// A new deviation is shrunk (RapidCheck) to the shortest program whose
// first divergence is in that clause; a tolerated one (known from the
// baseline) keeps the shortest program it was seen on, unshrunk.
struct PropertyFinding {
  Finding finding;
  Program program;
  bool tolerated_from_start = false;  // a baseline clause: seen, not shrunk
  int round = 0;                      // 0: the property's own seed; r: its r-th re-run past findings
};

// Why a property did not run (PropertyOutcome::status "skipped", or
// "stopped" before any case for Preflight). What it means for the clauses
// it declares is decided in clause_status.cpp: a property in another shard
// says nothing about them here; one the route cannot run (at scale on the
// Verse wire) makes them not judgeable on this route unless another
// declaring property runs; not claimed is the implementation's choice;
// anything else leaves them unchecked.
enum class PropertySkip { None, NotSelected, OtherShard, NotOnRoute, NotClaimed, NoOracle, Preflight };
const char* property_skip_name(PropertySkip s);  // "none", "not-selected", "other-shard", ... (report.json)
PropertySkip property_skip_named(const std::string& name);  // the inverse; None for an unknown name

struct PropertyOutcome {
  std::string id;
  PropertySkip skip = PropertySkip::None;
  // "pass" (ran all its cases, no finding), "fail" (ran all its cases and
  // found deviations), "stopped" (did not run all its cases: the budget ran
  // out, set-aside cases dominated, or RapidCheck gave up; `note` says
  // which), "skipped" (not run: not selected, another shard, capability not
  // claimed, no oracle, or the implementation could not be read at all).
  std::string status;
  std::string note;         // why skipped / stopped
  std::uint64_t seed = 0;
  int cases = 0;            // cases run to the end: judged + set aside + not judged
  int cases_target = 0;     // cases it should run
  int judged = 0;           // cases judged to the end (their tolerated commands taken out)
  long steps_taken_out = 0; // commands taken out of cases for a tolerated divergence (runner.cpp take_step_out)
  int set_aside = 0;        // cases whose first divergence was a tolerated clause
  int not_judged = 0;       // capability cases the oracle could not judge (FindingStatus::NotJudged)
  int rounds = 0;           // RapidCheck runs (1 + one per new finding)
  double seconds = 0;
  std::vector<PropertyFinding> findings;  // in the order found
  std::map<std::string, long> exercised;  // clause id -> judged steps of this property that decided it
  // clause id -> judged steps that only the derived document would have
  // decided it on, for a route that carries none (RouteLimits::derived)
  std::map<std::string, long> derived_only;
  std::vector<std::pair<Finding, Program>> notes;  // SHOULD-level findings, one per clause
};

struct ClauseOutcome {
  const Clause* clause = nullptr;
  // "pass"           every property that declares it ran all its cases, none
  //                  found a deviation in it, and at least one judged step
  //                  exercised it;
  // "fail", "crash", "timeout"  a deviation (any level; the verdict decides
  //                  what gates: verdict.h);
  // "unchecked"      not enough was judged to call it either (`note` says why:
  //                  a declaring property stopped, or nothing exercised it);
  // "not-claimed"    an optional capability the implementation does not claim;
  // "not-applicable" nothing in the run could judge it for this
  //                  implementation (REASON-1 when it reports no verdicts),
  //                  or the route cannot show it (Implementation::limits:
  //                  a clause the route names, or one only the derived
  //                  document decides on a route that carries none); the
  //                  note names the route and says why;
  // "skipped"        in another shard.
  std::string status;
  std::string note;
  std::vector<std::string> properties;  // that declare it and ran
  long exercised = 0;       // judged steps (or capability checks) that decided it
  // The rest of the evidence its status was decided from (clause_status.h),
  // kept so that `vgc merge` decides merged shards as one run would.
  long derived_only = 0;    // steps only the derived document, which the route lacks, would have decided it on
  std::string route_limit;  // non-empty: the route cannot judge it, why
  std::string found_by;     // property that found the failure
  std::uint64_t seed = 0;
  std::optional<Finding> finding;
  Program program;
  bool tolerated_from_start = false;  // the finding is a baseline clause's, seen not shrunk
  // What the program is when it was not drawn and shrunk by a property (a
  // user's mesh, certify --mesh): the heading summary.md and report.html
  // give it. Empty: shrunk, or tolerated_from_start.
  std::string program_origin;
};

// Per command kind ("polygon_set_face_uint8"): how often judged steps sent
// it, and what the reference's verdict on it was (the implementation agreed,
// or the step would be a finding). Counted outside shrinking.
struct CommandKindCount {
  long sent = 0;
  long applied = 0;
  std::map<std::string, long> rejected;  // reason name -> count
};

struct RunResult {
  std::string implementation;
  RunOptions options;
  std::vector<PropertyOutcome> properties;  // property catalog order
  std::vector<ClauseOutcome> clauses;  // catalog order; selected clauses and any clause with a finding
  std::map<std::string, CommandKindCount> command_kinds;
  // Rule name (reference/node/rule.h) -> judged uses: judged steps whose
  // reference trace applied the rule, and fresh-node checks for the fresh
  // node's rules. Counted outside shrinking; every rule is listed, 0 when
  // unused. The measure of the generators' reach (issue 17 item 3).
  std::map<std::string, long> rule_uses;
  long unreported_verdicts = 0;  // steps the implementation answered `done` to
  // Classes of input that cost a time-out and were not drawn again
  // (costly_class.h): one line each, what and where it was found.
  std::vector<std::string> avoided_classes;
  std::vector<CostlyClass> avoided;
  std::string route;  // RouteLimits::route of the implementation: empty, or the route whose limits apply
  // Set when the implementation could not even show a fresh node (it
  // crashed, hung, or answered what the contract does not allow): no
  // property ran, every other clause is unchecked.
  std::optional<Finding> preflight;
  bool conformant = false;  // no MUST clause failed, crashed or timed out (before any baseline)
  bool complete = false;    // every selected clause was judged (none unchecked, no property stopped)
  // "SIGTERM", "SIGINT": the run was cancelled (cancel.h) and stopped early;
  // its verdict is "incomplete" whatever it found. Empty otherwise.
  std::string cancelled_by;
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
