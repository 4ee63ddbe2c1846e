// cancel.h — a process-wide request to stop a run early: what SIGTERM or
// SIGINT (a cancelled or timed-out CI job, Ctrl-C) asks of `vgc certify`.
//
// Spec: none (CI practice; docs/certify.md "Cancelling a run").
//
// Rationale: a cancelled run must still write what it found. The signal
// handler only records the request (request_cancel is async-signal-safe);
// the runner then treats it like a budget that ran out, discarding the
// case it interrupted (a call cut short proves nothing about a clause),
// and an out-of-process implementation's wait for an answer ends at once,
// because cancel_fd() becomes readable and is polled with its pipes.
#pragma once

#include <string_view>

namespace vgc {

// Creates the descriptor cancel_fd() returns; call once before installing
// a signal handler that calls request_cancel. Idempotent.
void prepare_cancel();
// Records the request (the first signal number wins) and makes cancel_fd()
// readable. `sender` is the process that sent the signal (siginfo's
// si_pid; 0 from the kernel, a terminal's Ctrl-C). Async-signal-safe.
void request_cancel(int signal_number, long sender = 0) noexcept;
// Whether a signal that comes after a cancel was requested is the same
// cancel delivered again rather than a second request to exit at once:
// the same signal from the same sender within a second of the first.
// `timeout` (GNU coreutils) sends its signal to the command and then to
// its whole process group, and a supervisor may signal a process and its
// group alike: one cancel reaches vgc twice, microseconds apart, and the
// second used to make vgc exit at once without its report whenever the
// first had already been handled (issue 31: 1 SIGTERM in 33 left no
// report). Async-signal-safe.
bool repeated_cancel(int signal_number, long sender) noexcept;
// The signal number of the request, or 0 when there is none.
int cancel_signal() noexcept;
// "SIGTERM", "SIGINT", "signal N" for cancel_signal(); "" when none.
const char* cancel_signal_name() noexcept;
// The exit code of a run cancelled by the signal `name` names ("SIGTERM":
// 143, "SIGINT": 130, "SIGHUP": 129): 128 + the signal, as a shell reports
// a process the signal ended. 2 (incomplete) for any other name.
int cancelled_exit_code(std::string_view name) noexcept;
// A descriptor that is readable once cancel is requested, or -1 when
// prepare_cancel() was never called.
int cancel_fd() noexcept;

}  // namespace vgc
