// run_result.h — what a certification run found, per property and per
// clause, as the runner, the mesh path and `vgc merge` produce it and every
// report writer reads it.
//
// Spec: the clause catalog (clause.h) and its statuses (docs/certify.md
// "Statuses"); the properties (property.h).
//
// Rationale: vocabulary at the bottom (issue 29). The report writers,
// `vgc merge`, `vgc result` and the mesh path read a run without including
// the runner that makes it; a run's data is plain (RunSettings has no
// callbacks: those stay in runner.h's RunOptions). A clause's status and
// the run's verdict are decided in one place (clause_status.h).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "clause.h"
#include "costly_class.h"
#include "finding.h"
#include "program.h"

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

// What a run was asked to do, as its report keeps it: plain data (the
// report writers and `vgc merge` read it; no callbacks).
struct RunSettings {
  std::uint64_t seed = 1;
  int cases = 100;               // cases per property
  int max_size = 40;             // RapidCheck size: command sequences grow up to about this length
  double budget_seconds = 120;   // CPU seconds of vgc and the implementation (run_budget.h), wall guard 10x
  std::string clause_glob = "*"; // which clauses (fnmatch pattern, comma-separated alternatives)
  int shard_index = 0;           // this run's shard, 0-based
  int shard_count = 1;
  // Clauses tolerated from the first case (a baseline's known deviations):
  // a case whose first divergence is one of them is set aside, so the rest
  // of the catalog is judged in full.
  std::set<std::string> tolerated;
};

// A clause's status (docs/certify.md "Statuses"): decided in one place
// (clause_status.h, decide_clause_status), written by every report as its
// name, read back by `vgc merge` and `vgc result`. A switch over it is
// checked by the compiler for a forgotten status.
enum class ClauseStatus { Pass, Fail, Crash, Timeout, Unchecked, NotClaimed, NotApplicable, Skipped };
const char* clause_status_name(ClauseStatus s);  // "pass", "fail", "crash", "timeout", "unchecked", ...
std::optional<ClauseStatus> clause_status_named(std::string_view name);  // the inverse
ClauseStatus clause_status_of(FindingStatus s);  // a finding's kind as the clause's status (fail, crash, timeout)
bool is_deviation(ClauseStatus s);               // fail, crash or timeout: a finding stands

// A property's status: it ran all its cases and found nothing (Pass) or
// found deviations (Fail); it did not run all of them (Stopped: the
// budget, set-aside cases dominated, RapidCheck gave up, a cancel); it did
// not run at all (Skipped, PropertySkip says why).
enum class PropertyStatus { Pass, Fail, Stopped, Skipped };
const char* property_status_name(PropertyStatus s);  // "pass", "fail", "stopped", "skipped"
std::optional<PropertyStatus> property_status_named(std::string_view name);

// The names, for a log line or a test's message (GoogleTest prints them so).
std::ostream& operator<<(std::ostream& out, ClauseStatus s);
std::ostream& operator<<(std::ostream& out, PropertyStatus s);

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
  // Pass, Fail, Stopped (`note` says why), Skipped (`skip` and `note` say
  // why: not selected, another shard, capability not claimed, no oracle, or
  // the implementation could not be read at all).
  PropertyStatus status = PropertyStatus::Skipped;
  std::string note;         // why skipped / stopped
  std::uint64_t seed = 0;
  int cases = 0;            // cases run to the end: judged + set aside + not judged
  int cases_target = 0;     // cases it should run
  int judged = 0;           // cases judged to the end (their tolerated commands taken out)
  long steps_taken_out = 0; // commands taken out of cases for a tolerated divergence (property_case.cpp take_step_out)
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
  ClauseStatus status = ClauseStatus::Unchecked;
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
  // The clause's other findings: of the kind of the one shown but another
  // difference (Finding::difference: a late subscriber shown another value
  // by another behaviour), each with its own counterexample, program and
  // property, in the order found. Each is a ClauseOutcome of the clause
  // with `part` 1, 2, ... (its counterexample file is "<id>.<part+1>.vgc")
  // and no other findings of its own; the clause's status is the shown
  // finding's.
  std::vector<ClauseOutcome> other_findings;
  int part = 0;
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
  RunSettings options;  // what the run was asked (RunOptions without its callbacks)
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
  bool complete = false;    // every selected clause was judged (none unchecked, no property stopped)
  // "SIGTERM", "SIGINT": the run was cancelled (cancel.h) and stopped early;
  // its verdict is "incomplete" whatever it found. Empty otherwise.
  std::string cancelled_by;
  double seconds = 0;
};

}  // namespace vgc
