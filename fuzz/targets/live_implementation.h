// live_implementation.h — the implementation a fuzz target drives when it is
// not a plugin in process: a program over exec: or a Verse host over the
// wire (verse:HOST[:PORT]), opened exactly as `vgc certify` opens it, and
// how a finding against it is confirmed on a fresh instance.
//
// Spec: docs/adapters.md (the exec and Verse wire routes); STABLE-1 and
// ACCEPT-1 of the clause catalog (a crash, a hang); docs/fuzzing.md
// "Fuzzing a running implementation".
//
// Rationale: `vgc fuzz differential --impl exec:CMD|verse:...` passes the
// implementation to the libFuzzer binary in the environment (the binary
// takes no options of ours): VGC_FUZZ_IMPL the spec, VGC_FUZZ_TIMEOUT the
// seconds per call, VGC_FUZZ_VERSE_BONE_FORM the bone_create form,
// VGC_FUZZ_RESTART a shell command that starts a fresh instance of a wire
// host. A fresh instance of an exec program is a new process (restart());
// a host on the wire is a server vgc did not start: only the user's restart
// command can give a fresh one (restartable_host.h, as for certify), and
// without it a crash or hang is reported as not confirmed
// (LiveOptions::restart empty). The spec is read once into a Route
// (route.h), whose traits decide the rest.
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <string>

#include "implementation.h"
#include "route.h"

namespace vgc::fuzz {

struct LiveOptions {
  std::string spec;             // exec:CMD or verse:[NAME@]HOST[:PORT]; "" none
  std::optional<Route> route;   // spec, read (nullopt: none, or route_error says why not)
  std::string route_error;
  double timeout_s = 5;         // per call
  std::string verse_bone_form;  // "" = auto
  std::string restart;          // verse: shell command starting a fresh host; "" none
  // verse: the command running the host in the foreground, which the target
  // starts itself (VGC_FUZZ_HOST_CMD, --host-cmd; launched_host.h): with the
  // shared memory of its coverage, started again for a fresh instance, ended
  // with the target. Its output is appended to host_log (VGC_FUZZ_HOST_LOG).
  std::string host_cmd, host_log;
  // Clauses of known deviations (VGC_FUZZ_BASELINE, the certify baseline
  // file `vgc fuzz --baseline` was given, already checked by the
  // campaign): a finding in one of them does not stop libFuzzer. A host
  // that deviates at almost every input (r6) would otherwise be found
  // deviating there again and again, and nothing past it explored.
  std::set<std::string> tolerated;
};

// The options from VGC_FUZZ_IMPL (read into a Route), VGC_FUZZ_TIMEOUT,
// VGC_FUZZ_VERSE_BONE_FORM, VGC_FUZZ_RESTART, VGC_FUZZ_HOST_CMD and
// VGC_FUZZ_HOST_LOG; spec empty when
// VGC_FUZZ_IMPL is unset.
LiveOptions live_options_from_environment();

// Opens o.route (a route that is not in process: exec: or verse:). With a
// restart command, the implementation's restart() runs it (bounded: 60 s)
// and logs in to the new host (retried for up to 15 s; restartable_host.h);
// with a host command, the host is started here and again by restart()
// (launched_host.h).
// nullptr with *error otherwise.
std::unique_ptr<Implementation> open_live_implementation(const LiveOptions& o, std::string* error);

// Whether a finding against `o` can be confirmed on a fresh instance: on a
// route vgc restarts by itself (exec: a new process), or with a restart
// command or a host command (verse:).
bool can_confirm_on_fresh_instance(const LiveOptions& o);

}  // namespace vgc::fuzz
