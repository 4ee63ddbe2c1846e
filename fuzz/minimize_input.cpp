// minimize_input.cpp — see minimize_input.h.
#include "minimize_input.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "exec_implementation.h"  // shell_quote

namespace vgc::fuzz {
namespace {

namespace fs = std::filesystem;

std::size_t size_of(const std::string& path) {
  std::error_code ec;
  const auto n = fs::file_size(path, ec);
  return ec ? 0 : static_cast<std::size_t>(n);
}

// Runs `command` through the shell, its output (stdout and stderr) into `log`.
void run_logged(const std::string& command, const std::string& log) {
  FILE* p = popen((command + " >" + shell_quote(log) + " 2>&1").c_str(), "r");
  if (p) pclose(p);
}

bool is_hang(const std::string& input) {
  const std::string base = fs::path(input).filename().string();
  return base.rfind("timeout-", 0) == 0 || base.rfind("slow-unit-", 0) == 0;
}

}  // namespace

MinimizedInput minimize_input(const std::string& run_prefix, const std::string& input, const std::string& out_file,
                              const std::function<bool(const std::string&)>& same_failure,
                              std::chrono::steady_clock::time_point deadline) {
  using clock = std::chrono::steady_clock;
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
  const double left = std::chrono::duration<double>(deadline - t0).count();
  if (left < 2) {
    m.note = "no time left to minimize";
    return m;
  }
  m.tried = true;
  std::error_code ec;
  fs::remove(out_file, ec);
  // Each step (one libFuzzer run mutating into inputs smaller than the
  // current one) stops at its first crash, or after -runs or
  // -max_total_time when there is none: then the minimization ends. The
  // whole is cut at the deadline by `timeout` (its process group).
  const long total = std::max(1L, static_cast<long>(left));
  const long step = std::clamp(total / 3, 1L, 10L);
  const std::string command = fmt::format(
      "ASAN_OPTIONS=\"${{ASAN_OPTIONS:+$ASAN_OPTIONS:}}dedup_token_length=1\" timeout -k 2 {} env {} "
      "-minimize_crash=1 -runs=100000 -max_total_time={} -timeout=5 -exact_artifact_path={} {}",
      total, run_prefix, step, shell_quote(out_file), shell_quote(input));
  run_logged(command, out_file + ".log");
  {
    std::ofstream log(out_file + ".log", std::ios::app);
    log << "\nvgc fuzz: ran " << command << "\n";
  }
  m.seconds = std::chrono::duration<double>(clock::now() - t0).count();
  const std::size_t got = size_of(out_file);
  if (got == 0 || got >= m.before) {
    m.note = "libFuzzer found no smaller input that crashes";
  } else if (!same_failure(out_file)) {
    m.note = fmt::format("the {}-byte input libFuzzer ended with fails differently: the original is kept", got);
  } else {
    m.kept = true;
    m.file = out_file;
    m.after = got;
    return m;
  }
  fs::remove(out_file, ec);
  return m;
}

}  // namespace vgc::fuzz
