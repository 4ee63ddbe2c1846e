// clause_status.cpp — see clause_status.h.
#include "clause_status.h"

#include <algorithm>

#include "attribution.h"
#include "confirm_finding.h"
#include "property.h"
#include "route_limit_clauses.h"

namespace vgc {
namespace {

// How much a skip reason says about the clause (the strongest one counts).
int skip_strength(PropertySkip s) {
  switch (s) {
    case PropertySkip::None: return 0;
    case PropertySkip::NotSelected: return 1;
    case PropertySkip::OtherShard: return 2;
    case PropertySkip::NotOnRoute: return 3;
    case PropertySkip::NotClaimed: return 4;
    case PropertySkip::NoOracle: return 5;
    case PropertySkip::Preflight: return 6;
  }
  return 0;
}

bool declares(const PropertySpec& spec, std::string_view clause_id) {
  return std::find(spec.clauses.begin(), spec.clauses.end(), clause_id) != spec.clauses.end();
}

// The ladder's steps, each a named rule; the first that applies decides.
std::optional<ClauseDecision> decided_by_finding(const ClauseEvidence& e) {
  if (!e.finding) return std::nullopt;
  return ClauseDecision{clause_status_of(e.finding->status), ""};
}

std::optional<ClauseDecision> decided_by_preflight(const ClauseEvidence& e) {
  if (!e.preflight) return std::nullopt;
  return ClauseDecision{ClauseStatus::Unchecked, "not judged: the implementation could not show a fresh node (" +
                                         e.preflight->clause + ": " + e.preflight->message + ")"};
}

// The route alone decides: whatever the cases drew, on any shard.
std::optional<ClauseDecision> decided_by_route(const ClauseEvidence& e) {
  if (!e.route_limit.empty()) return ClauseDecision{ClauseStatus::NotApplicable, e.route_limit};
  if (e.declared_and_ran || e.skip != PropertySkip::NotOnRoute) return std::nullopt;
  return ClauseDecision{ClauseStatus::NotApplicable, "not judgeable over " + e.route + ": every property that declares it "
                                          "is one the route cannot run (" + e.skip_note + ")"};
}

std::optional<ClauseDecision> decided_by_skip(const ClauseEvidence& e) {
  if (e.declared_and_ran || e.skip == PropertySkip::None) return std::nullopt;
  switch (e.skip) {
    case PropertySkip::NotClaimed: return ClauseDecision{ClauseStatus::NotClaimed, e.skip_note};
    case PropertySkip::OtherShard: return ClauseDecision{ClauseStatus::Skipped, e.skip_note};
    default: return ClauseDecision{ClauseStatus::Unchecked, "not judged: " + e.skip_note};
  }
}

std::optional<ClauseDecision> decided_by_stop(const ClauseEvidence& e) {
  if (e.stopped_note.empty()) return std::nullopt;
  return ClauseDecision{ClauseStatus::Unchecked, e.stopped_note};
}

// REASON-1 from an implementation that reports no verdicts.
std::optional<ClauseDecision> decided_by_unreported_verdicts(const Clause& clause, const ClauseEvidence& e) {
  if (clause.id != "REASON-1" || e.exercised > 0 || e.unreported_verdicts == 0) return std::nullopt;
  return ClauseDecision{ClauseStatus::NotApplicable, "the implementation reports no verdicts (it answered `done` to " +
                                              std::to_string(e.unreported_verdicts) +
                                              " commands), so reason codes cannot be judged"};
}

std::optional<ClauseDecision> decided_by_reach(const ClauseEvidence& e) {
  if (e.exercised > 0) return std::nullopt;
  // A shard runs a share of every property's cases: that none of its share
  // reached a clause says nothing yet; the merged run decides.
  if (e.shard_part && e.declared_and_ran)
    return ClauseDecision{ClauseStatus::Skipped, "no judged command of this shard's cases exercised it; `vgc merge` of the "
                                     "shards decides it from all of them"};
  return ClauseDecision{ClauseStatus::Unchecked, e.declared_and_ran ? "0 judged commands exercised it"
                                                        : "no property declares it and no judged command exercised it"};
}

}  // namespace

std::string route_limit_of(std::string_view clause_id, const RouteLimits& limits) {
  if (const std::string why = route_cannot_judge(clause_id, limits); !why.empty())
    return "not judgeable over " + limits.route + ": " + why;
  const auto& derived = derived_only_clauses();
  if (!limits.derived && std::find(derived.begin(), derived.end(), clause_id) != derived.end())
    return "not judgeable over " + limits.route + ": only the derived document (bone world poses) decides it, and " +
           limits.why_no_derived;
  return "";
}

void gather_clause_evidence(const Clause& clause, const std::vector<PropertyOutcome>& outcomes, ClauseEvidence* e,
                            std::vector<std::string>* properties) {
  const auto& props = property_catalog();
  for (std::size_t i = 0; i < props.size() && i < outcomes.size(); ++i) {
    if (!declares(props[i], clause.id)) continue;
    const PropertyOutcome& po = outcomes[i];
    if (po.status == PropertyStatus::Skipped) {
      if (skip_strength(po.skip) > skip_strength(e->skip)) e->skip = po.skip, e->skip_note = po.note;
      continue;
    }
    if (po.status == PropertyStatus::Stopped && e->stopped_note.empty())
      e->stopped_note = "its property " + po.id + " stopped: " + po.note;
    e->declared_and_ran = e->declared_and_ran || po.status != PropertyStatus::Stopped || po.cases > 0;
    properties->push_back(po.id);
  }
  // A property in another shard runs there: the clause is judged there, so
  // nothing this shard cannot run says anything about it.
  if (e->skip == PropertySkip::NotOnRoute) {
    for (std::size_t i = 0; i < props.size() && i < outcomes.size(); ++i)
      if (declares(props[i], clause.id) && outcomes[i].skip == PropertySkip::OtherShard) {
        e->skip = PropertySkip::OtherShard;
        e->skip_note = outcomes[i].note;
        break;
      }
  }
}

bool prefer_finding(const Finding& candidate, const Program& candidate_program, int candidate_index,
                    const std::optional<Finding>& chosen, const Program& chosen_program, int chosen_index) {
  if (!chosen) return true;
  if (finding_severity(candidate) != finding_severity(*chosen))
    return finding_severity(candidate) > finding_severity(*chosen);
  if (candidate_program.commands.size() != chosen_program.commands.size())
    return candidate_program.commands.size() < chosen_program.commands.size();
  return candidate_index < chosen_index;
}

ClauseDecision decide_clause_status(const Clause& clause, const ClauseEvidence& e) {
  if (auto d = decided_by_finding(e)) return *d;
  if (!e.selected) return {};
  for (auto step : {decided_by_preflight, decided_by_route, decided_by_skip, decided_by_stop})
    if (auto d = step(e)) return *d;
  if (auto d = decided_by_unreported_verdicts(clause, e)) return *d;
  if (auto d = decided_by_reach(e)) return *d;
  if (e.derived_only > 0)
    return {ClauseStatus::Pass, "judged on the snapshot; its derived part (" + std::to_string(e.derived_only) +
                        " commands) is not judgeable over " + e.route};
  return {ClauseStatus::Pass, ""};
}

void summarize_run(RunResult* run) {
  run->complete = true;
  for (const auto& co : run->clauses)
    if (co.status == ClauseStatus::Unchecked) run->complete = false;
  for (const auto& po : run->properties)
    if (po.status == PropertyStatus::Stopped) run->complete = false;
  if (!run->cancelled_by.empty()) run->complete = false;
}

}  // namespace vgc
