// replay_program.h — replays a program from a fresh node as certify checks
// it: each command judged against the reference, the whole documents and
// the late view at the end, then the program's capability request.
//
// Spec: every clause a command's rules name (attribution.h); the fresh
// node's LAYER-BASE-1, CREASE-INITIAL-1 and STABLE-1; a capability's
// clauses (capability.h).
//
// Rationale: one replay for every caller that must see a program again as
// certify saw it: `vgc replay`, confirming a finding on a fresh instance
// (confirm_finding.h), isolating blame (isolate_blame.h), the fuzzers'
// minimisation and differential check, and the mesh path.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "finding.h"
#include "implementation.h"
#include "program.h"

namespace vgc {

// Replays `program` from a fresh node, then repeats its capability request
// if it has one, as certify checks it: the first finding, if any, and the
// index of the command it was found on (-1 for the fresh-node check,
// commands.size() for the capability request). A request that cannot be
// judged (sut does not claim the capability, no check is registered for
// it, or the check's oracle cannot be asked about this state:
// FindingStatus::NotJudged) is no finding: `not_judged` says why, naming
// the clause(s). Never
// throws for anything the implementation does.
struct ReplayResult {
  std::optional<Finding> failure;
  int failed_at = -1;
  std::vector<Finding> notes;
  std::string not_judged;  // empty, or why program.request could not be judged
  // Other failures the program's end shows besides `failure` (the late
  // view's: a document difference and a subscription kept in two formats;
  // certify reports whichever its tolerated clauses leave first).
  std::vector<Finding> also_failed;
};
ReplayResult replay_program(const Program& program, Implementation& sut);

}  // namespace vgc
