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

// Of `found` (parts of one clause, each with its property's index), one
// per difference of `shown`'s kind other than shown's own: the one
// prefer_finding prefers, numbered as parts 1, 2, ... in the order each
// difference was first found.
std::vector<ClauseOutcome> other_differences(const Finding& shown, std::vector<std::pair<int, ClauseOutcome>> found) {
  std::vector<std::pair<int, ClauseOutcome>> best;
  for (auto& [index, f] : found) {
    if (f.finding->difference == shown.difference || finding_kind(*f.finding) != finding_kind(shown)) continue;
    auto same = std::find_if(best.begin(), best.end(), [&f = f](const auto& o) {
      return o.second.finding->difference == f.finding->difference;
    });
    if (same == best.end())
      best.emplace_back(index, std::move(f));
    else if (prefer_finding(*f.finding, f.program, index, same->second.finding, same->second.program, same->first))
      *same = {index, std::move(f)};
  }
  std::vector<ClauseOutcome> out;
  for (auto& [index, f] : best) {
    f.part = static_cast<int>(out.size()) + 1;
    out.push_back(std::move(f));
  }
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
    // Findings of a kind that tells differences apart (Finding::difference):
    // those of the shown finding's kind but another difference are other
    // findings.
    // Each with its property's index (prefer_finding).
    std::vector<std::pair<int, ClauseOutcome>> differences;
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
        if (kind_tells_differences_apart(f)) {
          ClauseOutcome part;
          part.clause = &clause;
          part.finding = f;
          part.program = p;
          part.found_by = po.id;
          part.seed = po.seed;
          part.tolerated_from_start = known;
          differences.emplace_back(static_cast<int>(i), std::move(part));
        }
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
    if (co.finding) co.other_findings = other_differences(*co.finding, std::move(differences));
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
