// process_group_guard.h — a watcher process that kills a process group
// when this process ends, however it ends (exit, crash, SIGKILL).
//
// Spec: none (CI practice: nothing the suite starts may outlive it; issue 19).
//
// Rationale: an exec implementation runs as `/bin/sh -c CMD` in a process
// group of its own (so a timeout kills everything it started, children
// included), which also means nothing of it dies with vgc: killed with
// SIGKILL (a CI job cancelled hard), vgc used to leave the shell, the
// program and the program's children running under PID 1.
// PR_SET_PDEATHSIG would reach only the shell, not its children, so a
// small forked watcher waits on a pipe whose only writer is this process;
// the kernel closes it when this process ends, however, and the watcher
// then kills the whole group and exits. The watcher has a process group of
// its own and ignores the terminal's and CI's polite signals, so a signal
// to vgc's group (Ctrl-C, a CI runner's kill of the job's group) does not
// take it down before it did its job. Only a program that leaves its process
// group (setsid, setpgid) escapes it.
#pragma once

#include <string>
#include <sys/types.h>

namespace vgc {

class ProcessGroupGuard {
 public:
  ProcessGroupGuard() = default;
  ~ProcessGroupGuard() { release(); }
  ProcessGroupGuard(const ProcessGroupGuard&) = delete;
  ProcessGroupGuard& operator=(const ProcessGroupGuard&) = delete;

  // Starts a watcher for process group `pgid` (released first if one is
  // watched). On failure returns false and says why in *error.
  bool watch(pid_t pgid, std::string* error);
  // Stops the watcher without touching the group, and reaps it. Call it
  // before reaping the group's leader: while the leader is unreaped its
  // group id cannot be reused, so the watcher never kills a stranger.
  void release();
  // The watcher's process id, or -1.
  pid_t watcher() const { return watcher_; }

 private:
  pid_t watcher_ = -1;
  int alive_fd_ = -1;  // the pipe's write end; only this process holds it
};

}  // namespace vgc
