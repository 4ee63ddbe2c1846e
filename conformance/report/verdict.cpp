// verdict.cpp — see verdict.h.
#include "verdict.h"

namespace vgc {

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
    } else if (baselined && co.status != "skipped" && co.status != "not-claimed") {
      // Tolerated from the first case, yet no case diverged on it.
      if (co.status == "pass") v.stale_baseline.push_back(id);
    }
    if (co.status == "unchecked") v.unchecked.push_back(id);
  }
  if (!run.cancelled_by.empty()) {  // what it found is listed, but the run is no verdict
    v.name = "incomplete";
    v.exit_code = 2;
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

}  // namespace vgc
