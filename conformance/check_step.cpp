// check_step.cpp — see check_step.h.
#include "check_step.h"

#include "attribution.h"
#include "clause.h"
#include "command_text.h"
#include "derived_document.h"
#include "document_diff.h"
#include "implementation_choice.h"
#include "snapshot.h"

namespace vgc {
namespace {

FindingStatus status_of(CallStatus s) {
  switch (s) {
    case CallStatus::Crash: return FindingStatus::Crash;
    case CallStatus::Timeout: return FindingStatus::Timeout;
    default: return FindingStatus::Fail;
  }
}

}  // namespace

const char* finding_status_name(FindingStatus s) {
  switch (s) {
    case FindingStatus::Fail: return "fail";
    case FindingStatus::Crash: return "crash";
    case FindingStatus::Timeout: return "timeout";
    case FindingStatus::NotJudged: return "not-judged";
  }
  return "?";
}

std::optional<FindingStatus> finding_status_named(std::string_view name) {
  for (FindingStatus s : {FindingStatus::Fail, FindingStatus::Crash, FindingStatus::Timeout, FindingStatus::NotJudged})
    if (name == finding_status_name(s)) return s;
  return std::nullopt;
}

const char* finding_kind_name(FindingKind k) {
  switch (k) {
    case FindingKind::WrongAnswer: return "wrong-answer";
    case FindingKind::HiddenState: return "hidden-state";
    case FindingKind::ProtocolError: return "protocol-error";
    case FindingKind::Timeout: return "timeout";
    case FindingKind::Crash: return "crash";
  }
  return "wrong-answer";
}

std::optional<FindingKind> finding_kind_named(std::string_view name) {
  for (FindingKind k : {FindingKind::WrongAnswer, FindingKind::HiddenState, FindingKind::ProtocolError,
                        FindingKind::Timeout, FindingKind::Crash})
    if (name == finding_kind_name(k)) return k;
  return std::nullopt;
}

Finding call_failure(std::string_view clause, CallStatus s, const std::string& what, const std::string& detail) {
  Finding f;
  f.status = status_of(s);
  f.clause = s == CallStatus::ProtocolError ? "ACCEPT-1" : std::string(clause);
  f.protocol_error = s == CallStatus::ProtocolError;
  f.message = std::string(call_status_name(s)) + " while " + what + (detail.empty() ? "" : ": " + detail);
  return f;
}

std::optional<Finding> reason_note(const Command& c, Reason expected, const Answer& answer) {
  if (!answer.verdict_reported || answer.applied || expected == Reason::Ok || answer.reason == reason_name(expected))
    return std::nullopt;
  Finding f;
  f.clause = "REASON-1";
  f.message = "`" + print_command(c) + "`: expected rejected " + std::string(reason_name(expected)) +
              ", observed rejected " + answer.reason;
  return f;
}

StepResult check_step(const Node& before, const Command& c, Implementation& sut, Node* after,
                      bool follow_choices, const std::set<std::string>* masked) {
  StepResult result;
  *after = before;
  result.expected = after->apply(c, &result.rules);
  const Answer answer = sut.apply(c);
  return judge_step(before, c, answer, std::move(result), sut, after, follow_choices, masked);
}

namespace {

// What judge_step's steps share: the step as both sides took it, and what
// has been read of the implementation so far. Each step returns true when
// it decided the step (result.failure or result.not_judged set, or a
// document could not be read), and judge_step then stops.
struct Judging {
  const Node& before;
  const Command& c;
  const Answer& answer;
  Implementation& sut;
  Node* after;  // the reference's state after c; the implementation's choice with follow_choices
  bool follow_choices;
  StepResult result;
  std::string text;         // c as a command line
  RouteLimits limits;       // what the route carries (read once the answer is judged readable)
  Document snap;            // the implementation's snapshot after c, once read
  bool applied = false;     // the implementation's verdict: reported, or read from its state
  std::string observed_answer;
  const std::set<std::string>* masked = nullptr;  // line keys left out on both sides (check_step.h)

  // A route that cannot observe subscriptions (RouteLimits) compares the
  // snapshot's subscription column as "-" on both sides; masked lines are
  // left out.
  std::string comparable(std::string t) const {
    if (masked) t = without_keys(t, *masked);
    return limits.subscriptions ? t : without_subscriptions(t);
  }
};

// No answer (crash, timeout), or one outside the contract (ACCEPT-1): the
// call failed, blamed on the rules the command applies.
bool call_failed(Judging& j) {
  if (j.answer.status == CallStatus::Ok) return false;
  const Blame blame = blame_verdict(j.c, j.result.expected, j.result.rules);
  j.result.failure = call_failure(blame.clause, j.answer.status, "applying `" + j.text + "`", j.answer.detail);
  if (j.answer.status != CallStatus::ProtocolError) {
    j.result.failure->rules = blame.rules;
    j.result.failure->message += ". " + blame.explanation;
  }
  return true;
}

// The route cannot carry the command: both sides stay at `before`, nothing
// is judged.
bool not_sent(Judging& j) {
  if (!j.answer.not_sent) return false;
  *j.after = j.before;
  j.result.not_judged = "`" + j.text + "` was not sent: " + j.answer.detail;
  return true;
}

// It answered "error": it could not read a canonical command line (ACCEPT-1).
bool unreadable(Judging& j) {
  if (!j.answer.malformed) return false;
  Finding f;
  f.clause = "ACCEPT-1";
  f.message = "`" + j.text + "`: the implementation could not read this canonical command line: " + j.answer.detail;
  j.result.failure = f;
  return true;
}

// The verdict as the implementation reported it (ok / rejected REASON).
void take_reported_verdict(Judging& j) {
  j.limits = j.sut.limits();
  j.applied = j.answer.applied;
  j.observed_answer = j.answer.applied ? "ok" : "rejected " + j.answer.reason;
  j.result.verdict_reported = j.answer.verdict_reported;
}

// A `done` answer (Answer::verdict_reported false) says nothing about the
// verdict, so it is read from the state: the snapshot after the command
// against the one before it. The implementation held the state `before`
// (the precondition, checked by the previous step), so its snapshot before
// is print_snapshot(before) as diff_documents compares it, and no extra call
// is needed; the snapshot after is the one compared below anyway. Unchanged
// means dropped (rejected), changed means applied, except that a command
// the reference applies without changing anything (writing the value a slot
// already holds) is consistent with either. What the implementation told
// others about the command (a host's broadcast to its subscribers) is its
// verdict too: announced means applied, whatever the state shows. true when
// the snapshot could not be read (STABLE-1).
bool read_verdict_from_state(Judging& j) {
  if (j.answer.verdict_reported) return false;
  const Reason expected = j.result.expected;
  j.snap = j.sut.snapshot();
  if (j.snap.status != CallStatus::Ok) {
    j.result.failure =
        call_failure("STABLE-1", j.snap.status, "reading the snapshot after `" + j.text + "`", j.snap.detail);
    return true;
  }
  const std::string before_text = j.comparable(print_snapshot(j.before));
  const bool changed = diff_documents(before_text, j.comparable(j.snap.text)).has_value();
  const bool reference_changed = expected == Reason::Ok && j.comparable(print_snapshot(*j.after)) != before_text;
  const bool announced = !j.answer.broadcast.empty();
  j.applied = changed || announced || (expected == Reason::Ok && !reference_changed);
  j.result.implementation_unchanged = !changed;
  j.observed_answer = changed     ? "done, and the state changed (applied)"
                      : announced ? "done, and the state is unchanged but the host sent its subscribers `" +
                                        j.answer.broadcast + "` for it (applied)"
                                  : "done, and the state is unchanged (dropped)";
  return false;
}

// Applied where the reference rejects, or rejected where it applies: a
// finding at the clause of the rule that decided the reference's verdict
// (attribution.h, blame_verdict).
bool verdict_differs(Judging& j) {
  const Reason expected = j.result.expected;
  if (j.applied == (expected == Reason::Ok)) return false;
  const std::string expected_answer =
      expected == Reason::Ok ? "ok" : "rejected " + std::string(reason_name(expected));
  Finding f;
  const Blame blame = blame_verdict(j.c, expected, j.result.rules);
  f.clause = blame.clause;
  f.rules = blame.rules;
  f.message = "`" + j.text + "`: expected " + expected_answer + ", observed " + j.observed_answer + ". " +
              blame.explanation;
  j.result.failure = f;
  return true;
}

// The snapshot after the command (already read for a `done` answer); true
// when it could not be read (STABLE-1).
bool snapshot_unread(Judging& j) {
  if (j.answer.verdict_reported) j.snap = j.sut.snapshot();
  if (j.snap.status == CallStatus::Ok) return false;
  j.result.failure =
      call_failure("STABLE-1", j.snap.status, "reading the snapshot after `" + j.text + "`", j.snap.detail);
  return true;
}

// The snapshot against the model's: a choice the spec leaves to the
// implementation (which free id it picked) is followed by the model and
// noted at its clause (follow_choices, implementation_choice.h); any other
// difference is a finding blamed on the rule that wrote the line
// (attribution.h, blame_snapshot).
bool snapshot_differs(Judging& j) {
  const Reason expected = j.result.expected;
  std::optional<DocumentDifference> d =
      diff_documents(j.comparable(print_snapshot(*j.after)), j.comparable(j.snap.text));
  if (d && expected == Reason::Ok && j.follow_choices) {
    if (auto choice = follow_implementation_choice(j.before, j.c, j.snap.text)) {
      *j.after = std::move(choice->model);
      j.result.model_command = std::move(choice->applied);
      j.result.notes.push_back(std::move(choice->note));
      d.reset();
    }
  }
  if (!d) return false;
  Finding f;
  const Blame blame =
      blame_snapshot(j.before, *j.after, expected, j.result.rules, *d, j.comparable(j.snap.text));
  f.clause = blame.clause;
  f.rules = blame.rules;
  f.message =
      "after `" + j.text + "` (" + j.observed_answer + "), snapshot: " + d->describe() + ". " + blame.explanation;
  f.shown_by = "snapshot";
  f.observed_document = j.snap.text;
  f.expected_line = d->expected_line;
  f.observed_line = d->observed_line;
  j.result.failure = f;
  return true;
}

// The derived document against the model's, when the route carries one
// (RouteLimits::derived): a difference after an applied command is blamed
// on the derived rule that decided the line (attribution.h, blame_derived),
// after a rejected one on ATOMIC-1 (a rejected command changes nothing).
void judge_derived(Judging& j) {
  j.result.derived_judged = j.limits.derived;
  if (!j.limits.derived) return;  // the route carries no derived document
  const Document derived = j.sut.derived();
  if (derived.status != CallStatus::Ok) {
    j.result.failure = call_failure("STABLE-1", derived.status,
                                    "reading the derived document after `" + j.text + "`", derived.detail);
    return;
  }
  if (auto d = diff_documents(print_derived(*j.after), derived.text)) {
    Finding f;
    f.message = "after `" + j.text + "` (" + j.observed_answer + "), derived: " + d->describe();
    if (j.result.expected == Reason::Ok) {
      const DerivedBlame blame = blame_derived(*j.after, *d);
      f.clause = blame.clause;
      f.message += ". " + blame.explanation;
    } else {
      f.clause = "ATOMIC-1";
    }
    f.shown_by = "derived";
    f.observed_document = derived.text;
    f.expected_line = d->expected_line;
    f.observed_line = d->observed_line;
    j.result.failure = f;
  }
}

// The step in check_step.h's order: did the call answer, was the command
// carried and read; (1) the verdict, (2) the reason code, (3) the snapshot,
// (4) the derived document. The first step that decides ends it (true).
bool decide_step(Judging& j) {
  if (call_failed(j) || not_sent(j) || unreadable(j)) return true;
  take_reported_verdict(j);
  if (read_verdict_from_state(j) || verdict_differs(j)) return true;
  if (auto note = reason_note(j.c, j.result.expected, j.answer)) j.result.notes.push_back(std::move(*note));
  if (snapshot_unread(j) || snapshot_differs(j)) return true;
  judge_derived(j);
  return false;
}

// Every finding of the step carries what the host sent back after it, as
// the route's mirror applied it (Answer::host_sent; the Verse wire).
void attach_host_sent(const Answer& answer, StepResult* result) {
  if (!answer.host_sent_seen) return;
  auto stamp = [&answer](Finding& f) {
    f.host_sent_seen = true;
    f.host_sent = answer.host_sent;
    f.host_sent_count = answer.host_sent_count;
  };
  if (result->failure) stamp(*result->failure);
  for (Finding& note : result->notes) stamp(note);
}

}  // namespace

StepResult judge_step(const Node& before, const Command& c, const Answer& answer, StepResult result,
                      Implementation& sut, Node* after, bool follow_choices, const std::set<std::string>* masked) {
  Judging j{before, c, answer, sut, after, follow_choices, std::move(result), print_command(c), {}, {}, false, {},
            masked && !masked->empty() ? masked : nullptr};
  decide_step(j);
  attach_host_sent(answer, &j.result);
  return std::move(j.result);
}

std::optional<Finding> check_fresh_state(Implementation& sut) {
  const Node fresh;
  const auto differs = [&fresh](const char* document, const DocumentDifference& d, bool derived) {
    const Blame blame = blame_fresh(fresh, d, derived);
    Finding f{blame.clause, FindingStatus::Fail, "fresh node " + std::string(document) + ": " + d.describe() + ". " +
                                                     blame.explanation};
    f.rules = blame.rules;
    return f;
  };
  const Document snap = sut.snapshot();
  if (snap.status != CallStatus::Ok)
    return call_failure("STABLE-1", snap.status, "reading the snapshot of a fresh node", snap.detail);
  const RouteLimits limits = sut.limits();
  const std::string expected_text = print_snapshot(fresh);
  if (auto d = limits.subscriptions ? diff_documents(expected_text, snap.text)
                                    : diff_documents(without_subscriptions(expected_text),
                                                     without_subscriptions(snap.text)))
    return differs("snapshot", *d, false);
  if (!limits.derived) return std::nullopt;  // the route carries no derived document
  const Document derived = sut.derived();
  if (derived.status != CallStatus::Ok)
    return call_failure("STABLE-1", derived.status, "reading the derived document of a fresh node", derived.detail);
  if (auto d = diff_documents(print_derived(fresh), derived.text)) return differs("derived", *d, true);
  return std::nullopt;
}

std::optional<Finding> reset_and_check_fresh(Implementation& sut) {
  const Answer a = sut.reset();
  if (a.status != CallStatus::Ok) return call_failure("STABLE-1", a.status, "resetting to a fresh node", a.detail);
  return check_fresh_state(sut);
}

}  // namespace vgc
