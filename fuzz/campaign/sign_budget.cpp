// sign_budget.cpp — see sign_budget.h.
#include "sign_budget.h"

#include "run_budget.h"  // run_cpu_seconds

#include <algorithm>

namespace vgc::fuzz {

SignBudget SignBudget::starting_now(double time_s) {
  SignBudget b;
  b.cpu_limit_s = std::max(10.0, time_s / 10);
  b.cpu_at_start_s = run_cpu_seconds();
  const double guard_s = std::max(300.0, 20 * b.cpu_limit_s);
  b.wall_guard = std::chrono::steady_clock::now() +
                 std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(guard_s));
  return b;
}

double SignBudget::cpu_used_s() const { return run_cpu_seconds() - cpu_at_start_s; }

bool SignBudget::wall_guard_reached() const { return std::chrono::steady_clock::now() >= wall_guard; }

bool SignBudget::spent() const { return cpu_used_s() >= cpu_limit_s || wall_guard_reached(); }

bool SignBudget::half_spent() const {
  const auto now = std::chrono::steady_clock::now();
  const auto guard_start = wall_guard - std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                            std::chrono::duration<double>(std::max(300.0, 20 * cpu_limit_s)));
  return cpu_used_s() >= cpu_limit_s / 2 || now >= guard_start + (wall_guard - guard_start) / 2;
}

}  // namespace vgc::fuzz
