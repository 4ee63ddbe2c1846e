// process_cpu.h — CPU seconds of a process group, read from /proc (Linux).
//
// Spec: none of the Verse spec; docs/fuzzing.md "Soak" (a soak's budget in
// CPU seconds, --cpu-time).
//
// Rationale: a soak on a shared machine (a CI runner, a developer's box
// with builds running) is asked for "one CPU-hour of fuzzing", not "one
// hour of wall clock during which it got what was left". The kernel's
// rusage gives a process's CPU time only once it has been waited for, so a
// budget checked while libFuzzer runs reads /proc instead: each member of
// the group's own user + system time, plus what it has already collected
// from children it waited for (cutime, cstime). A fork-mode job counts
// while it runs (its own utime, stime) and after it ends (in the cutime of
// the process that waited for it), never twice.
#pragma once

#include <sys/types.h>

namespace vgc::fuzz {

// User + system CPU seconds of every live process whose process group is
// `pgid`, with the children each has waited for. 0 when /proc cannot be
// read or no process is in the group.
double process_group_cpu_seconds(pid_t pgid);

}  // namespace vgc::fuzz
