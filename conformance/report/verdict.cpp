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
    v.kind = VerdictKind::Incomplete;
    v.exit_code = cancelled_exit_code(run.cancelled_by);  // the process's: 128 + the signal
  } else if (!v.new_failures.empty()) {
    v.kind = VerdictKind::NotConformant;
    v.exit_code = 1;
  } else if (!run.complete) {
    v.kind = VerdictKind::Incomplete;
    v.exit_code = 2;
  } else {
    v.kind = VerdictKind::Conformant;
    v.exit_code = 0;
  }
  v.name = verdict_kind_name(v.kind);
  return v;
}

const char* verdict_kind_name(VerdictKind k) {
  switch (k) {
    case VerdictKind::Conformant: return "conformant";
    case VerdictKind::NotConformant: return "not-conformant";
    case VerdictKind::Incomplete: return "incomplete";
  }
  return "incomplete";
}

const char* verdict_kind_headline(VerdictKind k) {
  switch (k) {
    case VerdictKind::Conformant: return "CONFORMANT";
    case VerdictKind::NotConformant: return "NOT CONFORMANT";
    case VerdictKind::Incomplete: return "INCOMPLETE";
  }
  return "INCOMPLETE";
}

ClauseShown clause_shown(const ClauseOutcome& co, const Verdict& v) {
  const std::string id(co.clause->id);
  if (in(v.should_failures, id)) return {co.status, ShownQualifier::Should};
  if (in(v.known_failures, id)) return {co.status, ShownQualifier::Baseline};
  if (in(v.profile_differences, id)) return {co.status, ShownQualifier::ProfileDifference};
  return {co.status, ShownQualifier::None};
}

std::string shown_status_name(const ClauseShown& s) {
  switch (s.qualifier) {
    case ShownQualifier::None: return clause_status_name(s.status);
    case ShownQualifier::Baseline: return std::string(clause_status_name(s.status)) + " (baseline)";
    case ShownQualifier::ProfileDifference: return "profile difference";
    case ShownQualifier::Should: return std::string(clause_status_name(s.status)) + " (SHOULD)";
  }
  return clause_status_name(s.status);
}

std::string shown_status(const ClauseOutcome& co, const Verdict& v) { return shown_status_name(clause_shown(co, v)); }

namespace {

// The counts' fixed order: pass, what gates, what does not, what was not
// judged. A profile difference is one entry whatever its status.
int shown_rank(const ClauseShown& s) {
  const auto deviation = [](ClauseStatus st) { return st == ClauseStatus::Crash ? 1 : st == ClauseStatus::Timeout ? 2 : 0; };
  switch (s.qualifier) {
    case ShownQualifier::Baseline: return 10 + deviation(s.status);
    case ShownQualifier::ProfileDifference: return 20;
    case ShownQualifier::Should: return 30 + deviation(s.status);
    case ShownQualifier::None: break;
  }
  switch (s.status) {
    case ClauseStatus::Pass: return 0;
    case ClauseStatus::Fail: return 1;
    case ClauseStatus::Crash: return 2;
    case ClauseStatus::Timeout: return 3;
    case ClauseStatus::Unchecked: return 40;
    case ClauseStatus::NotApplicable: return 41;
    case ClauseStatus::NotClaimed: return 42;
    case ClauseStatus::Skipped: return 43;
  }
  return 50;
}

}  // namespace

std::vector<std::pair<ClauseShown, int>> shown_counts(const RunResult& run, const Verdict& v) {
  std::vector<std::pair<ClauseShown, int>> out;
  for (const auto& co : run.clauses) {
    ClauseShown s = clause_shown(co, v);
    if (s.qualifier == ShownQualifier::ProfileDifference) s.status = ClauseStatus::Fail;  // one entry, as printed
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& e) { return e.first == s; });
    if (it == out.end()) out.emplace_back(s, 1);
    else ++it->second;
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const auto& a, const auto& b) { return shown_rank(a.first) < shown_rank(b.first); });
  return out;
}

std::vector<std::pair<std::string, int>> shown_status_counts(const RunResult& run, const Verdict& v) {
  std::vector<std::pair<std::string, int>> out;
  for (const auto& [s, n] : shown_counts(run, v)) out.emplace_back(shown_status_name(s), n);
  return out;
}

std::string shown_status_tally(const RunResult& run, const Verdict& v) {
  std::string out;
  for (const auto& [status, n] : shown_status_counts(run, v))
    out += (out.empty() ? "" : ", ") + std::to_string(n) + " " + status;
  return out;
}

}  // namespace vgc
