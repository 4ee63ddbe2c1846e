// verdict.cpp — see verdict.h.
#include "verdict.h"

namespace vgc {

Verdict judge(const RunResult& run, const Baseline* baseline) {
  Verdict v;
  for (const ClauseOutcome& co : run.clauses) {
    const std::string id(co.clause->id);
    const bool baselined = baseline && baseline->reasons.count(id);
    if (co.finding) {
      if (co.clause->level == ClauseLevel::Should) v.should_failures.push_back(id);
      else if (baselined) v.known_failures.push_back(id);
      else v.new_failures.push_back(id);
    } else if (baselined && co.status == "pass") {
      v.stale_baseline.push_back(id);
    }
  }
  if (!v.new_failures.empty()) {
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
