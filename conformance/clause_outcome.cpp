// clause_outcome.cpp — see clause_outcome.h.
#include "clause_outcome.h"

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "clause.h"
#include "clause_selection.h"
#include "clause_status.h"
#include "confirm_finding.h"
#include "route_limit_clauses.h"

namespace vgc {
namespace {

std::string join(const std::set<std::string>& s) {
  std::string out;
  for (const auto& x : s) out += (out.empty() ? "" : ", ") + x;
  return out;
}

}  // namespace

void decide_clauses(const RunSettings& o, const RouteLimits& limits, RunResult* run) {
  for (const Clause& clause : clause_catalog()) {
    ClauseOutcome co;
    co.clause = &clause;
    const std::string id(clause.id);
    ClauseEvidence e;
    e.selected = clause_selected(o.clause_glob, clause.id);
    e.shard_part = o.shard_count > 1;
    e.preflight = run->preflight;
    e.route = limits.route;
    e.route_limit = route_limit_of(clause.id, limits);
    e.unreported_verdicts = run->unreported_verdicts;
    int chosen_index = 0;
    // Milder kinds of finding in the clause, shown in the note: each kind
    // once, with every property that found it.
    std::vector<std::pair<std::string, std::set<std::string>>> also;
    const auto also_found = [&also](const Finding& f, const std::string& by) {
      auto it = std::find_if(also.begin(), also.end(), [&](const auto& a) { return a.first == finding_kind(f); });
      if (it == also.end()) it = also.insert(also.end(), {finding_kind(f), {}});
      it->second.insert(by);
    };
    for (std::size_t i = 0; i < run->properties.size(); ++i) {
      const PropertyOutcome& po = run->properties[i];
      if (auto it = po.exercised.find(id); it != po.exercised.end()) e.exercised += it->second;
      if (auto it = po.derived_only.find(id); it != po.derived_only.end()) e.derived_only += it->second;
      auto take = [&](const Finding& f, const Program& p, bool known) {
        if (!prefer_finding(f, p, static_cast<int>(i), co.finding, co.program, chosen_index)) {
          if (co.finding && finding_kind(f) != finding_kind(*co.finding)) also_found(f, po.id);
          return;
        }
        if (co.finding && finding_kind(f) != finding_kind(*co.finding)) also_found(*co.finding, co.found_by);
        chosen_index = static_cast<int>(i);
        co.finding = f;
        co.program = p;
        co.found_by = po.id;
        co.seed = po.seed;
        co.tolerated_from_start = known;
      };
      for (const auto& pf : po.findings)
        if (pf.finding.clause == clause.id) take(pf.finding, pf.program, pf.tolerated_from_start);
      for (const auto& [f, p] : po.notes)
        if (f.clause == clause.id) take(f, p, false);
    }
    if (run->preflight && run->preflight->clause == clause.id) {
      co.finding = run->preflight;
      co.found_by = "fresh-node check";
    }
    e.finding = co.finding;
    gather_clause_evidence(clause, run->properties, &e, &co.properties);
    co.exercised = e.exercised;
    co.derived_only = e.derived_only;
    co.route_limit = e.route_limit;
    const ClauseDecision d = decide_clause_status(clause, e);
    if (!d.status) continue;  // not asked for and nothing found
    co.status = *d.status;
    co.note = d.note;
    if (!also.empty()) {
      co.note = "the worst kind of finding in this clause is shown; also found:";
      for (const auto& [kind, by] : also) co.note += " " + kind + " (" + join(by) + ")";
    }
    run->clauses.push_back(co);
  }
}

}  // namespace vgc
