// implementation_choice.h — where the spec leaves a visible choice to the
// implementation, the model follows the choice the implementation made
// instead of reporting a divergence on every later step.
//
// Spec: README (r6 protocol facts): "An id of 0xFFFFFFFF (vertex, polygon)
// or 0xFFFF (layer, bone) in a create/set command asks the host to pick a
// free id" — any free id; which one is the implementation's choice. Clauses
// LAYER-ID-PICK-1 and VERTEX-ID-PICK-1 (IMPLEMENTATION-DEFINED: the suite's
// reading is the lowest free id) and BONE-ID-PICK-1 (SHOULD: 000 2.6.3, bone
// ids "typically" kept tight).
//
// Rationale: the reference picks the lowest free id. An implementation that
// picks another free id is within the spec; comparing it with the reference
// afterwards would report every later command on that element as a
// divergence. So when the implementation's snapshot is exactly the state the
// same command gives with another id that was free, the model adopts that id
// (the same command with the id written explicitly, which the reference
// applies alike), and the choice is reported once, as a note at the id
// clause's own level (an IMPLEMENTATION-DEFINED reading or a SHOULD), never
// as a failure of another clause. check_step does this when its caller
// passes follow_choices (a caller that starts the next step from the model
// check_step returns): run_certification and replay_program (so `vgc
// replay` and fuzz_differential too) do, through ProgramChecker, so there a
// different pick is the note, not a failure at the id clause. Not covered:
// a pick whose id changes the verdict (a bone whose picked id would close a
// cycle in one choice and not in the other), and the other visible choice
// the spec leaves, whether a
// deleted vertex's polygons go with it (POLY-VERTEX-DELETE-1), which the
// model cannot represent (its polygons always name live vertices).
#pragma once

#include <optional>
#include <string>

#include "finding.h"
#include "command.h"
#include "node.h"

namespace vgc {

struct ChoiceFollowed {
  Node model;    // the reference's state after the command, with the implementation's id
  Command applied;  // the command the model applied: the command with that id written
  Finding note;  // the id clause, what the suite's reading would have picked and what was picked
};

// `c` was applied by the reference (from `before`) and by the
// implementation, whose snapshot after it is `observed` and differs from the
// reference's. When `c` asks to pick a free id, exactly one id of that kind
// is in `observed` and not in `before`, it was free, and the same command
// with that id gives exactly `observed`: that state and the note. Otherwise
// nullopt (the difference is judged as usual).
std::optional<ChoiceFollowed> follow_implementation_choice(const Node& before, const Command& c,
                                                           const std::string& observed);

}  // namespace vgc
