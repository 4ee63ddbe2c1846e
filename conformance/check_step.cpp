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

Finding call_failure(std::string_view clause, CallStatus s, const std::string& what, const std::string& detail) {
  Finding f;
  f.status = status_of(s);
  f.clause = s == CallStatus::ProtocolError ? "ACCEPT-1" : std::string(clause);
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
                      bool follow_choices) {
  StepResult result;
  *after = before;
  result.expected = after->apply(c, &result.rules);
  const Answer answer = sut.apply(c);
  return judge_step(before, c, answer, std::move(result), sut, after, follow_choices);
}

StepResult judge_step(const Node& before, const Command& c, const Answer& answer, StepResult result,
                      Implementation& sut, Node* after, bool follow_choices) {
  const Reason expected = result.expected;
  const std::string text = print_command(c);
  if (answer.status != CallStatus::Ok) {
    const Blame blame = blame_verdict(c, expected, result.rules);
    result.failure = call_failure(blame.clause, answer.status, "applying `" + text + "`", answer.detail);
    if (answer.status != CallStatus::ProtocolError) {
      result.failure->rules = blame.rules;
      result.failure->message += ". " + blame.explanation;
    }
    return result;
  }
  if (answer.not_sent) {  // the route cannot carry it: both sides stay at `before`
    *after = before;
    result.not_judged = "`" + text + "` was not sent: " + answer.detail;
    return result;
  }
  if (answer.malformed) {  // it answered "error": it could not read a canonical command line
    Finding f;
    f.clause = "ACCEPT-1";
    f.message = "`" + text + "`: the implementation could not read this canonical command line: " + answer.detail;
    result.failure = f;
    return result;
  }
  const std::string expected_answer =
      expected == Reason::Ok ? "ok" : "rejected " + std::string(reason_name(expected));

  // A `done` answer (Answer::verdict_reported false) says nothing about the
  // verdict, so it is read from the state: the snapshot after the command
  // against the one before it. The implementation held the state `before`
  // (the precondition, checked by the previous step), so its snapshot
  // before is print_snapshot(before) as diff_documents compares it, and no
  // extra call is needed; the snapshot after is the one compared below
  // anyway. Unchanged means dropped (rejected), changed means applied,
  // except that a command the reference applies without changing anything
  // (writing the value a slot already holds) is consistent with either.
  // A route that cannot observe subscriptions (RouteLimits) compares the
  // snapshot's subscription column as "-" on both sides.
  const RouteLimits limits = sut.limits();
  const auto comparable = [&limits](std::string text) {
    return limits.subscriptions ? text : without_subscriptions(text);
  };
  Document snap;
  bool applied = answer.applied;
  std::string observed_answer = answer.applied ? "ok" : "rejected " + answer.reason;
  result.verdict_reported = answer.verdict_reported;
  if (!answer.verdict_reported) {
    snap = sut.snapshot();
    if (snap.status != CallStatus::Ok) {
      result.failure = call_failure("STABLE-1", snap.status, "reading the snapshot after `" + text + "`", snap.detail);
      return result;
    }
    const std::string before_text = comparable(print_snapshot(before));
    const bool changed = diff_documents(before_text, comparable(snap.text)).has_value();
    const bool reference_changed = expected == Reason::Ok && comparable(print_snapshot(*after)) != before_text;
    // What the implementation told others about the command (a host's
    // broadcast to its subscribers) is its verdict too: announced means
    // applied, whatever the state shows.
    const bool announced = !answer.broadcast.empty();
    applied = changed || announced || (expected == Reason::Ok && !reference_changed);
    result.implementation_unchanged = !changed;
    observed_answer = changed     ? "done, and the state changed (applied)"
                      : announced ? "done, and the state is unchanged but the host sent its subscribers `" +
                                        answer.broadcast + "` for it (applied)"
                                  : "done, and the state is unchanged (dropped)";
  }
  if (applied != (expected == Reason::Ok)) {
    Finding f;
    const Blame blame = blame_verdict(c, expected, result.rules);
    f.clause = blame.clause;
    f.rules = blame.rules;
    f.message = "`" + text + "`: expected " + expected_answer + ", observed " + observed_answer + ". " +
                blame.explanation;
    result.failure = f;
    return result;
  }
  if (auto note = reason_note(c, expected, answer)) result.notes.push_back(std::move(*note));

  if (answer.verdict_reported) snap = sut.snapshot();
  if (snap.status != CallStatus::Ok) {
    result.failure = call_failure("STABLE-1", snap.status, "reading the snapshot after `" + text + "`", snap.detail);
    return result;
  }
  std::optional<DocumentDifference> d = diff_documents(comparable(print_snapshot(*after)), comparable(snap.text));
  if (d && expected == Reason::Ok && follow_choices) {
    // A choice the spec leaves to the implementation (which free id it
    // picked): the model follows it, and the choice is a note at its clause.
    if (auto choice = follow_implementation_choice(before, c, snap.text)) {
      *after = std::move(choice->model);
      result.model_command = std::move(choice->applied);
      result.notes.push_back(std::move(choice->note));
      d.reset();
    }
  }
  if (d) {
    Finding f;
    const Blame blame = blame_snapshot(before, *after, expected, result.rules, *d, comparable(snap.text));
    f.clause = blame.clause;
    f.rules = blame.rules;
    f.message = "after `" + text + "` (" + observed_answer + "), snapshot: " + d->describe() + ". " + blame.explanation;
    f.shown_by = "snapshot";
    f.observed_document = snap.text;
    f.expected_line = d->expected_line;
    f.observed_line = d->observed_line;
    result.failure = f;
    return result;
  }
  result.derived_judged = limits.derived;
  if (!limits.derived) return result;  // the route carries no derived document
  const Document derived = sut.derived();
  if (derived.status != CallStatus::Ok) {
    result.failure = call_failure("STABLE-1", derived.status, "reading the derived document after `" + text + "`",
                                  derived.detail);
    return result;
  }
  if (auto d = diff_documents(print_derived(*after), derived.text)) {
    Finding f;
    const std::string& line = d->expected_line.empty() ? d->observed_line : d->expected_line;
    f.clause = expected == Reason::Ok ? std::string(clause_for_derived(*after, *d, bone_id_of(line)))
                                      : "ATOMIC-1";
    f.message = "after `" + text + "` (" + observed_answer + "), derived: " + d->describe();
    f.shown_by = "derived";
    f.observed_document = derived.text;
    f.expected_line = d->expected_line;
    f.observed_line = d->observed_line;
    result.failure = f;
  }
  return result;
}

std::optional<Finding> check_state(const Node& expected, Implementation& sut, const char* clause_if_different) {
  const Document snap = sut.snapshot();
  if (snap.status != CallStatus::Ok)
    return call_failure("STABLE-1", snap.status, "reading the snapshot of a fresh node", snap.detail);
  const RouteLimits limits = sut.limits();
  const std::string expected_text = print_snapshot(expected);
  if (auto d = limits.subscriptions ? diff_documents(expected_text, snap.text)
                                    : diff_documents(without_subscriptions(expected_text),
                                                     without_subscriptions(snap.text)))
    return Finding{clause_if_different, FindingStatus::Fail, "fresh node snapshot: " + d->describe()};
  if (!limits.derived) return std::nullopt;  // the route carries no derived document
  const Document derived = sut.derived();
  if (derived.status != CallStatus::Ok)
    return call_failure("STABLE-1", derived.status, "reading the derived document of a fresh node", derived.detail);
  if (auto d = diff_documents(print_derived(expected), derived.text))
    return Finding{clause_if_different, FindingStatus::Fail, "fresh node derived: " + d->describe()};
  return std::nullopt;
}

}  // namespace vgc
