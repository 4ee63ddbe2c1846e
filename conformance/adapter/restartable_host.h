// restartable_host.h — a fresh instance of an implementation vgc did not
// start (a host on the Verse wire), from a shell command the user gives
// that starts one: `--restart CMD` of `vgc certify` and `vgc fuzz`.
//
// Spec: STABLE-1 and ACCEPT-1 of the clause catalog (a crash, a hang, a
// protocol error is confirmed on a fresh instance: confirm_finding.h);
// docs/adapters.md section 7 and docs/fuzzing.md "Fuzzing a running
// implementation" (--restart).
//
// Rationale: confirming a finding means repeating its program on an
// instance that has been through nothing else (Implementation::restart).
// An exec program is a process vgc starts, so restart() is a new process;
// a Verse host is a server that was running before vgc and goes on after
// it, so restart() on the wire is only a new node on the same host process,
// which is as old as it was. With the user's restart command, restart()
// runs it (the command stops the old host and starts a new one, and
// returns once it listens) and logs in to the new host, so certify, replay
// and fuzz confirm on a fresh host alike. A route that restarts by itself
// (RouteTraits::restartable) needs no command.
#pragma once

#include <memory>
#include <string>

#include "implementation.h"
#include "route.h"

namespace vgc {

// Opens `route`; with a non-empty `restart_command` on a route that does
// not restart by itself (RouteTraits::restartable), its restart() runs the
// command (bounded: 60 s) and opens the route again (a login retried for up
// to 15 s), and instance() counts the restarts. nullptr with *error when
// the first opening fails.
std::unique_ptr<Implementation> open_restartable(const Route& route, const OpenOptions& options,
                                                 const std::string& restart_command, std::string* error);

// Runs `command` with /bin/sh -c under a reaper (reaped_process.h) that
// keeps what it starts (the host) until vgc ends, then kills it; no
// terminal, no pipe of ours; at most `limit_s` seconds (then the command
// and everything it started are killed). true when it exited 0; *why
// otherwise.
bool run_restart_command(const std::string& command, double limit_s, std::string* why);

}  // namespace vgc
