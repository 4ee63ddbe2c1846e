// report_finding.h — how a fuzz target reports what it found.
//
// Spec: docs/fuzzing.md "Counterexamples".
//
// Rationale: a finding must be replayable by someone who has never seen the
// fuzzer. report_finding prints one line "vgc-fuzz: FINDING in <target>:
// <what>" (the line `vgc fuzz` deduplicates crashes by), then the commands
// run so far as a command file (reference/node/command_text.h), which
// `vgc apply FILE` runs, and then aborts, which libFuzzer records as a crash
// and saves the input.
#pragma once

#include <string>
#include <vector>

#include "command.h"

namespace vgc::fuzz {

[[noreturn]] void report_finding(const char* target, const std::string& what,
                                 const std::vector<Command>& commands_so_far);

}  // namespace vgc::fuzz
