// minimize_input.cpp — see minimize_input.h.
#include "minimize_input.h"

#include <fmt/core.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "exec_implementation.h"  // shell_quote
#include "reaped_command.h"

namespace vgc::fuzz {
namespace {

namespace fs = std::filesystem;
using clock = std::chrono::steady_clock;

std::size_t size_of(const std::string& path) {
  std::error_code ec;
  const auto n = fs::file_size(path, ec);
  return ec ? 0 : static_cast<std::size_t>(n);
}

// Runs `command` through the shell, its output (stdout and stderr) appended
// to `log`; its exit status (-1 when it could not be run or was signalled).
int run_logged(const std::string& command, const std::string& log) {
  std::string ignored;
  const int status = run_reaped_shell(command + " >>" + shell_quote(log) + " 2>&1", &ignored);
  return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// CPU seconds used by the children this process has waited for.
double children_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

bool is_hang(const std::string& input) {
  const std::string base = fs::path(input).filename().string();
  return base.rfind("timeout-", 0) == 0 || base.rfind("slow-unit-", 0) == 0;
}

// One libFuzzer minimizing step: mutations of `current` shorter than it,
// until one crashes (written to `next`, exit non-zero) or `runs` are spent
// (exit 0). `timeout` is the wall guard only.
std::string step_command(const std::string& run_prefix, const MinimizeLimits& limits, int k, long wall_guard_s,
                         const std::string& current, const std::string& next) {
  return fmt::format(
      "ASAN_OPTIONS=\"${{ASAN_OPTIONS:+$ASAN_OPTIONS:}}dedup_token_length=1\" timeout -k 2 {} env {} "
      "-minimize_crash_internal_step=1 -runs={} -seed={} -timeout=5 -exact_artifact_path={} {}",
      wall_guard_s, run_prefix, limits.runs_per_step, limits.seed + static_cast<unsigned>(k), shell_quote(next),
      shell_quote(current));
}

}  // namespace

MinimizedInput minimize_input(const std::string& run_prefix, const std::string& input, const std::string& out_file,
                              const std::function<bool(const std::string&)>& same_failure,
                              const MinimizeLimits& limits, clock::time_point deadline) {
  MinimizedInput m;
  m.before = size_of(input);
  if (m.before < 2) {
    m.note = "too small to minimize";
    return m;
  }
  if (is_hang(input)) {
    m.note = "a hang: not minimized (each try would take the whole timeout)";
    return m;
  }
  const auto t0 = clock::now();
  if (deadline - t0 < std::chrono::seconds(2)) {
    m.note = "no time left to minimize";
    return m;
  }
  m.tried = true;
  const double cpu0 = children_cpu_seconds();
  const std::string log = out_file + ".log", next = out_file + ".step";
  std::error_code ec;
  fs::remove(out_file, ec);
  fs::remove(log, ec);
  std::string current = input;  // the smallest input known to fail the same way
  std::size_t size = m.before;
  for (int k = 0;; ++k) {
    if (k >= limits.max_steps) {
      m.note = fmt::format("stopped after {} steps (the step limit)", k);
      break;
    }
    m.cpu_seconds = children_cpu_seconds() - cpu0;
    if (m.cpu_seconds >= limits.cpu_seconds) {
      m.note = fmt::format("stopped after {} steps: {:.0f} CPU seconds used (the limit)", k, m.cpu_seconds);
      break;
    }
    const long wall_left = std::chrono::duration_cast<std::chrono::seconds>(deadline - clock::now()).count();
    if (wall_left < 1) {
      m.note = fmt::format("cut after {} steps by the run's time guard, not finished", k);
      break;
    }
    fs::remove(next, ec);
    const std::string command = step_command(run_prefix, limits, k, wall_left, current, next);
    { std::ofstream(log, std::ios::app) << "\nvgc fuzz: step " << k + 1 << ": " << command << "\n"; }
    const int exit = run_logged(command, log);
    ++m.steps;
    if (exit == 0) {
      m.note = fmt::format("no smaller input fails after {} mutations", limits.runs_per_step);
      break;
    }
    if (exit == 124 || exit == 137) {
      m.note = fmt::format("step {} cut by the run's time guard, not finished", k + 1);
      break;
    }
    const std::size_t got = size_of(next);
    if (got == 0 || got >= size) {
      m.note = "libFuzzer's step ended without a smaller input that crashes";
      break;
    }
    if (!same_failure(next)) {
      m.note = fmt::format("the {}-byte input of step {} fails differently: the {}-byte one is kept", got, k + 1,
                           size);
      break;
    }
    fs::rename(next, out_file, ec);
    if (ec) break;
    current = out_file;
    size = got;
  }
  fs::remove(next, ec);
  m.seconds = std::chrono::duration<double>(clock::now() - t0).count();
  m.cpu_seconds = children_cpu_seconds() - cpu0;
  if (size < m.before && current == out_file) {
    m.kept = true;
    m.file = out_file;
    m.after = size;
  } else if (m.note.empty()) {
    m.note = "libFuzzer found no smaller input that crashes";
  }
  return m;
}

}  // namespace vgc::fuzz
