// campaign_process.h — the child processes of a fuzz campaign: libFuzzer
// run with its output read line by line until a deadline or a CPU budget,
// and a shell command run for its output (re-running one crash input).
//
// Spec: none (fuzzing practice; docs/fuzzing.md "Running a campaign": --time
// is a wall-clock limit; CI practice: nothing vgc starts outlives it, issue
// 29 item 5, docs/ci.md "Nothing outlives vgc").
//
// Rationale: both go through the one launcher, the reaper
// (conformance/adapter/reaped_process.h, reaped_command.h), so that a
// campaign killed with SIGKILL or SIGTERM leaves no libFuzzer job behind.
// libFuzzer runs in a process group of its own (the program's, under the
// reaper): at the deadline the group gets SIGTERM, then SIGKILL 2 s later,
// as libFuzzer's fork-mode jobs need; its CPU time is the reaper's rusage
// (the program and every descendant waited for) or the group's reading
// (process_cpu.h), whichever is larger.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace vgc::fuzz {

struct ChildRun {
  int exit = -1;
  bool killed = false;  // still running at the deadline: its process group was killed
  bool cpu_spent = false;  // stopped because the group had used its CPU budget (cpu_limit_s)
  double cpu_s = 0;     // user + system of the child and the descendants it waited for
};

// The environment of a child: this process's, with env_add (NAME=value)
// replacing or adding variables.
std::vector<std::string> child_environment(const std::vector<std::string>& env_add);

// Runs argv (argv[0] a path) with env additions, stdout+stderr into
// `on_line` line by line, until it exits or `deadline` passes, or
// stop_now() (when given) says so; then SIGTERM to its whole group, SIGKILL
// 2 s later. With cpu_limit_s > 0 the group is also stopped once it has
// used that many CPU seconds (read at most once a second); exit is then 0.
ChildRun run_streaming(const std::vector<std::string>& argv, const std::vector<std::string>& env_add,
                       std::chrono::steady_clock::time_point deadline,
                       const std::function<void(const std::string&)>& on_line,
                       const std::function<bool()>& stop_now, double cpu_limit_s = 0);

// `command` through /bin/sh, its stdout (bounded: 64 MiB kept); "" when it
// could not be run.
std::string run_capture(const std::string& command);

}  // namespace vgc::fuzz
