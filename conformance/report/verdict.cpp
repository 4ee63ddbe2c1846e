// verdict.cpp — see verdict.h.
#include "verdict.h"

#include "cancel.h"

#include <algorithm>
#include <map>

namespace vgc {

namespace {
bool in(const std::vector<std::string>& ids, const std::string& id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}
}  // namespace

bool finding_gates(const ClauseOutcome& co, bool strict) {
  if (!co.finding) return false;
  switch (co.clause->level) {
    case ClauseLevel::Should: return false;
    case ClauseLevel::Must: return true;
    case ClauseLevel::ImplementationDefined: return strict || co.finding->status != FindingStatus::Fail;
  }
  return true;
}

Verdict judge(const RunResult& run, const Baseline* baseline, bool strict) {
  Verdict v;
  v.strict = strict;
  for (const ClauseOutcome& co : run.clauses) {
    const std::string id(co.clause->id);
    const bool baselined = baseline && baseline->reasons.count(id);
    if (co.finding) {
      if (co.clause->level == ClauseLevel::Should) v.should_failures.push_back(id);
      else if (baselined) v.known_failures.push_back(id);
      else if (finding_gates(co, strict)) v.new_failures.push_back(id);
      else v.profile_differences.push_back(id);
    } else if (baselined && co.status != ClauseStatus::Skipped && co.status != ClauseStatus::NotClaimed) {
      // Tolerated from the first case, yet no case diverged on it.
      if (co.status == ClauseStatus::Pass) v.stale_baseline.push_back(id);
    }
    if (co.status == ClauseStatus::Unchecked) v.unchecked.push_back(id);
  }
  if (!run.cancelled_by.empty()) {  // what it found is listed, but the run is no verdict
    v.name = "incomplete";
    v.exit_code = cancelled_exit_code(run.cancelled_by);  // the process's: 128 + the signal
  } else if (!v.new_failures.empty()) {
    v.name = "not-conformant";
    v.exit_code = 1;
  } else if (!run.complete) {
    v.name = "incomplete";
    v.exit_code = 2;
  } else {
    v.name = "conformant";
    v.exit_code = 0;
  }
  return v;
}

std::string shown_status(const ClauseOutcome& co, const Verdict& v) {
  const std::string id(co.clause->id);
  if (in(v.should_failures, id)) return std::string(clause_status_name(co.status)) + " (SHOULD)";
  if (in(v.known_failures, id)) return std::string(clause_status_name(co.status)) + " (baseline)";
  if (in(v.profile_differences, id)) return "profile difference";
  return clause_status_name(co.status);
}

std::vector<std::pair<std::string, int>> shown_status_counts(const RunResult& run, const Verdict& v) {
  static const char* const kOrder[] = {
      "pass",           "fail",           "crash",         "timeout",         "fail (baseline)",
      "crash (baseline)", "timeout (baseline)", "profile difference", "fail (SHOULD)", "crash (SHOULD)",
      "timeout (SHOULD)", "unchecked",      "not-applicable", "not-claimed",     "skipped"};
  std::map<std::string, int> counts;
  std::vector<std::string> others;
  for (const auto& co : run.clauses) {
    const std::string s = shown_status(co, v);
    if (!counts[s]++ && std::find(std::begin(kOrder), std::end(kOrder), s) == std::end(kOrder)) others.push_back(s);
  }
  std::vector<std::pair<std::string, int>> out;
  for (const char* s : kOrder)
    if (counts.count(s)) out.emplace_back(s, counts[s]);
  for (const auto& s : others) out.emplace_back(s, counts[s]);
  return out;
}

std::string shown_status_tally(const RunResult& run, const Verdict& v) {
  std::string out;
  for (const auto& [status, n] : shown_status_counts(run, v))
    out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + status;
  return out;
}

}  // namespace vgc
