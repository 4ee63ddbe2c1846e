// clause_status.h — the one place where a clause's status, and a run's
// completeness and conformance, are decided from the judged evidence.
//
// Spec: the clause catalog's levels (clause.h); docs/certify.md "Statuses".
//
// Rationale: a CI gate is trusted when its verdict depends on the
// implementation and on nothing else. Before this file the status ladder
// was written twice (run_certification and vgc merge), and parts of it
// read what the cases happened to draw: a clause only the derived document
// decides was `not-applicable` on the Verse wire when a case reached it
// and `unchecked` when none did, and a property the route cannot run made
// its clauses `unchecked` in whichever shard it landed. Now:
//   - the evidence for a clause is gathered (gather_clause_evidence) from
//     the property outcomes, the summed exercised counts and the route's
//     static limits, the same way for one run and for merged shards, so a
//     merged run decides exactly as the unsharded run;
//   - decide_clause_status is a ladder of named steps, first match wins;
//   - what the route cannot judge is decided from the route alone
//     (route_limit_of), never from the cases.
// Statuses: ClauseStatus (run_result.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "clause.h"
#include "implementation.h"
#include "run_result.h"

namespace vgc {

struct ClauseEvidence {
  bool selected = true;              // --clauses matched it
  bool shard_part = false;           // one shard of several: merge decides what no case of it reached
  std::optional<Finding> finding;    // the chosen finding (choose_clause_finding)
  std::optional<Finding> preflight;  // the run's fresh-node failure
  std::string route;                 // RouteLimits::route ("" in process)
  std::string route_limit;           // non-empty: the route cannot judge it, why (route_limit_of)
  long exercised = 0;                // judged steps that decided it (all properties, all shards)
  long derived_only = 0;             // steps only the derived document, which the route lacks, decided it on
  long unreported_verdicts = 0;      // steps the implementation answered `done` to (the run's)
  // From the properties that declare it (gather_clause_evidence):
  bool declared_and_ran = false;     // one of them ran (or stopped after some cases)
  std::string stopped_note;          // the first one that stopped: why
  PropertySkip skip = PropertySkip::None;  // the strongest reason one of them did not run
  std::string skip_note;             // that one's note
};

struct ClauseDecision {
  std::optional<ClauseStatus> status;  // empty: not selected and nothing found (the clause is left out)
  std::string note;
};

// The route's static verdict on a clause: why the route cannot judge it
// (a clause RouteLimits names; a clause only the derived document decides
// on a route that carries none), or "" when it can.
std::string route_limit_of(std::string_view clause_id, const RouteLimits& limits);

// Fills the property part of *e (declared_and_ran, stopped_note, skip,
// skip_note) and *properties (the ids of declaring properties that ran,
// catalog order) from `outcomes`, one per catalog property in catalog
// order.
void gather_clause_evidence(const Clause& clause, const std::vector<PropertyOutcome>& outcomes, ClauseEvidence* e,
                            std::vector<std::string>* properties);

// Whether `candidate` (shown by `candidate_program`, from a property at
// `candidate_index` in the catalog) replaces the finding chosen so far
// (`chosen`, from `chosen_index`): the worse kind wins (a crash over a
// wrong answer: confirm_finding.h finding_severity), then the shortest
// program, then the earlier property. The same in one run and across
// merged shards.
bool prefer_finding(const Finding& candidate, const Program& candidate_program, int candidate_index,
                    const std::optional<Finding>& chosen, const Program& chosen_program, int chosen_index);

ClauseDecision decide_clause_status(const Clause& clause, const ClauseEvidence& e);

// Sets run->complete from its clauses, properties and cancel (RunResult).
// The one place it is computed; whether a finding gates is the verdict's
// (verdict.h judge: the one verdict function, with a baseline and --strict).
void summarize_run(RunResult* run);

}  // namespace vgc
