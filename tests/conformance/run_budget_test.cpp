// run_budget_test.cpp — run_budget.h: the wall-clock guard of --budget
// stops a run that waits without computing, and does not count the time
// the run waited for a CPU on a loaded machine (issue 31: same
// implementation, same verdict, on an idle or a loaded machine).
#include <gtest/gtest.h>

#include <sched.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>
#include <vector>

#include "run_budget.h"

namespace vgc {
namespace {

using Clock = std::chrono::steady_clock;

// Busy loops on `cpu` that are not this process's descendants (their CPU
// is no part of the run's budget): each is forked twice, its parent exits
// at once, and it is reparented. Killed when this goes out of scope.
class BusyNeighbours {
 public:
  BusyNeighbours(int cpu, int count) {
    for (int i = 0; i < count; ++i) {
      int fds[2];
      if (pipe(fds) != 0) return;
      const pid_t child = fork();
      if (child == 0) {
        if (fork() == 0) {
          cpu_set_t set;
          CPU_ZERO(&set);
          CPU_SET(cpu, &set);
          sched_setaffinity(0, sizeof set, &set);
          const pid_t me = getpid();
          (void)!write(fds[1], &me, sizeof me);
          for (volatile unsigned long n = 0;; n = n + 1) {
          }
        }
        _exit(0);
      }
      waitpid(child, nullptr, 0);
      pid_t loop = 0;
      if (read(fds[0], &loop, sizeof loop) == sizeof loop) pids_.push_back(loop);
      close(fds[0]);
      close(fds[1]);
    }
  }
  ~BusyNeighbours() {
    for (pid_t p : pids_) kill(p, SIGKILL);
  }
  std::size_t size() const { return pids_.size(); }

 private:
  std::vector<pid_t> pids_;
};

// This process on the CPU it is on; returns that CPU.
int pin_self() {
  const int cpu = sched_getcpu() < 0 ? 0 : sched_getcpu();
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  sched_setaffinity(0, sizeof set, &set);
  return cpu;
}

// A run that computes a little at a time, starved of CPU by two busy
// neighbours, goes on past 10 x its budget of wall clock: what it waited
// for was a CPU. The guard used to stop it at 10 x the budget.
TEST(RunBudget, TimeWaitingForACpuIsNotWaitingForTheImplementation) {
  const int cpu = pin_self();
  BusyNeighbours busy(cpu, 2);  // at this process's priority
  ASSERT_EQ(busy.size(), 2u);
  setpriority(PRIO_PROCESS, 0, 19);  // then this one at the lowest: about 1 % of the CPU
  RunBudget budget(0.05);  // 50 ms of CPU; the guard at 0.5 s
  const double queued0 = run_queue_seconds();
  const auto start = Clock::now();
  bool spent = false;
  double spent_at = 0;
  while (Clock::now() - start < std::chrono::milliseconds(1500)) {
    for (volatile int i = 0; i < 1000; i = i + 1) {
    }
    if (!spent && budget.spent()) {
      spent = true;
      spent_at = std::chrono::duration<double>(Clock::now() - start).count();
    }
  }
  const double queued = run_queue_seconds() - queued0;
  ASSERT_GT(queued, 0.75) << "the test was not starved of CPU (waited " << queued
                          << " s in the run queue): it shows nothing";
  EXPECT_FALSE(spent) << budget.why() << " after " << spent_at << " s, " << budget.cpu_used() << " s of CPU, "
                      << queued << " s waiting for a CPU in 1.5 s";
}

// ... and still stops a run that waits without computing (a hang): asleep
// is not waiting for a CPU.
TEST(RunBudget, TheWallGuardStopsARunThatWaitsWithoutComputing) {
  RunBudget budget(0.05);
  const auto start = Clock::now();
  bool spent = false;
  while (Clock::now() - start < std::chrono::milliseconds(1500) && !spent) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    spent = budget.spent();
  }
  EXPECT_TRUE(spent);
  EXPECT_NE(budget.why().find("wall-clock guard"), std::string::npos) << budget.why();
}

}  // namespace
}  // namespace vgc
