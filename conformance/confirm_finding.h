// confirm_finding.h — a finding of any kind (a crash, a timeout, a
// protocol error, a wrong verdict, reason or document) is reported against
// a clause only when its counterexample does it again on a fresh instance
// of the implementation.
//
// Spec: STABLE-1 ("An implementation answers every call": it neither
// crashes nor hangs on any command sequence) and ACCEPT-1 (answers within
// the protocol); the clause catalog (clause.h).
//
// Rationale: an implementation that fails after so many commands since it
// started (a leak, a counter, a store that rejects everything once it is
// full) fails on whatever command happens to be running then; blaming that command's clause is wrong, and the shrunk
// "counterexample" replays as agreeing with the reference. So before such a
// finding is reported, its program runs again on a new instance
// (Implementation::restart). If it fails the same way, it stands as found.
// If not, it is a finding that depends on the implementation's history: it
// is reported on STABLE-1 (ACCEPT-1 for a protocol error), never on the
// clause of the command that was running, and its program is the command
// history since the instance started (HistoryRecorder), reduced by cases,
// then by commands, to a sequence that fails a fresh instance the same way.
// (ClusterFuzz likewise marks a crash it cannot reproduce as unreliable
// instead of filing it.) The reduction is bounded in attempts and time; the
// finding says how far it got.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "forwarding_implementation.h"
#include "implementation.h"
#include "program.h"

namespace vgc {

// Forwards every call to the implementation and keeps the commands sent to
// the instance running now since it started, one list per case (a case
// starts at each reset()); a new instance (Implementation::instance())
// starts a new history.
class HistoryRecorder final : public ForwardingImplementation {
 public:
  explicit HistoryRecorder(Implementation& sut)
      : ForwardingImplementation(&sut), sut_(sut), instance_(sut.instance()) {}
  Answer reset() override;
  Answer restart() override;
  Answer apply(const Command& c) override;

  // The commands since the running instance started, case by case.
  const std::vector<std::vector<Command>>& history() const { return history_; }

 private:
  void follow_instance();
  Implementation& sut_;
  std::uint64_t instance_;
  std::vector<std::vector<Command>> history_;
};

// A crash, a timeout or a protocol error (a Fail of ACCEPT-1 whose message
// starts "protocol-error"): what confirmation is for.
bool is_call_failure(const Finding& f);

// Whether `program` fails a fresh instance (restarted) with the same kind
// of failure as `f` (finding_kind), on whatever command.
bool fails_fresh(Implementation& sut, const Finding& f, const Program& program);

// Whether `program` on a fresh instance shows the SHOULD-level note (or
// followed choice) `note` again, at its clause.
bool note_reproduces_fresh(Implementation& sut, const Finding& note, const Program& program);

// Whether `program` fails a fresh instance with `f`'s clause and status.
bool reproduces_fresh(Implementation& sut, const Finding& f, const Program& program);

// "crash", "timeout", "protocol-error", "hidden-state" (what a party that
// starts watching late is sent differs from what those that watched all
// along were sent and the model holds: program_checker.h check_late_view)
// or "wrong-answer" (a wrong verdict,
// reason or document): the kind of failure `f` is, or, for a finding that
// depends on the history, the kind it is about. Kinds are what
// confirmation compares: a history's reproducer must fail a fresh instance
// with the same kind.
std::string finding_kind(const Finding& f);
// The same as a value (finding.h FindingKind), so that a caller decides
// with a switch or a comparison, not by the printed word: read from the
// finding's status and the fields set where it was made (Finding::late_view,
// Finding::history_kind), never from its message.
FindingKind finding_kind_of(const Finding& f);

// Whether findings of `f`'s kind are told apart by their difference
// (Finding::difference): hidden state, where one clause can hide two
// behaviours of a host from its watchers (r6's copied XYZ positions and
// its kept values of a deleted element, both LAYER-DEFAULT-1).
bool kind_tells_differences_apart(const Finding& f);

// How bad a kind of failure is: a wrong answer 0, hidden state 1 (the
// watchers were told something else than is stored: worse than a state
// every watcher sees), a protocol error 2, a time-out 3, a crash (a
// sanitizer report included) 4. A finding of one
// kind in a clause hides nothing worse in it (property_run.cpp tolerates a
// clause only up to the worst kind found there), and a clause's outcome
// shows its worst finding (clause_status.h prefer_finding).
int finding_severity(const Finding& f);

// Whether `f` is a finding that depends on the implementation's history
// (confirm_call_failure made it: Finding::history_kind is set).
bool depends_on_history(const Finding& f);

// Confirms the finding `pf` (any kind but NotJudged), found while
// the instance had been sent `history` since it started (the failing case
// last). Returns true when pf's program fails a fresh instance with the same
// clause and status: pf is left as it is. Also true when no fresh instance
// could be started at all (a host that stopped answering): pf stands where
// it was seen, its message ending "[not confirmed on a fresh instance: ...]",
// since nothing showed that it needs a history. Otherwise rewrites pf as a finding
// that depends on the implementation's history (above) and returns false.
// Stops reducing at `deadline` or after `max_attempts` restarts.
bool confirm_call_failure(Implementation& sut, PropertyFinding* pf, const std::vector<std::vector<Command>>& history,
                          std::chrono::steady_clock::time_point deadline, int max_attempts = 80);

// What `vgc replay` shows for a history reproducer (Program::history_kind):
// `seen`, the failure its commands brought about at command `failed_at`,
// blamed as certify blamed it (STABLE-1, ACCEPT-1 for a protocol error)
// when it is of the program's kind; nullopt otherwise (a program that is no
// reproducer, or a failure of another kind, which stands as found).
std::optional<Finding> blame_as_history(const Program& program, const Finding& seen, std::size_t failed_at);

}  // namespace vgc
