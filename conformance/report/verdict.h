// verdict.h — from per-clause results (and a baseline) to one verdict and
// the exit code CI gates on.
//
// Spec: the clause levels of the catalog (clause.h), which follow the
// spec's words: MUST where the text or the wire facts make a rule, SHOULD
// where it says "typically", IMPLEMENTATION-DEFINED where it is silent and
// the suite checks its own reading.
//
// What gates (exit 1, "not-conformant"), unless the clause is in the
// baseline:
//   - a MUST clause that failed;
//   - any clause but a SHOULD one that crashed or timed out (a crash is
//     never a reading of a silent point);
//   - with `strict`, an IMPLEMENTATION-DEFINED clause whose reading the
//     implementation does not follow (otherwise a "profile difference",
//     reported, not gating).
// Then: any clause `unchecked` or property stopped makes the run
// "incomplete" (exit 2): neither a pass nor a failure. Otherwise
// "conformant" (exit 0). A cancelled run (RunResult::cancelled_by) is
// "incomplete" whatever it found: its findings are listed all the same,
// and its exit code is the process's, 128 + the signal (143 SIGTERM, 130
// SIGINT), so report.json and the exit status agree. Usage and
// infrastructure errors are also exit 2.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "baseline.h"
#include "run_result.h"

namespace vgc {

// The verdict itself: decided by judge(), read with a switch (the
// compiler flags a kind left out), printed by its name.
enum class VerdictKind : std::uint8_t { Conformant, NotConformant, Incomplete };
const char* verdict_kind_name(VerdictKind k);      // "conformant", "not-conformant", "incomplete"
const char* verdict_kind_headline(VerdictKind k);  // "CONFORMANT", "NOT CONFORMANT", "INCOMPLETE"

struct Verdict {
  VerdictKind kind = VerdictKind::Conformant;
  std::string name;  // verdict_kind_name(kind), as report.json and the tests read it
  int exit_code = 0;
  bool strict = false;
  std::vector<std::string> new_failures;    // clause ids that decide "not-conformant"
  std::vector<std::string> known_failures;  // failing, but in the baseline
  std::vector<std::string> should_failures; // SHOULD clauses that failed (verdict stands)
  // IMPLEMENTATION-DEFINED clauses that failed without --strict: the
  // implementation chose differently from the suite's reading.
  std::vector<std::string> profile_differences;
  std::vector<std::string> stale_baseline;  // in the baseline, but no case diverged on it
  std::vector<std::string> unchecked;       // selected clauses nothing could judge
};

// True when `co`'s finding gates the verdict (see above), baseline aside.
bool finding_gates(const ClauseOutcome& co, bool strict);

Verdict judge(const RunResult& run, const Baseline* baseline, bool strict = false);

// The one story every report tells (stdout, summary.md, report.html,
// report.json): the status a reader is shown for a clause. It is the
// clause's status, except for a finding that does not decide the verdict,
// which is named for why: "fail (SHOULD)" (the verdict stands), "fail
// (baseline)" (a known deviation), "profile difference" (an
// IMPLEMENTATION-DEFINED reading the implementation does not follow, not
// gating without --strict). So "fail", "crash" and "timeout" alone are
// exactly the clauses that make the run not conformant.
std::string shown_status(const ClauseOutcome& co, const Verdict& v);

// The same as values: the clause's status and why a finding does not decide
// the verdict (None where it does, or where there is no finding), so that a
// caller decides with a switch, not by comparing the printed words.
enum class ShownQualifier : std::uint8_t { None, Baseline, ProfileDifference, Should };
struct ClauseShown {
  ClauseStatus status = ClauseStatus::Pass;
  ShownQualifier qualifier = ShownQualifier::None;
  bool operator==(const ClauseShown& o) const { return status == o.status && qualifier == o.qualifier; }
};
ClauseShown clause_shown(const ClauseOutcome& co, const Verdict& v);
std::string shown_status_name(const ClauseShown& s);  // "pass", "fail (SHOULD)", "profile difference", ...

// How many clauses show each status, in one fixed order: pass, what gates,
// what does not, what was not judged (then any other status, in catalog
// order); statuses no clause shows are left out.
std::vector<std::pair<ClauseShown, int>> shown_counts(const RunResult& run, const Verdict& v);
// The same by name (report.json's keys, summary.md's tally).
std::vector<std::pair<std::string, int>> shown_status_counts(const RunResult& run, const Verdict& v);

// The counts as a reader sees them: "39 pass, 1 fail, 1 fail (SHOULD),
// 1 profile difference".
std::string shown_status_tally(const RunResult& run, const Verdict& v);

}  // namespace vgc
