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

namespace vgc {

// Creates the descriptor cancel_fd() returns; call once before installing
// a signal handler that calls request_cancel. Idempotent.
void prepare_cancel();
// Records the request (the first signal number wins) and makes cancel_fd()
// readable. Async-signal-safe.
void request_cancel(int signal_number) noexcept;
// The signal number of the request, or 0 when there is none.
int cancel_signal() noexcept;
// "SIGTERM", "SIGINT", "signal N" for cancel_signal(); "" when none.
const char* cancel_signal_name() noexcept;
// A descriptor that is readable once cancel is requested, or -1 when
// prepare_cancel() was never called.
int cancel_fd() noexcept;

}  // namespace vgc
