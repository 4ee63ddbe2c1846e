// runner.cpp — see runner.h.
#include "runner.h"

#include <fcntl.h>
#include <fnmatch.h>
#include <rapidcheck.h>
#include <rapidcheck/detail/Configuration.h>
#include <unistd.h>
#include <rapidcheck/state.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <sstream>

#include "capability.h"
#include "clause_status.h"
#include "costly_class.h"
#include "run_budget.h"
#include "exercised_clauses.h"
#include "forwarding_implementation.h"
#include "isolate_blame.h"
#include "command_text.h"
#include "confirm_finding.h"
#include "cancel.h"
#include "program_checker.h"
#include "scale_mesh.h"
#include "property.h"
#include "route_limit_clauses.h"

namespace vgc {
namespace {

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
  // Kinds of call failure ("crash", "timeout", "protocol-error") the run
  // already found to depend on the implementation's history: another one
  // whose case does not fail a fresh instance is set aside, not shrunk.
  std::set<std::string> history_kinds;
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

thread_local CaseContext* g_context = nullptr;

bool owns_case(const CaseContext& c, int index) {
  return c.shard_count <= 1 || index % c.shard_count == c.shard_index;
}

// How many of `all` cases fall in shard `index` of `count`.
int shard_cases(int all, int index, int count);

// Shards by cost (RunOptions::shard_*): the shard each property of the
// catalog runs in, or -1 for a property at scale, whose cases are split
// over every shard (case k in shard k mod N; its cases cost about the same,
// scale_mesh.h). The others go whole to one shard each, so a shard's
// findings are the unsharded run's: the costliest first, each to the shard
// with the least cost so far (the split property's share counted in every
// shard), ties to the earlier property and the lower shard. Only the
// properties that will run count (`runs`: selected, claimed, runnable on
// the route), and on a route that is not run at scale (the Verse wire,
// RouteLimits::at_scale) a property costs
// its cases, each a run of round trips; PropertySpec::cost otherwise. The
// same in every shard of one implementation.
std::vector<int> assign_shards(const std::vector<bool>& runs, int count, int cases, bool wire) {
  const auto& props = property_catalog();
  std::vector<int> shard(props.size(), 0);
  if (count <= 1) return shard;
  auto cost = [&](std::size_t i) {
    return wire ? static_cast<double>(property_cases(props[i], cases)) : props[i].cost;
  };
  std::vector<double> load(static_cast<std::size_t>(count), 0.0);
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < props.size(); ++i) {
    if (!props[i].at_scale) {
      order.push_back(i);
      continue;
    }
    shard[i] = -1;
    if (!runs[i]) continue;
    const int all = property_cases(props[i], cases);
    for (int k = 0; k < count; ++k)
      load[static_cast<std::size_t>(k)] += cost(i) * shard_cases(all, k, count) / all;
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return (runs[a] ? cost(a) : 0.0) > (runs[b] ? cost(b) : 0.0);
  });
  for (std::size_t i : order) {
    const auto least = static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
    if (runs[i]) load[least] += cost(i);
    shard[i] = static_cast<int>(least);
  }
  return shard;
}

// How many of `all` cases fall in shard `index` of `count`.
int shard_cases(int all, int index, int count) {
  if (count <= 1) return all;
  return all / count + (index < all % count ? 1 : 0);
}

// The budget ran out (CPU seconds, or its wall-clock guard: run_budget.h),
// or the run was cancelled (cancel.h): either way no further case runs and
// the case under way is not judged.
thread_local RunBudget* g_budget = nullptr;  // the run's --budget (run_budget.h), set by run_certification

bool past_deadline() {
  if (Clock::now() < g_context->deadline && !cancel_signal() && !(g_budget && g_budget->spent())) return false;
  g_context->deadline_hit = true;
  return true;
}

// Whether `f` is tolerated: its clause has a finding of the same or a
// worse kind already.
bool is_tolerated(const CaseContext& c, const Finding& f) {
  const auto it = c.tolerated.find(f.clause);
  return it != c.tolerated.end() && finding_severity(f) <= it->second;
}

// The first (shortest) program that showed a tolerated clause's divergence
// is kept for the report.
void note_tolerated(const Finding& f, const std::optional<CapabilityRequest>& request = std::nullopt) {
  CaseContext& c = *g_context;
  if (c.shrinking) return;
  auto it = c.tolerated_seen.find(f.clause);
  if (it == c.tolerated_seen.end() || it->second.program.commands.size() > c.trace.size()) {
    PropertyFinding pf;
    pf.finding = f;
    pf.program.commands = c.trace;
    pf.program.request = request;
    pf.tolerated_from_start = c.baseline.count(f.clause) > 0 || c.found_earlier.count(f.clause) > 0;
    c.tolerated_seen[f.clause] = std::move(pf);
  }
}

// A tolerated clause diverged first: the case is set aside.
void set_case_aside(const Finding& f, const std::optional<CapabilityRequest>& request = std::nullopt) {
  if (!g_context->set_aside_case) g_context->set_aside_clause = f.clause;
  g_context->set_aside_case = true;
  note_tolerated(f, request);
}

// A command whose first divergence is a plain failure in a tolerated clause
// is taken out of the case instead of setting the whole case aside: the
// implementation is reset and the case so far, without that command, is
// sent again and must agree with the model as it did before; then the case
// goes on and every later command is judged. Without this, an
// implementation that deviates on a command most cases send (a host that
// ignores the id a bone_create asks for) leaves every clause downstream of
// that command unjudged. A command the implementation dropped (its state is
// still the state before) is taken out without a reset. The case is set
// aside instead when the case already had kMaxTakenOut commands taken out,
// the divergence is not a plain failure (a crash or time-out leaves an
// instance nothing should be built on), the replay does not agree (an
// implementation that does not repeat itself), or no clause still wants
// reach: taking out costs a reset and a replay, so it is spent only
// while a clause the property is meant to check, with no finding of its
// own, has been decided by fewer than kReachWanted judged steps.
constexpr int kMaxTakenOut = 4;
constexpr long kReachWanted = 20;

// A clause the route cannot judge wants no reach (run_certification reports
// it not-applicable): one the route names, reason codes from an
// implementation that answers `done`, and one only the derived document
// decides on a route that carries none.
bool reach_wanted() {
  const CaseContext& c = *g_context;
  const RouteLimits limits = c.sut->limits();
  for (std::string_view clause : *c.declared) {
    const std::string id(clause);
    if (c.tolerated.count(id) || !route_cannot_judge(id, limits).empty()) continue;
    if (id == "REASON-1" && *c.unreported > 0) continue;
    const auto it = c.exercised->find(id);
    const long judged = it == c.exercised->end() ? 0 : it->second;
    if (judged == 0 && c.derived_only->count(id)) continue;
    if (judged < kReachWanted) return true;
  }
  return false;
}

// A case's checker. A step judged wrong on an answer from a batch is judged
// again on its own (ProgramChecker::judge_again_alone) unless its clause
// already has a finding of that kind: such a step is only taken out or set
// aside, which does not decide any clause's status.
std::unique_ptr<ProgramChecker> case_checker(CaseContext& c) {
  auto checker = std::make_unique<ProgramChecker>(*c.sut, /*follow_choices=*/true);
  checker->judge_again_alone([&c](const Finding& f) { return !is_tolerated(c, f); });
  return checker;
}

bool take_step_out(const StepResult& r) {
  CaseContext& c = *g_context;
  const Finding& f = *r.failure;
  if (f.status != FindingStatus::Fail || c.no_take_out || c.taken_out >= kMaxTakenOut || c.trace.empty() ||
      !reach_wanted())
    return false;
  note_tolerated(f);  // with the command still in the trace: the program that shows it
  c.trace.pop_back();
  if (r.implementation_unchanged) {
    c.checker->drop_last();  // it dropped the command: both sides still hold the state before it
  } else {
    // Once the command is out of the trace the case cannot fall back to
    // fail_case (its program would no longer show the divergence): a reset
    // or replay that fails sets the case aside here.
    if (c.sut->reset().status != CallStatus::Ok) return c.set_aside_case = true;
    c.checker = case_checker(c);
    c.sut->expect_commands(c.trace);  // the replay, told ahead (a route may batch it)
    for (const auto& cmd : c.trace)
      if (c.checker->step(cmd).failure) {
        c.sut->expect_commands({});
        return c.set_aside_case = true;
      }
    c.sut->expect_commands({});
  }
  ++c.taken_out;
  if (!c.shrinking) ++c.steps_taken_out;
  return true;
}

// Records `f` and fails the case, unless it is a different failure from the
// one being shrunk; returns false in that case (the case then passes).
// `request` is the capability check that found it, if one did. A failure in
// a tolerated clause sets the case aside instead (returns false).
// Whether the case's program, from a fresh instance, fails as `f` did: a
// call failure of the same kind on whatever command (a crash is a crash
// wherever the shrunk program ends), a wrong answer in the same clause.
bool case_fails_fresh(const Finding& f, const Program& program) {
  HistoryRecorder& recorder = *g_context->recorder;
  return is_call_failure(f) ? fails_fresh(recorder, f, program) : reproduces_fresh(recorder, f, program);
}

// A finding of any kind is confirmed on a fresh instance before it is
// shrunk or blamed (confirm_finding.h). Returns false when the case is set
// aside instead: it does not fail a fresh instance, and the run already
// has a finding that depends on the history for that kind of failure.
bool confirm_before_shrinking(const Finding& f, const std::optional<CapabilityRequest>& request) {
  CaseContext& c = *g_context;
  if (c.shrinking || !c.recorder || f.status == FindingStatus::NotJudged) return true;
  const Program program{c.trace, request};
  const std::vector<std::vector<Command>> history = c.recorder->history();
  const bool reproduced = case_fails_fresh(f, program);
  if (!reproduced && c.history_kinds.count(finding_kind(f))) {
    c.set_aside_case = true;  // the history-dependent failure again: already reported
    return false;
  }
  c.failure_history = history;
  c.failure_program = program;
  c.failure_reproduced = reproduced;
  // A failure that a fresh instance does not repeat is not shrunk (every
  // attempt would only add to the history).
  if (!reproduced) c.stop = true;
  return true;
}

// A time-out on a command names a class of input (costly_class.h) that the
// rest of the run does not draw again. Returns true when the class's kind
// of element already had a costly class: the time-out is then that class
// again (one found at 2^27 first, then at 2^23: the node is slow from some
// size on), its floor is lowered to this id's and the case is set aside,
// not reported as a finding of whatever clause its command has.
bool avoid_costly_class(const Finding& f) {
  CaseContext& c = *g_context;
  if (f.status != FindingStatus::Timeout || c.shrinking || c.trace.empty() || !c.avoided) return false;
  const auto k = costly_class_of(c.trace.back());
  if (!k) return false;
  for (std::size_t i = 0; i < c.avoided->size(); ++i) {
    CostlyClass& known = (*c.avoided)[i];
    if (known.kind != k->kind) continue;
    if (k->floor < known.floor) {
      known.floor = k->floor;
      (*c.avoided_notes)[i] = describe_costly_class(known) + ": time-outs on " + f.clause + " (" + *c.property_id +
                              ") and others; no command naming one was sent for the rest of the run";
    }
    return true;
  }
  c.avoided->push_back(*k);
  c.avoided_notes->push_back(describe_costly_class(*k) + ": a time-out on " + f.clause + " (" + *c.property_id +
                             "); no command naming one was sent for the rest of the run");
  return false;
}

bool fail_case(const Finding& f, std::optional<CapabilityRequest> request = std::nullopt) {
  if (avoid_costly_class(f)) {
    g_context->set_aside_case = true;  // the costly class again: found once already
    return false;
  }
  if (is_tolerated(*g_context, f)) {
    set_case_aside(f, request);
    return false;
  }
  if (blame_isolates(f) && g_context->explained_shapes.count(isolated_shape(f))) {
    g_context->set_aside_case = true;  // another finding's difference again (seen_through_found_clause)
    return false;
  }
  auto& sig = g_context->signature;
  // Shrinking keeps a smaller example of the same finding, or one whose
  // first difference one rule alone explains (isolate_blame.h).
  if (sig && (!g_context->last_failure ||
              choose_shrink(*g_context->last_failure, g_context->last_program.commands, f, g_context->trace) ==
                  ShrinkChoice::Reject))
    return false;
  if (!confirm_before_shrinking(f, request)) return false;
  sig = std::make_pair(f.clause, f.status);
  g_context->shrinking = true;
  g_context->last_failure = f;
  g_context->last_program.commands = g_context->trace;
  g_context->last_program.request = std::move(request);
  // Not shrunk: a time-out (every attempt could wait the full limit again),
  // a fresh node's failure (nothing to shrink), and a crash or protocol
  // error at scale (every attempt replays 10^4 commands and more on a
  // restarted instance; the case itself is the counterexample).
  if (f.status == FindingStatus::Timeout || g_context->trace.empty() || (g_context->no_take_out && is_call_failure(f)))
    g_context->stop = true;
  RC_FAIL(f.clause + ": " + f.message);
  return true;  // unreachable: RC_FAIL throws
}

void count_exercised(const std::vector<std::string_view>& clauses) {
  for (auto c : clauses) ++(*g_context->exercised)[std::string(c)];
}

// rc::state command: model = the reference node, system = the implementation.
struct Step final : rc::state::Command<Node, Implementation> {
  vgc::Command command;
  explicit Step(vgc::Command c) : command(std::move(c)) {}

  void apply(Node& model) const override { model.apply(command); }

  void run(const Node& /*rapidcheck_model*/, Implementation& sut) const override {
    CaseContext& c = *g_context;
    const std::size_t at = c.drawn_next++;  // this step's index among the drawn commands
    if (c.stop || c.abandoned || c.set_aside_case || c.deadline_hit || past_deadline()) return;
    if (in_costly_class(command, *c.avoided)) return;  // a class that costs a time-out: found once already
    c.trace.push_back(command);
    // The step starts from the case's own model, not RapidCheck's: where the
    // implementation made a choice the spec leaves open (which free id it
    // picked), the model follows it (implementation_choice.h) and the rest
    // of the case is still judged.
    (void)sut;  // c.checker holds it
    // What is left of the case, this command first, is told to the
    // implementation for this step only (a route may send several commands
    // before one round trip; replays in between send theirs on their own).
    if (at < c.drawn.size()) {
      std::vector<vgc::Command> next;
      for (std::size_t k = at; k < c.drawn.size(); ++k)
        if (!in_costly_class(c.drawn[k], *c.avoided)) next.push_back(c.drawn[k]);
      c.sut->expect_commands(std::move(next));
    }
    std::vector<DerivedChange> derived_changed;
    StepResult r = c.checker->step(command, &derived_changed);
    c.sut->expect_commands({});
    if (cancel_signal()) {  // the step may have been cut short: it proves nothing
      c.deadline_hit = true;
      return;
    }
    if (r.failure && c.checker->failed_at() >= 0)  // found for an earlier command (sparse reading)
      c.trace.resize(static_cast<std::size_t>(c.checker->failed_at()) + 1);
    else if (r.failure && is_tolerated(c, *r.failure) && take_step_out(r))
      return;
    const Node& after = c.checker->model();
    for (auto& note : r.notes) {
      auto it = c.notes.find(note.clause);
      if (it == c.notes.end() || it->second.second.commands.size() > c.trace.size())
        c.notes[note.clause] = {note, Program{c.trace, std::nullopt}};
    }
    if (!r.failure && !c.shrinking && r.not_judged.empty()) {
      std::vector<std::string_view> decided, derived_only;
      exercised_clauses(derived_changed, command, r.expected, r.rules, after, r.verdict_reported, &decided,
                        r.derived_judged ? nullptr : &derived_only);
      count_exercised(decided);
      for (Rule rule : r.rules) ++(*c.rule_uses)[std::string(rule_name(rule))];
      for (auto clause : derived_only) ++(*c.derived_only)[std::string(clause)];
      CommandKindCount& k = (*c.kinds)[command_kind(command)];
      ++k.sent;
      if (r.expected == Reason::Ok) ++k.applied;
      else ++k.rejected[std::string(reason_name(r.expected))];
      if (!r.verdict_reported) ++*c.unreported;
    }
    // A different failure while shrinking: the rest of this case proves nothing.
    if (r.failure && !fail_case(*r.failure) && !c.set_aside_case) c.abandoned = true;
  }

  void show(std::ostream& os) const override { os << print_command(command); }
};

// A case of a property at scale (scale_mesh.h): the mesh drawn for the
// case, built and edited command by command, each command a Step as in
// every other property.
void run_scale_case() {
  CaseContext& c = *g_context;
  ScaleCase sc;
  sc.shape = static_cast<ScaleShape>(*rc::gen::inRange(0, kScaleShapes));
  sc.elements = *rc::gen::shrink(rc::gen::inRange(kScaleDrawLow, kScaleDrawHigh + 1),
                                 [](int v) { return rc::shrink::towards(v, kScaleMinElements); });
  sc.spread_ids = *rc::gen::arbitrary<bool>();
  sc.seed = *rc::gen::arbitrary<std::uint32_t>();
  const Node unused;  // Step::run judges against the case's own model
  c.checker->allow_sparse_reading();  // a route without ?digest: the documents read every so often
  for (const auto& cmd : scale_case_commands(sc)) {
    Step(cmd).run(unused, *c.sut);
    if (c.stop || c.abandoned || c.set_aside_case || c.deadline_hit) return;
  }
}

class ProgressListener final : public rc::detail::TestListener {
 public:
  ProgressListener(RunProgress* p, const std::function<void(const RunProgress&)>* cb, Clock::time_point start)
      : p_(p), cb_(cb), start_(start) {}
  void onTestCaseFinished(const rc::detail::CaseDescription& d) override {
    if (d.result.type == rc::detail::CaseResult::Type::Failure) p_->shrinking = true;
    emit();
  }
  void onShrinkTried(const rc::detail::CaseDescription&, bool) override { emit(); }
  void onTestFinished(const rc::detail::TestMetadata&, const rc::detail::TestResult&) override {}

 private:
  void emit() {
    if (g_context) {
      p_->cases_done = g_context->cases_done;
      p_->set_aside = g_context->set_aside;
    }
    p_->elapsed_seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    if (*cb_) (*cb_)(*p_);
  }
  RunProgress* p_;
  const std::function<void(const RunProgress&)>* cb_;
  Clock::time_point start_;
};

// The start of a capability case: a 3 x 2 grid of quads on a curved height
// field (12 vertices, 6 polygons, one boundary loop); for "loop", which
// takes triangles only, the same grid with each quad split in two along
// alternating diagonals (12 triangles; the inner vertices have valence 8
// and 4, where Loop's weights differ from other schemes', not 6).
const std::vector<vgc::Command>& capability_start_commands(std::string_view capability) {
  static const auto build = [](bool triangles) {
    std::string text;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i)
        text += "vertex_set_xyz_real64 0 " + std::to_string(j * 4 + i) + " " + std::to_string(i) + " " +
                std::to_string(j) + " " + std::to_string((i * j) % 3) + "\n";
    int p = 0;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        const int a = j * 4 + i;
        const std::string q[4] = {std::to_string(a), std::to_string(a + 4), std::to_string(a + 5),
                                  std::to_string(a + 1)};
        if (triangles) {
          const int d = (i + j) % 2;  // checkerboard diagonals: inner vertices of valence 8 and 4
          auto tri = [&](int x, int y, int z) {
            text += "polygon_set_corner_uint32 1 " + std::to_string(p++) + " " + q[x] + " " + q[y] + " " + q[z] +
                    " 4294967295\n";
          };
          if (d == 0) tri(0, 1, 2), tri(0, 2, 3);
          else tri(0, 1, 3), tri(1, 2, 3);
        } else {
          text += "polygon_set_corner_uint32 1 " + std::to_string(p++) + " " + q[0] + " " + q[1] + " " + q[2] + " " +
                  q[3] + "\n";
        }
      }
    std::vector<vgc::Command> out;
    TextError error;
    parse_commands(text, &out, &error);
    return out;
  };
  static const std::vector<vgc::Command> quads = build(false), triangles = build(true);
  return capability == "loop" ? triangles : quads;
}

}  // namespace

// Forwards every call to `sut` and keeps the last capability request and
// its answer, so a capability finding can carry what the implementation
// answered (Finding::observed_document, for report.html's picture).
class RequestRecorder final : public ForwardingImplementation {
 public:
  explicit RequestRecorder(Implementation& sut) : ForwardingImplementation(&sut) {}
  Document request(const std::string& line) override {
    Document d = ForwardingImplementation::request(line);
    last_request = line;
    last_answer = d.status == CallStatus::Ok ? d.text : std::string();
    return d;
  }
  std::string last_request, last_answer;
};

// Runs `check` as `request` says: check_drawn with the drawn value (0 when
// absent) for a check that draws, check otherwise.
std::optional<Finding> run_capability_check(const CapabilityCheck& check, const Node& model, Implementation& sut,
                                            const CapabilityRequest& request) {
  RequestRecorder recorder(sut);
  std::optional<Finding> f = check.check_drawn
                                 ? check.check_drawn(model, recorder, request.variant, request.draw.value_or(0))
                                 : check.check(model, recorder, request.variant);
  if (f && f->shown_by.empty() && !recorder.last_request.empty()) {
    f->shown_by = recorder.last_request;
    f->observed_document = recorder.last_answer;
  }
  return f;
}

namespace {

// A fresh node must look like the reference's fresh node.
std::optional<Finding> check_fresh(Implementation& sut) {
  const Answer a = sut.reset();
  if (a.status != CallStatus::Ok) return call_failure("STABLE-1", a.status, "resetting to a fresh node", a.detail);
  return check_fresh_state(sut);
}

// The seed of round `round` of a property: round 0 is the property's own
// seed (so its first finding is what an earlier vgc found at that seed),
// each later round a seed derived from it.
std::uint64_t round_seed(std::uint64_t seed, int round) {
  return round == 0 ? seed : property_seed(seed, "round-" + std::to_string(round));
}

std::string join(const std::set<std::string>& s) {
  std::string out;
  for (const auto& x : s) out += (out.empty() ? "" : ", ") + x;
  return out;
}

// A crash, timeout or protocol error stands only if its program does it
// again on a fresh instance; otherwise it becomes a finding that depends on
// the implementation's history (confirm_finding.h). Returns false when the
// run already has that history-dependent finding (same clause and status):
// this one is then not reported again.
bool confirm_finding(PropertyFinding* pf, CaseContext& ctx, Clock::time_point deadline, const PropertyOutcome& out,
                     const RunResult& run) {
  const auto limit = std::min(deadline, Clock::now() + std::chrono::seconds(60));
  if (confirm_call_failure(*ctx.recorder, pf, ctx.failure_history, limit)) return true;
  ctx.history_kinds.insert(finding_kind(pf->finding));
  auto same = [pf](const PropertyFinding& f) {
    return f.finding.clause == pf->finding.clause && f.finding.status == pf->finding.status &&
           depends_on_history(f.finding);
  };
  for (const auto& f : out.findings)
    if (same(f)) return false;
  for (const auto& p : run.properties)
    for (const auto& f : p.findings)
      if (same(f)) return false;
  return true;
}

// What every case of one property draws and checks.
struct CaseSpec {
  Focus focus = Focus::Anything;
  const CapabilityCheck* capability = nullptr;  // an optional capability's check, or none
  std::string_view capability_name;
  std::string capability_clause_list;  // its clauses, comma-separated
  bool at_scale = false;
};

// Tallies a fresh case when it ends, however it ends.
struct CaseTally {
  CaseContext& c;
  bool counted;
  ~CaseTally() {
    if (!counted || c.shrinking) return;  // the failing case itself is counted with its finding
    ++c.cases_done;
    // The first case at scale set aside by a clause an earlier property
    // found stands for the finding the property would have made of it
    // (counted as that failing case was: neither judged nor set aside).
    if (c.set_aside_case && c.found_earlier.count(c.set_aside_clause) && c.stood_for.insert(c.set_aside_clause).second) {
    } else if (c.set_aside_case) ++c.set_aside;
    else if (c.not_judged_case) ++c.not_judged;
    else if (!c.abandoned && !c.deadline_hit) ++c.judged;
    if (c.cases_done >= c.set_aside_min_cases && c.set_aside > kSetAsideShare * c.cases_done) c.dominated = true;
  }
};

// Whether a case runs here at all: not after a stop, a dominated property,
// the deadline or the target; and, for a fresh case, in this shard. Case k
// of a property split by case runs in shard k mod N: RapidCheck draws each
// case from its own split of the seed, so skipping another shard's case,
// before drawing anything, leaves every other case as the unsharded run
// draws it.
bool case_runs_here(CaseContext& c, bool counted) {
  if (c.stop || c.dominated || c.deadline_hit || past_deadline()) return false;
  if (counted && c.cases_done >= c.target) return false;
  return !counted || owns_case(c, c.case_index++);
}

void reset_case(CaseContext& c) {
  c.trace.clear();
  c.checker = case_checker(c);
  c.abandoned = false;
  c.set_aside_case = false;
  c.set_aside_clause.clear();
  c.not_judged_case = false;
  c.taken_out = 0;
}

bool case_still_judged(CaseContext& c) {
  return !c.stop && !c.abandoned && !c.set_aside_case && !c.deadline_hit && !past_deadline();
}

// The fresh node must look like the reference's; false ends the case.
bool check_fresh_node(CaseContext& c) {
  if (auto f = check_fresh(*c.sut)) {
    if (past_deadline()) return false;  // cut short by a cancel: no finding
    if (!fail_case(*f)) return false;
  }
  if (!c.shrinking) {
    count_exercised(fresh_node_clauses());
    for (Rule rule : {Rule::BaseLayers, Rule::InitialCreases}) ++(*c.rule_uses)[std::string(rule_name(rule))];
  }
  return true;
}

// A capability case starts from a small open surface, so that its random
// commands edit a mesh rather than mostly build nothing; false ends the case.
bool build_capability_start(CaseContext& c, std::string_view capability) {
  for (const auto& cmd : capability_start_commands(capability)) {
    c.trace.push_back(cmd);
    StepResult r = c.checker->step(cmd);
    if (r.failure && past_deadline()) return false;
    if (r.failure) {
      fail_case(*r.failure);
      return false;
    }
  }
  return true;
}

// The case's commands, drawn by RapidCheck from the model (rc::state), each
// a Step judged as it runs.
void run_drawn_commands(CaseContext& c, Focus focus) {
  const Node start = c.checker->model();
  const auto commands = *rc::state::gen::commands(start, [focus](const Node& model) {
    return rc::gen::map(gen_command(model, focus), [](vgc::Command cmd) {
      return std::shared_ptr<const rc::state::Command<Node, Implementation>>(std::make_shared<Step>(cmd));
    });
  });
  c.drawn.clear();
  for (const auto& step : commands)
    if (const auto* st = dynamic_cast<const Step*>(step.get())) c.drawn.push_back(st->command);
  c.drawn_next = 0;
  struct Forget {  // however the case ends (RC_FAIL throws)
    CaseContext& c;
    ~Forget() {
      c.drawn.clear();
      c.drawn_next = 0;
    }
  } forget{c};
  if (c.drawn.size() != commands.size()) c.drawn.clear();  // not all Steps: no lookahead
  rc::state::runAll(commands, start, *c.sut);
}

// Where the steps compared digests, the whole documents once at the end
// (program_checker.h); a difference is localized to its command. False
// ends the case.
bool compare_whole_documents(CaseContext& c) {
  if (!case_still_judged(c)) return false;
  if (auto l = c.checker->finish(c.trace)) {
    c.trace.resize(static_cast<std::size_t>(l->index) + 1);
    fail_case(*l->step.failure);
    return false;
  }
  return true;
}

// What a party that starts watching the node now is sent (the Verse wire's
// late subscriber), against the model; a difference is localized and
// blamed (program_checker.h check_late_view). The case's steps were all
// judged, so a difference in a clause tolerated at that kind is noted, not
// set aside; a shape of difference already localized to such a clause is
// not localized again (each costs a bisection: reset and replay). False
// ends the case.
bool check_late_view(CaseContext& c) {
  if (!case_still_judged(c)) return false;
  const auto localize = [&c](const std::string& shape) {
    if (c.shrinking)
      return c.last_failure && finding_kind(*c.last_failure) == "hidden-state" && shape == c.sought_late_shape;
    const auto it = c.late_shapes.find(shape);
    return it == c.late_shapes.end() || !is_tolerated(c, it->second);
  };
  auto l = c.checker->check_late_view(c.trace, localize);
  if (!l || past_deadline()) return true;
  const Finding f = *l->step.failure;
  const std::string shape = c.checker->late_shape();
  if (!c.shrinking) c.late_shapes[shape] = f;
  if (is_tolerated(c, f)) {
    note_tolerated(f);
    return true;
  }
  c.trace.resize(static_cast<std::size_t>(l->index) + 1);
  if (!c.shrinking) c.sought_late_shape = shape;
  fail_case(f);
  return false;
}

// An optional capability: judged on the final state, the variant
// (subdivision level) chosen by the case; a check that needs more
// (check_drawn) gets a value drawn for the case.
void check_capability(CaseContext& c, const CaseSpec& s) {
  if (!case_still_judged(c)) return;
  const int variant = static_cast<int>(c.trace.size() % 3) + 1;
  CapabilityRequest request{s.capability->capability, variant, std::nullopt};
  if (s.capability->check_drawn) request.draw = *rc::gen::arbitrary<std::uint32_t>();
  const auto f = run_capability_check(*s.capability, c.checker->model(), *c.sut, request);
  if (f && past_deadline()) return;  // cut short by a cancel: no finding
  if (f && f->status != FindingStatus::NotJudged) {
    fail_case(*f, request);
  } else if (f) {  // run, and counted, but neither judged nor exercising anything
    c.not_judged_case = true;
  } else if (!c.shrinking) {  // a case the oracle could not judge exercises nothing
    std::stringstream ids(s.capability_clause_list);
    std::string id;
    while (std::getline(ids, id, ',')) ++(*c.exercised)[id];
  }
}

// One case of the property: what RapidCheck calls, fresh or shrinking.
void run_case(const CaseSpec& s) {
  CaseContext& c = *g_context;
  const bool counted = !c.shrinking;  // fresh cases count toward the property's cases; shrink attempts do not
  if (!case_runs_here(c, counted)) return;
  reset_case(c);
  CaseTally tally{c, counted};
  if (!check_fresh_node(c)) return;
  if (s.capability && !build_capability_start(c, s.capability_name)) return;
  if (s.at_scale) run_scale_case();
  else run_drawn_commands(c, s.focus);
  if (!compare_whole_documents(c)) return;
  if (!check_late_view(c)) return;
  if (s.capability) check_capability(c, s);
}

// A property at scale tolerates from the start what earlier properties of
// the run found, at the kind they found it: a case of 10^4 commands and
// more that diverges in such a clause is set aside where it diverges, not
// confirmed and shrunk again (a minute per finding through an out-of-process
// route, for a counterexample the clause already has). The divergence is
// still the property's finding, as first seen and not shrunk
// (tolerated_from_start: never chosen over the earlier, shorter one). A
// worse kind in the same clause (a crash at scale behind a wrong answer) is
// still a finding of its own, and a clause only scale reaches is judged as
// before.
void tolerate_found_earlier(CaseContext& ctx, const RunResult& run) {
  for (const auto& p : run.properties)
    for (const auto& f : p.findings) {
      if (depends_on_history(f.finding) || f.finding.status == FindingStatus::NotJudged) continue;
      int& worst = ctx.tolerated[f.finding.clause];
      worst = std::max(worst, finding_severity(f.finding));
      ctx.found_earlier.insert(f.finding.clause);
    }
}

// The case state of one property (CaseContext), wired to its outcome and
// to the run's tallies.
void start_context(CaseContext& ctx, const PropertySpec& spec, Implementation& sut, const RunOptions& o,
                   Clock::time_point deadline, RunResult* run, PropertyOutcome* out) {
  ctx.sut = &sut;
  ctx.recorder = dynamic_cast<HistoryRecorder*>(&sut);
  for (const auto& p : run->properties)  // history-dependent failures earlier properties found
    for (const auto& f : p.findings)
      if (depends_on_history(f.finding)) ctx.history_kinds.insert(finding_kind(f.finding));
  ctx.deadline = deadline;
  // A baseline knows a clause's wrong answers; a crash, time-out or protocol
  // error in it is still a finding.
  for (const auto& clause : o.tolerated) ctx.tolerated[clause] = finding_severity(Finding{});
  ctx.baseline = o.tolerated;
  ctx.all_cases = property_cases(spec, o.cases);
  // A property at scale is split by case over the shards (assign_shards);
  // any other runs whole in its one shard.
  if (spec.at_scale) ctx.shard_index = o.shard_index, ctx.shard_count = o.shard_count;
  ctx.target = shard_cases(ctx.all_cases, ctx.shard_index, ctx.shard_count);
  if (spec.at_scale) ctx.set_aside_min_cases = 1, ctx.no_take_out = true;
  if (spec.at_scale) tolerate_found_earlier(ctx, *run);
  ctx.exercised = &out->exercised;
  ctx.declared = &spec.clauses;
  ctx.derived_only = &out->derived_only;
  ctx.kinds = &run->command_kinds;
  ctx.rule_uses = &run->rule_uses;
  ctx.unreported = &run->unreported_verdicts;
  ctx.avoided = &run->avoided;
  ctx.avoided_notes = &run->avoided_classes;
  ctx.property_id = &out->id;
}

// Whether the shrunk `pf`, which one rule alone explains, shows the same
// difference without one of its earlier commands, explained there by the
// rule of a clause the property already found (isolate_blame.h): that
// finding's again. Replays only the smaller programs the model points to.
bool seen_through_found_clause(const PropertyFinding& pf, CaseContext& ctx) {
  if (pf.program.request || !ctx.sut) return false;
  const auto leave_out = commands_to_leave_out(pf.finding, pf.program.commands, [&ctx](const std::string& clause) {
    return ctx.tolerated.count(clause) > 0;
  });
  for (std::size_t k : leave_out) {
    Program smaller = pf.program;
    smaller.commands.erase(smaller.commands.begin() + static_cast<std::ptrdiff_t>(k));
    const ReplayResult r = replay_program(smaller, *ctx.sut);
    if (!r.failure || r.failed_at + 1 != static_cast<int>(smaller.commands.size())) continue;
    if (choose_shrink(pf.finding, pf.program.commands, *r.failure, smaller.commands) == ShrinkChoice::Switch &&
        is_tolerated(ctx, *r.failure)) {
      ctx.explained_shapes.insert(isolated_shape(pf.finding));
      return true;
    }
  }
  return false;
}

// A round's failure (RapidCheck shrank it): confirmed on a fresh instance,
// then the property's next finding, its clause tolerated from now on.
void record_round_failure(const rc::detail::FailureResult& failure, int round, CaseContext& ctx,
                          Clock::time_point deadline, PropertyOutcome* out, const RunResult& run,
                          RunProgress* progress) {
  PropertyFinding pf;
  pf.round = round;
  if (ctx.last_failure) {
    pf.finding = *ctx.last_failure;
    pf.program = ctx.last_program;
  } else {  // an exception escaped from somewhere we did not expect
    pf.finding = Finding{"STABLE-1", FindingStatus::Fail, failure.description};
  }
  ++ctx.cases_done;  // the failing case
  if (ctx.recorder && ctx.last_failure) {
    if (!ctx.failure_reproduced) {
      if (!confirm_finding(&pf, ctx, deadline, *out, run)) return;  // reported once already
    } else if (is_call_failure(pf.finding) && pf.program.commands.size() < ctx.failure_program.commands.size() &&
               !case_fails_fresh(pf.finding, pf.program)) {
      // Shrinking was misled by the instance's history (a crash shrinks on
      // whatever command brings it about; a wrong answer must stay in its
      // clause, which shrinking checks on each attempt).
      pf.program = ctx.failure_program;
    }
  }
  if (ctx.last_failure && seen_through_found_clause(pf, ctx)) {
    ++ctx.set_aside;
    return;
  }
  int& worst = ctx.tolerated[pf.finding.clause];
  worst = std::max(worst, finding_severity(pf.finding));
  out->findings.push_back(std::move(pf));
  progress->failures = static_cast<int>(out->findings.size());
}

// Rounds of RapidCheck until the property's cases are done: each finding
// ends a round, and the next round runs the cases left with its clause
// tolerated (a clause already tolerated cannot fail again, so there is at
// most one round per catalog clause). Returns why it stopped early, if
// RapidCheck gave up or erred.
std::string run_rounds(const CaseSpec& cases, CaseContext& ctx, const PropertySpec& spec, const RunOptions& o,
                       Clock::time_point deadline, RunProgress* progress, Clock::time_point run_start,
                       PropertyOutcome* out, const RunResult& run) {
  auto property = [&cases] { run_case(cases); };
  for (int round = 0; ctx.cases_done < ctx.target && ctx.case_index < ctx.all_cases; ++round) {
    ctx.shrinking = false;
    ctx.stop = false;
    ctx.signature.reset();
    ctx.failure_reproduced = false;
    ctx.last_failure.reset();
    ctx.last_program = Program{};
    progress->shrinking = false;
    rc::detail::TestParams params;
    params.seed = round_seed(out->seed, round);
    params.maxSuccess = ctx.all_cases - ctx.case_index;
    params.maxSize = o.max_size;
    params.maxDiscardRatio = 10;
    rc::detail::TestMetadata meta;
    meta.id = out->id;
    meta.description = std::string(spec.title);
    ProgressListener listener(progress, &o.progress, run_start);
    const auto result = rc::detail::checkTestable(property, meta, params, listener);
    ++out->rounds;
    rc::detail::FailureResult failure;
    rc::detail::GaveUpResult gave_up;
    rc::detail::Error error;
    if (result.match(failure)) {
      record_round_failure(failure, round, ctx, deadline, out, run, progress);
      continue;
    }
    if (result.match(gave_up)) return "RapidCheck gave up: " + gave_up.description;
    if (result.match(error)) return "RapidCheck error: " + error.description;
    break;
  }
  return "";
}

// SHOULD-level notes and followed choices are confirmed like findings: one
// a fresh instance does not repeat depends on the history (the
// history-dependent finding, if the run has one, says what) and is left
// out. Returns how many were left out.
int confirm_notes(CaseContext& ctx, Clock::time_point deadline, PropertyOutcome* out) {
  int unconfirmed = 0;
  for (auto& [clause, note] : ctx.notes) {
    if (ctx.recorder && !cancel_signal() && Clock::now() < deadline && !(g_budget && g_budget->spent()) &&
        !note_reproduces_fresh(*ctx.recorder, note.first, note.second))
      ++unconfirmed;
    else
      out->notes.push_back(note);
  }
  return unconfirmed;
}

// Why the property did not run all its cases, or "".
std::string stop_note_of(const CaseContext& ctx, const std::string& rapidcheck_note) {
  const std::string ran = std::to_string(ctx.cases_done) + " of " + std::to_string(ctx.target) + " cases";
  if (ctx.deadline_hit && cancel_signal()) return std::string("cancelled by ") + cancel_signal_name() + " after " + ran;
  if (ctx.deadline_hit)
    return (g_budget && g_budget->spent() ? g_budget->why() : std::string("the budget ran out")) + " after " + ran +
           "; raise --budget";
  if (ctx.dominated) {
    std::set<std::string> hits;
    for (const auto& [clause, pf] : ctx.tolerated_seen) hits.insert(clause);
    return std::to_string(ctx.set_aside) + " of its " + std::to_string(ctx.cases_done) +
           " cases were set aside (first divergence in " + join(hits) + "), so it stopped before " +
           std::to_string(ctx.target) + " cases";
  }
  if (!rapidcheck_note.empty()) return rapidcheck_note;
  if (ctx.cases_done < ctx.target) return "it ran " + ran;
  return "";
}

// The property's counts, its tolerated divergences (each once, with the
// shortest program it was seen on, in the order of the catalog's ids), and
// its status.
void finish_outcome(const CaseContext& ctx, const std::string& stop_note, int unconfirmed_notes,
                    PropertyOutcome* out) {
  for (const auto& [clause, pf] : ctx.tolerated_seen) {
    bool found = false;
    for (const auto& f : out->findings) found = found || f.finding.clause == clause;
    if (!found) out->findings.push_back(pf);
  }
  out->cases = ctx.cases_done;
  out->judged = ctx.judged;
  out->set_aside = ctx.set_aside;
  out->steps_taken_out = ctx.steps_taken_out;
  out->not_judged = ctx.not_judged;
  if (!stop_note.empty()) {
    out->status = PropertyStatus::Stopped;
    out->note = stop_note;
    return;
  }
  out->status = out->findings.empty() ? PropertyStatus::Pass : PropertyStatus::Fail;
  if (unconfirmed_notes)
    out->note = std::to_string(unconfirmed_notes) + " SHOULD-level or choice difference(s) did not repeat on a fresh "
                "instance: not reported (they depend on the implementation's history)";
}

PropertyOutcome run_property(const PropertySpec& spec, Implementation& sut, const RunOptions& o,
                             Clock::time_point deadline, RunProgress* progress, Clock::time_point run_start,
                             RunResult* run) {
  PropertyOutcome out;
  out.id = std::string(spec.id);
  out.seed = property_seed(o.seed, spec.id);
  const auto start = Clock::now();
  CaseContext ctx;
  start_context(ctx, spec, sut, o, deadline, run, &out);
  out.cases_target = ctx.target;
  CaseSpec cases;
  cases.focus = spec.focus;
  cases.capability = spec.capability.empty() ? nullptr : find_capability_check(std::string(spec.capability));
  cases.capability_name = spec.capability;
  cases.capability_clause_list = capability_clauses(std::string(spec.capability));
  cases.at_scale = spec.at_scale;
  g_context = &ctx;
  const std::string rapidcheck_note = run_rounds(cases, ctx, spec, o, deadline, progress, run_start, &out, *run);
  g_context = nullptr;
  out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const int unconfirmed = confirm_notes(ctx, deadline, &out);
  finish_outcome(ctx, stop_note_of(ctx, rapidcheck_note), unconfirmed, &out);
  return out;
}

// RapidCheck prints its global configuration ("Using configuration:
// seed=...") to stderr the first time it is read. The runner never uses
// that configuration (every property gets explicit TestParams), so a
// printed random seed would only mislead: read it once with stderr closed.
void load_rapidcheck_configuration_quietly() {
  static const bool done = [] {
    std::fflush(stderr);
    const int saved = dup(STDERR_FILENO);
    const int null = open("/dev/null", O_WRONLY);
    if (saved >= 0 && null >= 0) dup2(null, STDERR_FILENO);
    try {
      (void)rc::detail::configuration();
    } catch (...) {
      // a malformed RC_PARAMS: irrelevant here, properties set their own parameters
    }
    std::cerr.flush();
    if (saved >= 0) {
      dup2(saved, STDERR_FILENO);
      close(saved);
    }
    if (null >= 0) close(null);
    return true;
  }();
  (void)done;
}

// Per clause: the findings of every property that ran, whoever declared
// it, and the evidence clause_status.h decides its status from.
void decide_clauses(const RunOptions& o, const RouteLimits& limits, RunResult* run) {
  for (const Clause& clause : clause_catalog()) {
    ClauseOutcome co;
    co.clause = &clause;
    const std::string id(clause.id);
    ClauseEvidence e;
    e.selected = clause_selected(o.clause_glob, clause.id);
    e.shard_part = o.shard_count > 1;
    e.preflight = run->preflight;
    e.route = limits.route;
    e.route_limit = route_limit_of(clause.id, limits);
    e.unreported_verdicts = run->unreported_verdicts;
    int chosen_index = 0;
    // Milder kinds of finding in the clause, shown in the note: each kind
    // once, with every property that found it.
    std::vector<std::pair<std::string, std::set<std::string>>> also;
    const auto also_found = [&also](const Finding& f, const std::string& by) {
      auto it = std::find_if(also.begin(), also.end(), [&](const auto& a) { return a.first == finding_kind(f); });
      if (it == also.end()) it = also.insert(also.end(), {finding_kind(f), {}});
      it->second.insert(by);
    };
    for (std::size_t i = 0; i < run->properties.size(); ++i) {
      const PropertyOutcome& po = run->properties[i];
      if (auto it = po.exercised.find(id); it != po.exercised.end()) e.exercised += it->second;
      if (auto it = po.derived_only.find(id); it != po.derived_only.end()) e.derived_only += it->second;
      auto take = [&](const Finding& f, const Program& p, bool known) {
        if (!prefer_finding(f, p, static_cast<int>(i), co.finding, co.program, chosen_index)) {
          if (co.finding && finding_kind(f) != finding_kind(*co.finding)) also_found(f, po.id);
          return;
        }
        if (co.finding && finding_kind(f) != finding_kind(*co.finding)) also_found(*co.finding, co.found_by);
        chosen_index = static_cast<int>(i);
        co.finding = f;
        co.program = p;
        co.found_by = po.id;
        co.seed = po.seed;
        co.tolerated_from_start = known;
      };
      for (const auto& pf : po.findings)
        if (pf.finding.clause == clause.id) take(pf.finding, pf.program, pf.tolerated_from_start);
      for (const auto& [f, p] : po.notes)
        if (f.clause == clause.id) take(f, p, false);
    }
    if (run->preflight && run->preflight->clause == clause.id) {
      co.finding = run->preflight;
      co.found_by = "fresh-node check";
    }
    e.finding = co.finding;
    gather_clause_evidence(clause, run->properties, &e, &co.properties);
    co.exercised = e.exercised;
    co.derived_only = e.derived_only;
    co.route_limit = e.route_limit;
    const ClauseDecision d = decide_clause_status(clause, e);
    if (!d.status) continue;  // not asked for and nothing found
    co.status = *d.status;
    co.note = d.note;
    if (!also.empty()) {
      co.note = "the worst kind of finding in this clause is shown; also found:";
      for (const auto& [kind, by] : also) co.note += " " + kind + " (" + join(by) + ")";
    }
    run->clauses.push_back(co);
  }
}

}  // namespace

std::uint64_t property_seed(std::uint64_t run_seed, std::string_view property_id) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a
  for (unsigned char ch : property_id) {
    h ^= ch;
    h *= 1099511628211ull;
  }
  // splitmix64 of the mix, so nearby run seeds give unrelated property seeds
  std::uint64_t z = run_seed ^ h;
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

namespace {

// Preflight: an implementation that cannot show a fresh node at all (it
// crashes, hangs or answers outside the contract) can be judged on
// nothing; every case would only wait for it again.
std::optional<Finding> preflight(Implementation& sut) {
  const Answer a = sut.reset();
  std::optional<Finding> f;
  if (a.status != CallStatus::Ok) {
    f = call_failure("STABLE-1", a.status, "resetting to a fresh node", a.detail);
  } else {
    const int documents = sut.limits().derived ? 2 : 1;  // a route may carry no derived document
    for (int doc = 0; doc < documents && !f; ++doc) {
      const Document d = doc == 0 ? sut.snapshot() : sut.derived();
      if (d.status != CallStatus::Ok)
        f = call_failure("STABLE-1", d.status,
                         std::string("reading the ") + (doc == 0 ? "snapshot" : "derived document") + " of a fresh node",
                         d.detail);
    }
  }
  return cancel_signal() ? std::nullopt : f;  // a cancel cut it short: no finding
}

// Why property `spec` will not run in this run, whatever the shard: its
// skipped (or, after a failed preflight, stopped) outcome; nullopt when it
// runs. `claimed`: the capabilities the implementation claims.
std::optional<PropertyOutcome> why_not_run(const PropertySpec& spec, const RunOptions& o, const RunResult& run,
                                           const RouteLimits& limits, const std::vector<std::string>& claimed) {
  PropertyOutcome skipped;
  skipped.id = std::string(spec.id);
  skipped.seed = property_seed(o.seed, spec.id);
  skipped.status = PropertyStatus::Skipped;
  auto as = [&skipped](PropertySkip why, std::string note) {
    skipped.skip = why;
    skipped.note = std::move(note);
    return skipped;
  };
  bool selected = false;
  for (auto c : spec.clauses) selected = selected || clause_selected(o.clause_glob, c);
  if (!selected) return as(PropertySkip::NotSelected, "no selected clause");
  if (run.preflight) {
    skipped.status = PropertyStatus::Stopped;
    skipped.cases_target = property_cases(spec, o.cases);
    return as(PropertySkip::Preflight,
              "not run: the implementation could not show a fresh node (" + run.preflight->clause + ")");
  }
  // A route that carries a command per packet exchange (the Verse wire,
  // RouteLimits::at_scale): 10^4 to 10^5 commands a case are beyond a run's
  // time there.
  if (spec.at_scale && !limits.at_scale)
    return as(PropertySkip::NotOnRoute, "not run on " + limits.route +
                                            ": its cases send 10^4 to 10^5 commands; certify the node through "
                                            "exec: or plugin: for it");
  if (spec.capability.empty()) return std::nullopt;
  if (std::find(claimed.begin(), claimed.end(), spec.capability) == claimed.end())
    return as(PropertySkip::NotClaimed, "not claimed");
  if (!find_capability_check(std::string(spec.capability))) return as(PropertySkip::NoOracle, "no oracle linked");
  return std::nullopt;
}

// Runs one property with progress reports around it.
void run_one_property(std::size_t i, Implementation& sut, const RunOptions& o, Clock::time_point deadline,
                      Clock::time_point start, RunProgress* progress, RunResult* run) {
  const PropertySpec& spec = property_catalog()[i];
  progress->property = std::string(spec.id);
  progress->property_index = static_cast<int>(i);
  progress->cases_done = 0;
  progress->set_aside = 0;
  progress->failures = 0;
  progress->cases_total = property_cases(spec, o.cases);
  progress->shrinking = false;
  if (o.progress) {  // the property starts (its first case may take long)
    progress->elapsed_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    o.progress(*progress);
  }
  run->properties.push_back(run_property(spec, sut, o, deadline, progress, start, run));
  if (o.property_done) {
    progress->elapsed_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    o.property_done(run->properties.back(), *progress);
  }
}

// A capability property of a cancelled run, when what the implementation
// claims was never known (the cancel came before ?capabilities was
// answered): stopped, so its clauses are unchecked, not not-claimed
// (issue 31, item 6).
PropertyOutcome stopped_before_claims(PropertyOutcome p, const PropertySpec& spec, const RunOptions& o) {
  p.status = PropertyStatus::Stopped;
  p.skip = PropertySkip::None;
  p.cases_target = property_cases(spec, o.cases);
  p.note = std::string("cancelled by ") + cancel_signal_name() +
           " before the implementation was asked which capabilities it claims";
  return p;
}

}  // namespace

RunResult run_certification(Implementation& implementation, const RunOptions& o) {
  load_rapidcheck_configuration_quietly();
  // Every call goes through the recorder: a call failure's history since the
  // instance started is then at hand to confirm it (confirm_finding.h).
  HistoryRecorder recorder(implementation);
  Implementation& sut = recorder;
  RunResult run;
  run.implementation = sut.name();
  run.options = o;
  for (std::size_t i = 1; i < kRuleCount; ++i) run.rule_uses[std::string(rule_name(static_cast<Rule>(i)))] = 0;
  const auto start = Clock::now();
  // --budget counts CPU seconds (run_budget.h) with a wall-clock guard
  // that moves on with the machine's load: every wait asks the budget
  // (past_deadline), so no fixed deadline is set here.
  RunBudget budget(o.budget_seconds);
  g_budget = &budget;
  struct Unset {
    ~Unset() { g_budget = nullptr; }
  } unset;
  const auto deadline = Clock::time_point::max();
  // ?capabilities first: its answer is also where an exec program declares
  // what it does not show (declared_profile.h), which the limits and the
  // fresh-node check follow. A cancelled run asks nothing more: the
  // question would end unanswered and read as "claims nothing"
  // (stopped_before_claims).
  bool claims_known = !cancel_signal();
  const std::vector<std::string> claimed = claims_known ? query_capabilities(sut) : std::vector<std::string>{};
  claims_known = claims_known && !cancel_signal();
  const RouteLimits limits = sut.limits();
  run.preflight = preflight(sut);

  // Which properties run at all, then which of them run in this shard.
  const auto& props = property_catalog();
  std::vector<std::optional<PropertyOutcome>> not_run;
  std::vector<bool> runs;
  for (const PropertySpec& spec : props) {
    not_run.push_back(why_not_run(spec, o, run, limits, claimed));
    if (!claims_known && not_run.back() && not_run.back()->skip == PropertySkip::NotClaimed)
      not_run.back() = stopped_before_claims(*not_run.back(), spec, o);
    runs.push_back(!not_run.back());
  }
  const std::vector<int> shard = assign_shards(runs, o.shard_count, o.cases, !limits.at_scale);

  RunProgress progress;
  progress.property_count = static_cast<int>(props.size());
  for (std::size_t i = 0; i < props.size(); ++i) {
    if (!not_run[i] && shard[i] >= 0 && shard[i] != o.shard_index) {
      PropertyOutcome elsewhere;
      elsewhere.id = std::string(props[i].id);
      elsewhere.seed = property_seed(o.seed, props[i].id);
      elsewhere.status = PropertyStatus::Skipped;
      elsewhere.skip = PropertySkip::OtherShard;
      elsewhere.note = "in shard " + std::to_string(shard[i] + 1) + "/" + std::to_string(o.shard_count);
      not_run[i] = elsewhere;
    }
    if (not_run[i]) run.properties.push_back(*not_run[i]);
    else run_one_property(i, sut, o, deadline, start, &progress, &run);
  }

  run.route = limits.route;
  isolate_findings(sut, &run);
  decide_clauses(o, limits, &run);
  if (cancel_signal()) run.cancelled_by = cancel_signal_name();
  summarize_run(&run);
  run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return run;
}

std::string capability_clauses(const std::string& capability) {
  std::string out;
  for (const PropertySpec& spec : property_catalog()) {
    if (spec.capability != capability) continue;
    for (auto c : spec.clauses)
      if (out.find(std::string(c)) == std::string::npos) out += (out.empty() ? "" : ",") + std::string(c);
  }
  return out;
}

ReplayResult replay_program(const Program& program, Implementation& sut) {
  ReplayResult r;
  // As in certify, ?capabilities is asked first, before the node is reset:
  // for the claim, and for the profile an exec program declares in its
  // answer (declared_profile.h), which the checks below follow.
  const auto names = query_capabilities(sut);
  const bool claimed =
      program.request && std::find(names.begin(), names.end(), program.request->capability) != names.end();
  if (auto f = check_fresh(sut)) {
    r.failure = f;
    return r;
  }
  ProgramChecker checker(sut, /*follow_choices=*/true);
  // A program at scale (a case of storage.scale, a history reproducer) is
  // read as certify reads it: the documents every so often, a difference
  // bisected back to its command (program_checker.h); reading both after
  // each of 10^4 commands costs the node's size squared on a route without
  // ?digest.
  if (program.commands.size() >= kScaleMinElements / 2) checker.allow_sparse_reading();
  // The program is told ahead (a route may send several commands before one
  // round trip; a step judged wrong on a batch is judged again alone).
  sut.expect_commands(program.commands);
  struct Forget {
    Implementation& sut;
    ~Forget() { sut.expect_commands({}); }
  } forget{sut};
  for (std::size_t i = 0; i < program.commands.size(); ++i) {
    StepResult s = checker.step(program.commands[i]);
    for (auto& n : s.notes) r.notes.push_back(n);
    if (s.failure) {
      const std::size_t at = checker.failed_at() >= 0 ? static_cast<std::size_t>(checker.failed_at()) : i;
      r.failure = blame_as_history(program, *s.failure, at).value_or(*s.failure);
      r.failed_at = static_cast<int>(at);
      return r;
    }
  }
  if (auto l = checker.finish(program.commands)) {  // a ?digest that does not stand for the documents
    r.failure = l->step.failure;
    r.failed_at = l->index;
    return r;
  }
  if (auto l = checker.check_late_view(program.commands)) {  // what a late subscriber is sent
    r.failure = l->step.failure;
    r.failed_at = l->index;
    if (const auto& also = checker.late_format_finding(); also && also->clause != r.failure->clause)
      r.also_failed.push_back(*also);
    return r;
  }
  const Node& model = checker.model();
  if (!program.request) return r;
  const CapabilityRequest& q = *program.request;
  std::string clauses = capability_clauses(q.capability);
  if (clauses.empty()) clauses = "no clause of this vgc";
  if (!claimed) {
    r.not_judged = sut.name() + " does not claim the capability \"" + q.capability + "\" (certify reports " +
                   clauses + " as not-claimed)";
    return r;
  }
  const CapabilityCheck* check = find_capability_check(q.capability);
  if (!check) {
    r.not_judged = "this vgc has no oracle linked for the capability \"" + q.capability + "\" (" + clauses +
                   " cannot be judged)";
    return r;
  }
  if (auto f = run_capability_check(*check, model, sut, q)) {
    if (f->status == FindingStatus::NotJudged) {
      r.not_judged = "not judged (" + f->clause + "): " + f->message;
      return r;
    }
    r.failure = f;
    r.failed_at = static_cast<int>(program.commands.size());
  }
  return r;
}

}  // namespace vgc

namespace vgc {

const char* property_skip_name(PropertySkip s) {
  switch (s) {
    case PropertySkip::None: return "none";
    case PropertySkip::NotSelected: return "not-selected";
    case PropertySkip::OtherShard: return "other-shard";
    case PropertySkip::NotOnRoute: return "not-on-route";
    case PropertySkip::NotClaimed: return "not-claimed";
    case PropertySkip::NoOracle: return "no-oracle";
    case PropertySkip::Preflight: return "preflight";
  }
  return "none";
}

PropertySkip property_skip_named(const std::string& name) {
  for (PropertySkip s : {PropertySkip::NotSelected, PropertySkip::OtherShard, PropertySkip::NotOnRoute,
                         PropertySkip::NotClaimed, PropertySkip::NoOracle, PropertySkip::Preflight})
    if (name == property_skip_name(s)) return s;
  return PropertySkip::None;
}

}  // namespace vgc
