// launched_host.h — a Verse host that vgc starts itself (`--host-cmd CMD`
// of certify, replay and fuzz): the user's command run under the reaper,
// waited for until the host answers a login, restarted for a fresh
// instance, and ended with vgc.
//
// Spec: STABLE-1 and ACCEPT-1 of the clause catalog (a crash, a hang is
// confirmed on a fresh instance: confirm_finding.h); docs/adapters.md
// section 7 (the Verse wire route); docs/fuzzing.md "A Verse host vgc
// starts (--host-cmd)"; docs/ci.md "Nothing outlives vgc".
//
// Rationale: a Verse host is a server that was running before vgc and goes
// on after it, so a fresh instance needs the user's restart script
// (restartable_host.h), and a host started by a script lives outside what
// vgc controls: it cannot be given the shared memory of the
// implementation's coverage (live_coverage.h), nor be sure to end with vgc.
// Given the command that runs the host in the foreground (`./verse
// -port=4950`), vgc starts it as it starts an exec: program: /bin/sh -c CMD
// under a reaper of its own (reaped_process.h; this process's environment,
// so VGC_COVERAGE_SHM reaches it), its output to a log file or /dev/null,
// no terminal. Before it starts, the host's UDP port must be free (a host
// of an earlier round may still be ending: waited for up to 10 s); then a
// login is tried (the first within a second, each next one given twice as
// long), 100 ms apart, until one is accepted, the command ends (it
// started the host in the background, or failed: said with its exit
// status), or the start limit (OpenOptions::start_timeout_seconds) passes.
// restart() stops the host and everything it started (the reaper) and
// starts the command again: a fresh process, the same port. When vgc ends,
// however (SIGKILL included), the reaper ends the host.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "implementation.h"
#include "reaped_process.h"
#include "route.h"

namespace vgc {

class LaunchedHost {
 public:
  // `route` is a verse: route; `command` a shell command running the host in
  // the foreground; `log` a file the host's output is appended to ("" :
  // /dev/null).
  LaunchedHost(Route route, std::string command, std::string log, double start_timeout_s);
  ~LaunchedHost();  // stop()
  LaunchedHost(const LaunchedHost&) = delete;
  LaunchedHost& operator=(const LaunchedHost&) = delete;

  // Stops a running host, then starts the command and waits until the host
  // accepts a login opened with `options`. The
  // login's session is handed over in *session when it is not null (else
  // closed). false and *why when the host did not come up.
  bool start(const OpenOptions& options, std::unique_ptr<Implementation>* session, std::string* why);
  // Ends the host and everything it started (bounded: 5 s).
  void stop();
  bool running() const { return proc_.pid > 0; }
  std::uint64_t starts() const { return starts_; }
  const std::string& command() const { return command_; }

 private:
  Route route_;
  std::string command_, log_;
  double start_timeout_s_;
  ReapedProcess proc_;
  std::uint64_t starts_ = 0;
};

// A verse: route whose host vgc starts with `command` (output appended to
// `log`, "" : none): the host started (LaunchedHost) and logged in to;
// restart() ends it and starts it again, instance() counts the starts.
// nullptr and *error when the host does not come up.
std::unique_ptr<Implementation> open_launched_host(const Route& route, const OpenOptions& options,
                                                   const std::string& command, const std::string& log,
                                                   std::string* error);

// Whether UDP `port` of `host` can be bound here now (false: something
// listens on it). A host that is not an address of this machine: true.
bool udp_port_free(const std::string& host, std::uint16_t port);

}  // namespace vgc
