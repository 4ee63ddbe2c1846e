// property_case.h — one case of a property: a fresh node, the commands
// RapidCheck draws (each a Step judged against the reference as it runs),
// the whole documents and the late view at the end, and an optional
// capability's check; and the state a property's cases share (CaseContext).
//
// Spec: every clause a property declares (property.h); the fresh node's
// LAYER-BASE-1, CREASE-INITIAL-1 and STABLE-1; a capability's clauses
// (capability.h).
//
// Rationale: RapidCheck calls the property (run_case) with no argument, and
// rc::state::Command::run gets only RapidCheck's model and the system under
// test, so a case reaches the property's state through a thread-local set
// for the property's run (CaseScope). The runner's other steps
// (property_run.h) are handed that state explicitly. The case's own model
// is the checker's (program_checker.h), which follows an implementation's
// choices where the spec leaves them open; RapidCheck's model only draws.
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "capability.h"
#include "command_gen.h"
#include "confirm_finding.h"
#include "costly_class.h"
#include "program.h"
#include "program_checker.h"
#include "run_budget.h"
#include "run_result.h"

namespace vgc {

using Clock = std::chrono::steady_clock;

// A property stops when, after at least this many cases, set-aside cases
// are more than this share of the cases run: the rest of its cases would
// mostly be set aside too, and say nothing about the clauses still unjudged.
constexpr int kSetAsideMinCases = 20;
constexpr double kSetAsideShare = 0.75;

// What the property's cases report back; one per running property.
struct CaseContext {
  Implementation* sut = nullptr;
  Clock::time_point deadline;
  bool deadline_hit = false;
  std::vector<Command> trace;           // commands of the current case so far
  // The case's drawn commands (run_drawn_commands) and the index of the
  // next Step to run among them: what is left of the case is told to the
  // implementation before each step (Implementation::expect_commands).
  std::vector<Command> drawn;
  std::size_t drawn_next = 0;
  // The reference state after trace (checker->model()), and how each
  // command is compared (program_checker.h); a new one per case.
  std::unique_ptr<ProgramChecker> checker;
  std::optional<Finding> last_failure;  // the most recent failing case: after
  Program last_program;                 // shrinking, the smallest one
  std::map<std::string, std::pair<Finding, Program>> notes;
  // Once a case fails, shrinking keeps only failures of the same clause and
  // status: a smaller case that fails differently is not a smaller example
  // of *this* failure.
  std::optional<std::pair<std::string, FindingStatus>> signature;
  bool abandoned = false;  // the current case hit a different failure
  // Set when shrinking cannot help and would only cost time: a timeout
  // (every shrink attempt could wait the full time limit again) or a
  // failure of the fresh node (the program is already empty). The cases
  // still to run then pass at once, so the first failing program stands.
  bool stop = false;

  // Running past findings (runner.h).
  // Clauses whose divergence sets a case aside, each with the worst kind of
  // failure tolerated in it (finding_severity): a worse kind in the same
  // clause (a crash behind a wrong answer) is a new finding of its own.
  std::map<std::string, int> tolerated;
  // Within a clause tolerated at exactly a kind that tells differences
  // apart (confirm_finding.h kind_tells_differences_apart), the differences
  // found (Finding::difference): another one of that kind is a finding of
  // its own.
  std::set<std::pair<std::string, std::string>> tolerated_differences;
  std::set<std::string> baseline;   // the subset tolerated from the start
  // At scale: clauses an earlier property of the run has a finding in,
  // tolerated from the start at that finding's kind (tolerate_found_earlier),
  // and those of them a case has stood for (CaseTally).
  std::set<std::string> found_earlier, stood_for;
  std::string set_aside_clause;     // the clause that set the current case aside
  // A tolerated clause's divergence as first seen (shortest program kept).
  std::map<std::string, PropertyFinding> tolerated_seen;
  bool set_aside_case = false;      // the current case diverged in a tolerated clause
  int taken_out = 0;                // commands of the current case taken out (take_step_out)
  long steps_taken_out = 0;         // ... in all cases of the property (outside shrinking)
  bool not_judged_case = false;     // the oracle could not judge the case's capability check
  bool shrinking = false;           // this round found its failure: cases now are shrink attempts
  int cases_done = 0, judged = 0, set_aside = 0, not_judged = 0, target = 0;
  // Sharding by case (RunOptions::shard_*): the property's cases in all
  // shards, the index of the next fresh case among them, and this shard.
  // `target` is the number this shard runs.
  int all_cases = 0, case_index = 0, shard_index = 0, shard_count = 1;
  bool dominated = false;           // set-aside cases dominate: stop
  // ... once this many cases ran (kSetAsideMinCases; 1 at scale, where a
  // case is a whole mesh and the property runs only a few).
  int set_aside_min_cases = kSetAsideMinCases;
  // A case at scale (10^4 to 10^5 commands) sets a tolerated divergence
  // aside instead of taking the command out: each take-out resets the
  // implementation and replays the case so far, which at that size costs
  // minutes on a slow route (r6's geometry code behind vgc_r6_exec).
  bool no_take_out = false;
  // The late view (program_checker.h check_late_view): each shape of
  // difference with the finding it was last localized to, and the shape of
  // the finding being shrunk (a shrink attempt with another shape is not
  // localized: it cannot be that finding).
  std::map<std::string, Finding> late_shapes;
  std::string sought_late_shape;
  // Shapes of isolated findings shown to be another finding's again
  // (isolate_blame.h isolated_shape): set aside when seen again.
  std::set<std::string> explained_shapes;
  // What the instance had been sent since it started when the round's first
  // call failure happened (confirm_finding.h), the failing case last.
  HistoryRecorder* recorder = nullptr;
  std::vector<std::vector<Command>> failure_history;
  // Kinds of failure (a crash, a time-out, a protocol error, a wrong answer) the run
  // already found to depend on the implementation's history: another one
  // whose case does not fail a fresh instance is set aside, not shrunk.
  std::set<FindingKind> history_kinds;
  // The round's first call failure: whether its case failed a fresh
  // instance the same way, and that case (the fallback when shrinking, on
  // an instance with a history of its own, ends on a program that does not).
  bool failure_reproduced = false;
  Program failure_program;

  // Tallies (outside shrinking): the property's exercised counts, the run's
  // command kinds and unreported verdicts.
  std::map<std::string, long>* exercised = nullptr;
  const std::vector<std::string_view>* declared = nullptr;  // the property's clauses
  std::map<std::string, long>* derived_only = nullptr;  // route without a derived document
  std::map<std::string, CommandKindCount>* kinds = nullptr;
  std::map<std::string, long>* rule_uses = nullptr;
  long* unreported = nullptr;
  // Classes of input that cost a time-out (costly_class.h), run-wide: no
  // command of one is sent again. And what the report says of each.
  std::vector<CostlyClass>* avoided = nullptr;
  std::vector<std::string>* avoided_notes = nullptr;
  const std::string* property_id = nullptr;
};

// What every case of one property draws and checks.
struct CaseSpec {
  Focus focus = Focus::Anything;
  const CapabilityCheck* capability = nullptr;  // an optional capability's check, or none
  std::string_view capability_name;
  std::string capability_clause_list;  // its clauses, comma-separated
  bool at_scale = false;
};

// Makes `c` the case state of the cases run on this thread until the
// scope ends.
class CaseScope {
 public:
  explicit CaseScope(CaseContext* c);
  ~CaseScope();
  CaseScope(const CaseScope&) = delete;
  CaseScope& operator=(const CaseScope&) = delete;
};

// Makes `budget` the run's --budget (run_budget.h) on this thread until
// the scope ends: every wait of a case asks it (past_deadline).
class RunBudgetScope {
 public:
  explicit RunBudgetScope(RunBudget* budget);
  ~RunBudgetScope();
  RunBudgetScope(const RunBudgetScope&) = delete;
  RunBudgetScope& operator=(const RunBudgetScope&) = delete;
};

// The case state of the property running on this thread, or nullptr.
CaseContext* current_case();

// Whether the run's --budget (RunBudgetScope) is spent; and why, for the notes.
bool run_budget_spent();
std::string run_budget_why();

// One case of the property: what RapidCheck calls, fresh or shrinking.
void run_case(const CaseSpec& s);

// Whether `f` is tolerated: its clause has a finding of a worse kind
// already, or of the same kind and, where that kind tells differences
// apart (Finding::difference), the same difference.
bool is_tolerated(const CaseContext& c, const Finding& f);

// Records that `f` was found: its clause tolerated from now on up to its
// kind, and at that kind its difference (is_tolerated).
void tolerate(CaseContext& c, const Finding& f);

// Whether the case's program, from a fresh instance, fails as `f` did: a
// call failure of the same kind on whatever command (a crash is a crash
// wherever the shrunk program ends), a wrong answer in the same clause.
bool case_fails_fresh(const CaseContext& c, const Finding& f, const Program& program);

}  // namespace vgc
