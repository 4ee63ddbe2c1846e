// sign_budget.h — what a campaign may spend after libFuzzer stops: re-running
// saved crash inputs to sign them, minimizing and replaying the findings.
//
// Spec: none of the Verse spec; docs/fuzzing.md "--time is a wall-clock
// limit" (issue 19) and "Same implementation, same verdict" (issue 31).
//
// Rationale: the budget used to be wall clock (max(10 s, --time/10)), so a
// loaded machine signed fewer inputs, minimized less and confirmed fewer
// findings than an idle one: the same campaign wrote different findings
// depending on what else ran beside it. The budget is now CPU seconds of
// vgc and its children, waited for or running (run_budget.h's
// run_cpu_seconds, which certify's --budget counts too: the targets, `vgc replay`, an exec:
// implementation), which the machine's load barely changes, and the counts
// already there (200 inputs, 200 replays). A wall guard (20 times the CPU
// budget, at least 5 minutes) only stops what uses no CPU while it waits (a
// hanging implementation): a run that reaches it says so in its summary.
#pragma once

#include <chrono>

namespace vgc::fuzz {

struct SignBudget {
  double cpu_limit_s = 10;       // CPU seconds of this process and its children
  double cpu_at_start_s = 0;
  std::chrono::steady_clock::time_point wall_guard;

  // The budget of a campaign of `time_s` seconds, starting now.
  static SignBudget starting_now(double time_s);
  double cpu_used_s() const;
  bool spent() const;                  // the CPU budget or the wall guard is spent
  bool half_spent() const;             // half of either (a live implementation's inputs stop there)
  bool wall_guard_reached() const;
};

}  // namespace vgc::fuzz
