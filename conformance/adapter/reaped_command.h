// reaped_command.h — a shell command run to its end under the reaper
// (reaped_process.h), its output captured: what popen() and std::system()
// did for the fuzz campaign (minimisation steps, corpus merges,
// llvm-symbolizer, re-running a crash), without leaving anything behind
// when vgc is killed meanwhile.
//
// Spec: none (CI practice: nothing the suite starts may outlive it; issue 29
// item 5; docs/ci.md "Nothing outlives vgc").
//
// Rationale: popen() and system() fork a /bin/sh that stays in vgc's
// process group and is reparented to PID 1 when vgc dies, with whatever it
// started. Under the reaper the command, and every process it starts, ends
// with vgc however vgc ends; while vgc lives the command runs to its own
// end, as with popen (bound it with coreutils `timeout` where it may hang).
#pragma once

#include <cstddef>
#include <string>

namespace vgc {

// Runs `/bin/sh -c command`, stdin from /dev/null and stderr this process's;
// its stdout into *output (the first output_limit bytes kept, the rest read
// and dropped) or, when output is null, this process's stdout. Waits for the
// command's end; returns its wait status (as pclose and system do), or -1
// when it could not be started.
int run_reaped_shell(const std::string& command, std::string* output,
                     std::size_t output_limit = std::size_t{64} << 20);

}  // namespace vgc
