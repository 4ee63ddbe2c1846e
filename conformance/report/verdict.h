// verdict.h — from per-clause results (and a baseline) to one verdict and
// the exit code CI gates on.
//
// Exit codes: 0 conformant; 1 not conformant (a MUST or
// IMPLEMENTATION-DEFINED clause failed, crashed or timed out and is not in
// the baseline); 2 usage or infrastructure error, or an incomplete run
// (the budget ran out), which is neither a pass nor a failure.
#pragma once

#include <string>
#include <vector>

#include "baseline.h"
#include "runner.h"

namespace vgc {

struct Verdict {
  std::string name;  // "conformant", "not-conformant", "incomplete"
  int exit_code = 0;
  std::vector<std::string> new_failures;    // clause ids that decide "not-conformant"
  std::vector<std::string> known_failures;  // failing, but in the baseline
  std::vector<std::string> should_failures; // SHOULD clauses that failed (verdict stands)
  std::vector<std::string> stale_baseline;  // in the baseline, but now passing
};

Verdict judge(const RunResult& run, const Baseline* baseline);

}  // namespace vgc
