// run_budget.h — what `--budget` counts: the CPU time of vgc and of every
// process it started (an exec: implementation, an isolated plugin's child,
// and what those started), not the wall clock.
//
// Spec: none of the Verse spec; docs/certify.md "The command" (--budget)
// and docs/ci.md "On a loaded machine" (issue 31: same implementation,
// same verdict, on an idle or a loaded machine).
//
// Rationale: a budget of wall-clock seconds made the verdict depend on the
// machine's load: the same implementation was `conformant` on an idle
// runner and `incomplete` (exit 2) on a loaded one, where vgc had used 18 s
// of CPU in 300 s of wall clock (docs/ci.md). CPU time is what the run
// costs whatever else runs beside it. It is read from the kernel: this
// process's own time and its waited-for children's (getrusage), plus every
// live descendant's (/proc/PID/stat: utime, stime and the cutime, cstime
// of the children it waited for), so an implementation that is still
// running counts as it runs. What waits without computing (an
// implementation that hangs until --timeout, a Verse host vgc did not
// start, whose CPU is not vgc's to see) costs no CPU: a wall-clock guard of
// kWallGuardFactor times the budget stops the run then, and says so. The
// guard does not count the time vgc and its live descendants waited in the
// kernel's run queue for a CPU (/proc/PID/schedstat): on a machine with
// 8 busy processes per 2 cores a run that computes 8 s takes far more
// than 80 s of wall clock without waiting for anything but the CPU (a
// loaded CertifyBudgetIsCpuTime was stopped by the guard at 80 s).
#pragma once

#include <chrono>
#include <string>

namespace vgc {

inline constexpr double kWallGuardFactor = 10;

// CPU seconds of this process, its waited-for children and its live
// descendants, now.
double run_cpu_seconds();

// CPU seconds of this process alone (cheap: no scan of /proc).
double own_cpu_seconds();

// Seconds this process's threads and its live descendants have waited in a
// run queue for a CPU (the machine's load), now; 0 where the kernel keeps
// no scheduler statistics.
double run_queue_seconds();

class RunBudget {
 public:
  // A budget of `seconds` (--budget) starting now; <= 0: none.
  explicit RunBudget(double seconds);
  // Whether the CPU budget or the wall-clock guard is spent (reads the
  // kernel's counters at most every budget/300, 50 ms to 1 s; once spent,
  // stays spent). The guard moves on by the time spent waiting for a CPU.
  bool spent();
  // Why it is spent, for the notes: "the budget (--budget 300: CPU seconds
  // of vgc and the implementation) ran out" or the wall guard's words.
  std::string why() const;
  double cpu_used() const { return last_cpu_ - cpu0_; }
  // The guard as it stands (it moves on with the load: see spent()).
  std::chrono::steady_clock::time_point wall_guard() const { return wall_guard_; }

 private:
  double seconds_ = 0, cpu0_ = 0, last_cpu_ = 0, queued0_ = 0;
  double own_at_read_ = 0, read_cost_ = 0;  // vgc's CPU at the last read, and what that read cost
  std::chrono::steady_clock::time_point start_, wall_guard_, next_read_, read_at_;
  bool spent_ = false, by_wall_ = false;
};

// "300", "0.5", "1e-06": a budget as the user wrote it, shortest form.
std::string budget_seconds_text(double seconds);

}  // namespace vgc
