// check_step.h — one command, run on the reference and on an implementation,
// compared, and any difference attributed to a clause.
//
// Spec: every clause of the catalog (clause.h); attribution.h says which.
// README (r6 wire facts): "Hosts on the wire send no acknowledgement and no
// error: a command is applied ... or dropped silently" — hence `done` answers.
//
// Rationale: this is the model-versus-implementation comparison that every
// property (rc::state commands, property.h) and `vgc replay` share, so a
// counterexample replays exactly as it failed. After each command it
// compares (1) applied or rejected (read from the state when the answer is
// `done`), (2) the reason code (SHOULD level),
// (3) the snapshot, (4) the derived document. The first MUST-level
// difference ends the check; SHOULD-level ones are returned as notes, and,
// when the caller asks to follow choices, so is a free id the implementation
// picked where the reference picks another (implementation_choice.h).
#pragma once

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "command.h"
#include "finding.h"
#include "implementation.h"
#include "node.h"

namespace vgc {

struct StepResult {
  std::optional<Finding> failure;  // a MUST or IMPLEMENTATION-DEFINED clause broken
  // SHOULD clauses broken, and implementation choices the model followed
  // (follow_choices, implementation_choice.h) at their clause's level; the
  // check goes on.
  std::vector<Finding> notes;
  Reason expected = Reason::Ok;  // the reference's verdict on the command
  RuleTrace rules;               // the rules the reference applied to it (rule.h)
  // false when the implementation answered `done` (Answer::verdict_reported):
  // applied or rejected was read from its state, and REASON-1 (reason codes)
  // could not be judged on this step: the runner reports it "not-applicable"
  // when no step of a run judged it.
  bool verdict_reported = true;
  // false when the route carries no derived document (RouteLimits::derived):
  // the step was judged on its verdict and snapshot only.
  bool derived_judged = true;
  // Set when the implementation's state after the command was read and is
  // the state before it (it dropped the command): the runner can then take
  // a tolerated command out of a case without resetting (property_case.cpp, take_step_out).
  bool implementation_unchanged = false;
  // Set when the model followed an implementation's choice (follow_choices):
  // the command the model applied instead (the id written).
  std::optional<Command> model_command;
  // Set when the route could not carry the command (Answer::not_sent):
  // nothing was judged, *after is `before` (neither side changed), and the
  // runner counts nothing for the step. Says why.
  std::string not_judged;
};

// The finding for a call that did not answer (crash, timeout) or answered
// outside the contract (ProtocolError, always ACCEPT-1): `clause` is the
// rule of what was asked, `what` says what was being done ("applying ...").
Finding call_failure(std::string_view clause, CallStatus s, const std::string& what, const std::string& detail);

// Applies `c` to a copy of `before` and to `sut` (which must hold the same
// state as `before`), and compares. On return *after holds the reference's
// state after `c`. Never throws for any command or any answer.
// An answer `done` (verdict not reported, docs/adapters.md) is judged from
// the state: the implementation's snapshot after `c` identical to `before`'s
// means dropped (rejected), otherwise applied; then as usual, except that a
// command the reference applies without changing its own snapshot is
// consistent with an unchanged state, and no reason is compared. An
// unchanged state with a broadcast (Answer::broadcast: the host announced
// the command's effect to its subscribers) means applied. Same calls
// as an ok/rejected answer: apply, snapshot, derived.
//
// The route's limits (Implementation::limits) apply: with no derived
// document, derived() is not called and the derived comparison is skipped
// (StepResult::derived_judged false); with no observable subscriptions, the
// snapshots are compared with their subscription column as "-".
//
// follow_choices: where the spec leaves the implementation a visible choice
// (which free id a pick takes; implementation_choice.h) and the
// implementation made another one than the reference, *after is the state
// with the implementation's choice and the choice is a note at its clause,
// not a failure. Only for a caller that starts the next step from *after
// (otherwise the next step would diverge at another clause); by default a
// different choice is a failure, as before.
//
// masked: line keys (document_diff.h line_key) left out of every snapshot
// comparison on both sides, the verdict read from the state included: a
// caller that localizes one difference of several (the late view,
// program_checker.h) leaves out the lines of the others. nullptr: none.
StepResult check_step(const Node& before, const Command& c, Implementation& sut, Node* after,
                      bool follow_choices = false, const std::set<std::string>* masked = nullptr);

// The REASON-1 note for a rejection the implementation reported with
// another reason than the reference's `expected`; nullopt when the reasons
// agree or the command was not rejected by both.
std::optional<Finding> reason_note(const Command& c, Reason expected, const Answer& answer);

// check_step after both sides applied `c`: `result` holds the reference's
// verdict and rules (expected, rules) and nothing else, *after the
// reference's state after `c` (from `before`), `answer` what the
// implementation answered to `c`. For a caller that applied `c` itself.
StepResult judge_step(const Node& before, const Command& c, const Answer& answer, StepResult result,
                      Implementation& sut, Node* after, bool follow_choices,
                      const std::set<std::string>* masked = nullptr);

// Compares the implementation's documents with a fresh node's, with no
// command involved (used after reset). nullopt when equal; a difference is
// blamed on the fresh-node rule of its line (attribution.h, blame_fresh):
// node.base_layers (LAYER-BASE-1) or node.initial_creases (CREASE-INITIAL-1).
std::optional<Finding> check_fresh_state(Implementation& sut);

// Resets `sut` to a fresh node and compares it with the reference's fresh
// node (check_fresh_state); a reset that fails is a STABLE-1 call failure.
std::optional<Finding> reset_and_check_fresh(Implementation& sut);

}  // namespace vgc
