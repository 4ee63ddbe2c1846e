// program_checker.h — a program checked command by command against the
// reference, at the cost of what each command changed.
//
// Spec: the clauses check_step.h attributes (clause.h, 000 section 2.6);
// the `?digest` request of docs/adapters.md (document_digest.h).
//
// Rationale (issue 21): check_step compares both whole documents after every
// command, so a program of n commands costs n^2 (a 100,000-face mesh could
// not be replayed or certified). When the implementation offers `?digest`,
// ProgramChecker applies each command to its model in place, keeps the
// model's digest up to date from what the command changed (NodeDigest), and
// after each command compares only what is cheap: the call answered, the
// verdict, and the two digests. Anything else (a different verdict or
// digest, a `done` answer, a call that failed) is judged exactly as
// check_step judges it, at that same command, from the state before it
// (rebuilt from the commands the model applied: costs the program so far,
// only then). So every divergence check_step finds is found at the same
// command, with the same finding. After the last command, finish()
// compares the whole documents once, so that an implementation whose
// ?digest does not match what it prints cannot pass, and finds the command
// where they came to differ by bisection. Without `?digest` every step is
// check_step, as before, unless the caller allows sparse reading (below).
#pragma once

#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "check_step.h"
#include "command.h"
#include "document_diff.h"
#include "document_digest.h"
#include "implementation.h"
#include "node.h"

namespace vgc {

// Where a program's documents first differ: the failing step's result and
// its index in the program.
struct Localized {
  StepResult step;
  int index = -1;
};

class ProgramChecker {
 public:
  // The model starts as a fresh node: the caller resets `sut` (check_fresh).
  // follow_choices as check_step. use_digest false: every step is check_step.
  ProgramChecker(Implementation& sut, bool follow_choices, bool use_digest = true);

  // For long programs on a route without ?digest (a property at scale): the
  // documents are read only every so often (once the commands since the
  // last reading are as many as the model's elements, so reading costs the
  // program's length in all), the verdict after every command. A
  // difference found at a reading is localized by bisection: the
  // implementation is reset and a prefix of the program sent again
  // (log n times), and the first command whose prefix differs is judged by
  // check_step. A difference that a later command hides before the next
  // reading is not seen on such a route (with ?digest it is).
  void allow_sparse_reading();

  // Which steps judged wrong on an answer from a batch are judged again
  // alone (judge_alone): by default every one; the runner spares those
  // whose finding is in a clause already found so (they are taken out or
  // set aside, and decide nothing).
  void judge_again_alone(std::function<bool(const Finding&)> which) { judge_again_ = std::move(which); }

  // Runs `c` on the model and on the implementation and compares them (as
  // check_step). When derived_changed is not null it receives the derived
  // lines the reference's step changed (for exercised_clauses). A failure
  // found for an earlier command (sparse reading) says so: failed_at().
  StepResult step(const Command& c, std::vector<DerivedChange>* derived_changed = nullptr);
  // The index of the command the last failure belongs to (-1: the command
  // just stepped).
  int failed_at() const { return failed_at_; }

  // The reference's state after the steps so far.
  const Node& model() const { return model_; }
  // The commands the model applied (a followed choice with its id written).
  const std::vector<Command>& model_commands() const { return applied_; }
  // Whether the steps so far compared digests.
  bool used_digest() const { return digest_on_; }

  // The model goes back to its state before the last step (the caller took
  // that command out of the case); costs the program so far.
  void drop_last();

  // After the last step, when the documents were not compared after every
  // command (digests, sparse reading): compares the whole documents once,
  // and localizes a difference to its command (bisection). nullopt when
  // they agree or every step compared them. `sent` is the program as sent.
  std::optional<Localized> finish(const std::vector<Command>& sent);

  // After the last step, on a route that shows what a party that starts
  // watching now would be sent (Implementation::offers_late_view: the
  // Verse wire's late subscriber): that view against the model. Every
  // difference is considered, one per line key in the reference's order
  // (document_diff.h all_differences), each with its shape (attribution.h
  // difference_shape, and kRemovedSlotKept for a slot the model removed
  // with its element). `localize` (may be empty: always) is asked each
  // shape first: false spares that difference (a shape already localized
  // to a tolerated clause). A difference that is localized is localized
  // alone, the lines of every other difference left out on both sides
  // (check_step.h masked): by provenance (a prefix of the program from a
  // fresh node, the view read after it; first the command that last wrote
  // the model's differing line, checked), else by bisection, and the first
  // command whose prefix differs is judged by check_step on the late view,
  // so it is blamed by provenance like any other; its message starts with
  // kLateViewPrefix. `goes_on` (may be empty: never) is given each
  // localized difference with its shape: true means the caller tolerates it
  // (or only collects it), and the next difference is considered with the
  // checker as before; false returns it. nullopt when no difference is
  // returned: the view agrees, the route has none, the view could not be
  // read (that is no finding: the route's own session, not the
  // implementation), or every difference was spared or gone on from.
  std::optional<Localized> check_late_view(
      const std::vector<Command>& sent, const std::function<bool(const std::string& shape)>& localize = {},
      const std::function<bool(const std::string& shape, const Localized& l)>& goes_on = {});
  // The shape of the late view's last difference (empty: none seen).
  const std::string& late_shape() const { return late_shape_; }

 private:
  Node rebuild(std::size_t commands) const;  // a fresh node with the first `commands` of applied_
  // When `line` is a slot line the model held earlier in the case, and a
  // command removed that slot (its element deleted) while it held it, and
  // the model holds the line no more: that command's index in the case
  // (the last such); nullopt otherwise, and for a case of more than 2,000
  // commands (not searched).
  std::optional<std::size_t> removed_slot_at(const std::string& line) const;
  StepResult full_step(const Command& c, std::vector<DerivedChange>* derived_changed);
  // A step judged wrong on an answer from a batch (several commands before
  // one round trip: Implementation::last_apply_batched) is judged again
  // from a fresh node that was sent the program so far, with the command
  // sent on its own (one round trip, nothing told ahead): that judgement
  // is the step's, so a batch changes no verdict and no blame. `batched`
  // stands when the replay cannot be made.
  StepResult judge_alone(const Command& c, StepResult batched, Node* after);
  // Sends the first `n` of `sent` (the implementation told them ahead, so
  // a route may batch them); false when a call fails. Nothing is judged:
  // the caller compares the state after them.
  bool send_told(const std::vector<Command>& sent, std::size_t n);
  // A step whose answer is as the reference's (or `done`): the documents
  // are read only when due.
  StepResult sparse_step(const Command& c, const Answer& answer, StepResult result);
  // Whether the implementation's documents equal `model`'s; *call the
  // finding of a call that failed.
  bool documents_agree(const Node& model, std::optional<Finding>* call, std::string* difference);
  // The first command after `agreed` (a prefix length whose documents agree)
  // up to `differs` whose prefix differs, judged; nullopt when none does.
  std::optional<Localized> bisect(const std::vector<Command>& sent, std::size_t agreed, std::size_t differs);
  // Command `index` of `sent` judged by check_step after the prefix before
  // it, sent to a fresh implementation, agrees with the model; nullopt
  // when the prefix does not agree or the command shows no difference.
  std::optional<Localized> judge_at(const std::vector<Command>& sent, std::size_t index);
  // One difference `d` of the late view localized alone (check_late_view);
  // `stale` says where the model removed its slot (removed_slot_at).
  std::optional<Localized> localize_late(const std::vector<Command>& sent, const DocumentDifference& d,
                                         std::optional<std::size_t> stale);

  Implementation& sut_;
  bool follow_choices_;
  bool digest_on_;
  bool sparse_ = false;
  std::size_t agreed_ = 0;          // sparse: the prefix length the documents last agreed at
  std::vector<Command> sent_;       // sparse: the commands sent (for bisection)
  int failed_at_ = -1;
  Node model_;
  NodeDigest digest_;
  ChangeLog changes_;
  std::vector<Command> applied_;
  std::function<bool(const Finding&)> judge_again_;  // empty: every step
  std::vector<Command> as_sent_;    // full steps: the commands judged, as sent (judge_alone replays them)
  std::string late_shape_;
  std::optional<Finding> late_format_;
  // Line keys every comparison leaves out on both sides while the late
  // view localizes one of its differences (check_late_view); else empty.
  std::set<std::string> masked_;
};

// How a finding of the late view (ProgramChecker::check_late_view) begins.
inline constexpr const char* kLateViewPrefix = "late subscriber";
// The late view's one kind of difference within hidden state
// (Finding::difference): a slot the model removed with its element, shown
// again as it was on an element made at its id.
inline constexpr const char* kRemovedSlotKept = "a removed slot kept";
// ... and a slot shown at its layer's default where the model holds a value
// equal to it only as a number (-0.0 and 0: attribution.h
// blame_subscription_dump); and a subscription kept in two formats.
inline constexpr const char* kDefaultByValue = "a slot left out as the default by value";

}  // namespace vgc
