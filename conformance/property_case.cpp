// property_case.cpp — see property_case.h.
#include "property_case.h"

#include <rapidcheck.h>
#include <rapidcheck/state.h>

#include <algorithm>
#include <sstream>

#include "cancel.h"
#include "capability_run.h"
#include "command_text.h"
#include "derived_rule.h"
#include "exercised_clauses.h"
#include "isolate_blame.h"
#include "route_limit_clauses.h"
#include "scale_mesh.h"

namespace vgc {
namespace {

thread_local CaseContext* g_context = nullptr;
thread_local RunBudget* g_budget = nullptr;  // the run's --budget (run_budget.h), set by RunBudgetScope

}  // namespace

CaseScope::CaseScope(CaseContext* c) { g_context = c; }

CaseScope::~CaseScope() { g_context = nullptr; }

RunBudgetScope::RunBudgetScope(RunBudget* budget) { g_budget = budget; }

RunBudgetScope::~RunBudgetScope() { g_budget = nullptr; }

CaseContext* current_case() { return g_context; }

bool run_budget_spent() { return g_budget && g_budget->spent(); }

std::string run_budget_why() { return g_budget ? g_budget->why() : std::string(); }

bool is_tolerated(const CaseContext& c, const Finding& f) {
  const auto it = c.tolerated.find(f.clause);
  if (it == c.tolerated.end() || finding_severity(f) > it->second) return false;
  if (finding_severity(f) < it->second || !kind_tells_differences_apart(f)) return true;
  // The same kind, which tells differences apart: tolerated only for a
  // difference found.
  return c.tolerated_differences.count({f.clause, f.difference}) > 0;
}

void tolerate(CaseContext& c, const Finding& f) {
  int& worst = c.tolerated[f.clause];
  worst = std::max(worst, finding_severity(f));
  if (kind_tells_differences_apart(f)) c.tolerated_differences.insert({f.clause, f.difference});
}

bool case_fails_fresh(const CaseContext& c, const Finding& f, const Program& program) {
  HistoryRecorder& recorder = *c.recorder;
  return is_call_failure(f) ? fails_fresh(recorder, f, program) : reproduces_fresh(recorder, f, program);
}

namespace {

bool owns_case(const CaseContext& c, int index) {
  return c.shard_count <= 1 || index % c.shard_count == c.shard_index;
}

// The budget ran out (CPU seconds, or its wall-clock guard: run_budget.h),
// or the run was cancelled (cancel.h): either way no further case runs and
// the case under way is not judged.
bool past_deadline() {
  if (Clock::now() < g_context->deadline && !cancel_signal() && !(g_budget && g_budget->spent())) return false;
  g_context->deadline_hit = true;
  return true;
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

// A finding of any kind is confirmed on a fresh instance before it is
// shrunk or blamed (confirm_finding.h). Returns false when the case is set
// aside instead: it does not fail a fresh instance, and the run already
// has a finding that depends on the history for that kind of failure.
bool confirm_before_shrinking(const Finding& f, const std::optional<CapabilityRequest>& request) {
  CaseContext& c = *g_context;
  if (c.shrinking || !c.recorder || f.status == FindingStatus::NotJudged) return true;
  const Program program{c.trace, request};
  const std::vector<std::vector<Command>> history = c.recorder->history();
  const bool reproduced = case_fails_fresh(c, f, program);
  if (!reproduced && c.history_kinds.count(finding_kind_of(f))) {
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
      if (r.derived_judged && r.expected == Reason::Ok)  // the derived document's rules its lines put to the test
        for (DerivedRule rule : derived_rules_changed(derived_changed, r.rules, after))
          ++(*c.rule_uses)[std::string(derived_rule_name(rule))];
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
  if (auto f = reset_and_check_fresh(*c.sut)) {
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
// late subscriber), against the model; every difference is localized and
// blamed (program_checker.h check_late_view). The case's steps were all
// judged, so a difference in a clause tolerated at that kind is noted, not
// set aside, and the next difference is looked at; a shape of difference
// already localized to such a clause is not localized again (each costs a
// bisection: reset and replay). False ends the case.
bool check_late_view(CaseContext& c) {
  if (!case_still_judged(c)) return false;
  const auto localize = [&c](const std::string& shape) {
    if (c.shrinking)
      return c.last_failure && finding_kind_of(*c.last_failure) == FindingKind::HiddenState && shape == c.sought_late_shape;
    const auto it = c.late_shapes.find(shape);
    return it == c.late_shapes.end() || !is_tolerated(c, it->second);
  };
  const auto goes_on = [&c](const std::string& shape, const Localized& l) {
    if (past_deadline()) return false;
    const Finding& f = *l.step.failure;
    if (!c.shrinking) c.late_shapes[shape] = f;
    if (!is_tolerated(c, f)) return false;
    note_tolerated(f);
    return true;
  };
  auto l = c.checker->check_late_view(c.trace, localize, goes_on);
  if (!l || past_deadline()) return true;
  const Finding f = *l->step.failure;
  const std::string shape = c.checker->late_shape();
  if (!c.shrinking) c.late_shapes[shape] = f;
  if (is_tolerated(c, f)) {  // the subscription kept in two formats (goes_on is not asked)
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

}  // namespace

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

}  // namespace vgc
