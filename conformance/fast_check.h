// fast_check.h — a command sequence checked cheaply, localized only on failure.
//
// Spec: the clauses check_step.h attributes (clause.h, 000 section 2.6).
//
// Rationale: the fuzz targets run thousands of short command sequences a
// second. Comparing both documents after every command (check_step) makes
// each input cost a snapshot and a derived document per command on both
// sides; almost every input agrees, so that work is wasted. The fast path
// runs the sequence on the reference and on the implementation comparing
// only what is cheap after each command (the call answered, the line was
// read, applied or rejected as the reference says, when the answer says it),
// and the documents once, at the end. Only when any of that differs does
// the exact path run: replay_program (replay_program.h) from a fresh node, step by
// step with check_step, which names the first divergent command and its
// clause exactly as `vgc certify` and `vgc replay` do.
//
// What the fast path cannot see: a difference in the documents that a later
// command hides again (an implementation that stores a wrong value which
// the next command overwrites). The sequence that stops at the hiding
// command's predecessor shows it, and a fuzzer produces such prefixes
// constantly; check_program_exact is the step-by-step check for callers
// that must not miss it.
#pragma once

#include <vector>

#include "command.h"
#include "implementation.h"
#include "replay_program.h"

namespace vgc {

struct FastCheckResult {
  ReplayResult replay;      // as replay_program reports it (no failure: agreed)
  bool exact_ran = false;   // the fast path saw a difference and the exact path ran
};

// Resets `sut` and runs `commands` on it and on the reference (see above).
// Never throws for anything the implementation does.
FastCheckResult check_program_fast(const std::vector<Command>& commands, Implementation& sut);

// The exact path alone: replay_program of `commands` (no capability request).
ReplayResult check_program_exact(const std::vector<Command>& commands, Implementation& sut);

}  // namespace vgc
