// finding.h — a deviation as every layer above the reference speaks of it:
// the clause it is blamed on, its kind, and what the implementation showed.
//
// Spec: the clause catalog (clause.h): a finding names one clause id.
//
// Rationale: vocabulary at the bottom (issue 29). A finding is made by
// check_step, the capability checks and the mesh build, shrunk by the
// runner, confirmed by confirm_finding, replayed by `vgc replay`, written
// by the report writers and read back by `vgc merge`: none of them should
// have to include a driver to name it. Plain data: no behaviour but its
// name.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rule.h"

namespace vgc {

// NotJudged is no finding: a capability check (capability.h) returns it
// when its oracle cannot be asked about the case (OpenSubdiv refuses the
// mesh), `message` saying why; certify counts the case as not judged and
// `vgc replay` says so instead of "passes".
enum class FindingStatus { Fail, Crash, Timeout, NotJudged };
const char* finding_status_name(FindingStatus s);  // "fail", "crash", "timeout", "not-judged"
// The inverse of finding_status_name (a report.json or a signature line
// read back); nullopt for any other word.
std::optional<FindingStatus> finding_status_named(std::string_view name);

// What kind of deviation a finding is, in order of severity
// (confirm_finding.h finding_severity): a wrong verdict, reason or document;
// hidden state (a party that starts watching late is sent something else
// than those that watched all along and the model hold); a protocol error;
// a time-out; a crash (a sanitizer report included).
enum class FindingKind : std::uint8_t { WrongAnswer, HiddenState, ProtocolError, Timeout, Crash };
const char* finding_kind_name(FindingKind k);  // "wrong-answer", "hidden-state", ...
// The inverse (a program's "#! history" or a report.json read back);
// nullopt for any other word.
std::optional<FindingKind> finding_kind_named(std::string_view name);

struct Finding {
  Finding() = default;
  Finding(std::string clause_id, FindingStatus s, std::string text)
      : clause(std::move(clause_id)), status(s), message(std::move(text)) {}

  std::string clause;          // catalog id
  FindingStatus status = FindingStatus::Fail;
  std::string message;         // expected versus observed, one paragraph
  // What the implementation showed, for a picture of the finding
  // (report_html.cpp): the document that differed ("snapshot", "derived")
  // or the capability request it answered ("?subdivide 2"), the whole text
  // it printed, and for a document the first differing lines (either may be
  // empty: a line missing or extra). All empty when no document differed
  // (a verdict, a crash).
  std::string shown_by;
  std::string observed_document;
  std::string expected_line, observed_line;
  // The reference node's rules the finding is blamed on (attribution.h),
  // the blamed one first; empty for a finding no node rule decided (a
  // derived line, a capability check, a fresh node).
  std::vector<Rule> rules;
  // What the implementation sent back after the step, on a route that
  // watches it (the Verse wire, Answer::host_sent): the host's messages for
  // the node, printed as commands in the order vgc's mirror applied them,
  // the first kHostSentKept of host_sent_count. host_sent_count 0 with
  // host_sent_seen: the host sent nothing. Not seen (false) on routes that
  // answer for themselves, and for findings no step made.
  bool host_sent_seen = false;
  std::vector<std::string> host_sent;
  std::size_t host_sent_count = 0;
  // The kind of difference within the finding's kind, for a kind that
  // tells differences apart (confirm_finding.h
  // kind_tells_differences_apart: hidden state): "" or, for a late
  // subscriber shown a slot the model removed with its element, that slot
  // as it was (program_checker.h kRemovedSlotKept). Two findings of one
  // clause and such a kind but another difference are two findings: a run
  // tolerates the one it found, not the other (property_case.h
  // is_tolerated), and the clause shows both (ClauseOutcome::
  // other_findings).
  std::string difference;
  // Set where the finding is made, never read back from its message:
  // late_view by the late subscriber's check (program_checker.h
  // check_late_view: the finding is hidden state); protocol_error by
  // check_step.h call_failure (an answer outside the adapter contract,
  // ACCEPT-1); history_kind by
  // confirm_finding.h confirm_call_failure when the failure showed only
  // after what the instance had been sent since it started (the finding is
  // then STABLE-1's or ACCEPT-1's, and this is the kind of failure that
  // history brought about).
  bool late_view = false;
  bool protocol_error = false;
  std::optional<FindingKind> history_kind;
};

}  // namespace vgc
