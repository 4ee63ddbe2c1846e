// reaped_process.h — a program started under a reaper of its own, so that
// nothing it starts outlives vgc, however vgc ends (exit, crash, SIGKILL),
// even what left the program's process group or session (setsid, a double
// fork).
//
// Spec: none (CI practice: nothing the suite starts may outlive it; issue 19
// item 3; docs/ci.md "Nothing outlives vgc").
//
// Rationale: killing the program's process group misses whatever called
// setsid() or setpgid(), and a process whose parent died is reparented to
// PID 1. Linux offers PR_SET_CHILD_SUBREAPER: orphans are reparented to the
// nearest ancestor that set it instead. So vgc forks a small reaper (no
// exec, only async-signal-safe calls: vgc may have threads) that marks
// itself a subreaper and forks the program (/bin/sh -c CMD) in a process
// group of its own; everything the program starts is the reaper's
// descendant, and every orphan among them becomes the reaper's child. The
// reaper holds the read end of a control pipe whose only writer is vgc: end
// of file (vgc closed it to stop the program, or vgc ended, however: the
// kernel closes it) or the program's end makes the reaper kill the
// program's group, then every child it has (orphans, with their groups),
// again as new orphans arrive, until it has no child left (bounded: 5 s),
// and exit with the program's own wait status (a signal is re-raised, core
// dumps off), so that vgc sees what the program did. PR_SET_PDEATHSIG was
// not used: it fires when the parent *thread* ends, and vgc may start an
// implementation from a worker thread. What this cannot reach (a process
// that is not a descendant: one a daemon starts on the program's request)
// is said in docs/ci.md.
//
// It is the one way vgc starts a child process (issue 29 item 5): the exec:
// route's implementation, the fuzz campaign's libFuzzer runs, minimisation,
// merges and symbolisation (reaped_command.h: a shell command, its output
// captured), and a --restart command. The reaper tells vgc the program's
// pid, which is also its process group's id, so that vgc can signal the
// group (a fuzz campaign's SIGTERM at its deadline) while the reaper still
// guarantees the end. A restart command starts a host that must outlive the
// command but not vgc: started with `keep_descendants`, its reaper reports
// the command's wait status when the command ends and keeps what it
// started (reaping orphans) until vgc closes the control pipe or ends, or
// until nothing it started is left.
#pragma once

#include <string>
#include <sys/types.h>

namespace vgc {

struct ReapedProcess {
  pid_t pid = -1;        // the reaper's pid (its wait status is the program's)
  int control_fd = -1;   // the control pipe's write end (O_CLOEXEC); closing it stops the program
  pid_t program = -1;    // the program's pid and process group id (signal -program to reach its group)
  int status_fd = -1;    // keep_descendants only: the program's wait status (an int) arrives here
};

// How the program is started: its environment (nullptr: this process's),
// and whether what it starts is kept after it ends (see the top comment).
struct ReapedStart {
  char* const* envp = nullptr;
  bool keep_descendants = false;
};

// Starts `path` with `argv` and this process's environment under a reaper,
// with stdin, stdout and stderr from in_fd, out_fd, err_fd (any O_CLOEXEC
// descriptors; the caller closes its copies of the child's ends). On
// failure returns false and says why in *error.
bool spawn_reaped(const char* path, char* const argv[], int in_fd, int out_fd, int err_fd, ReapedProcess* out,
                  std::string* error, const ReapedStart& how = {});

// keep_descendants: waits up to `bound_ms` for the program's wait status
// (from status_fd); false when it did not come (the program still runs, or
// the reaper died).
bool wait_program_status(const ReapedProcess& p, int bound_ms, int* status);

// Hands a keep_descendants reaper over until vgc ends: its control pipe is
// held (what the program started lives on), and reapers whose descendants
// have all ended are reaped at the next call. Thread-safe.
void keep_until_exit(ReapedProcess* p);

// Stops the program and everything it started (closes the control pipe)
// and reaps the reaper within `bound_ms` (then kills it); returns its wait
// status (the program's). `p` is reset.
int stop_reaped(ReapedProcess* p, int bound_ms = 5000);

}  // namespace vgc
