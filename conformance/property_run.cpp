// property_run.cpp — see property_run.h.
#include "property_run.h"

#include <rapidcheck.h>

#include <algorithm>
#include <set>
#include <string>
#include <utility>

#include "cancel.h"
#include "capability_run.h"
#include "confirm_finding.h"
#include "isolate_blame.h"
#include "replay_program.h"
#include "shard_plan.h"

namespace vgc {
namespace {

// Reports the property's progress as RapidCheck finishes a case or tries a
// shrink.
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
    if (const CaseContext* c = current_case()) {
      p_->cases_done = c->cases_done;
      p_->set_aside = c->set_aside;
    }
    p_->elapsed_seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    if (*cb_) (*cb_)(*p_);
  }
  RunProgress* p_;
  const std::function<void(const RunProgress&)>* cb_;
  Clock::time_point start_;
};

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
  ctx.history_kinds.insert(finding_kind_of(pf->finding));
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
      tolerate(ctx, f.finding);
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
      if (depends_on_history(f.finding)) ctx.history_kinds.insert(finding_kind_of(f.finding));
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
               !case_fails_fresh(ctx, pf.finding, pf.program)) {
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
  tolerate(ctx, pf.finding);
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
    if (ctx.recorder && !cancel_signal() && Clock::now() < deadline && !run_budget_spent() &&
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
    return (run_budget_spent() ? run_budget_why() : std::string("the budget ran out")) + " after " + ran +
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

// What every case of `spec` draws and checks.
CaseSpec case_spec_of(const PropertySpec& spec) {
  CaseSpec cases;
  cases.focus = spec.focus;
  cases.capability = spec.capability.empty() ? nullptr : find_capability_check(std::string(spec.capability));
  cases.capability_name = spec.capability;
  cases.capability_clause_list = capability_clauses(std::string(spec.capability));
  cases.at_scale = spec.at_scale;
  return cases;
}

}  // namespace

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
  const CaseSpec cases = case_spec_of(spec);
  std::string rapidcheck_note;
  {
    CaseScope scope(&ctx);
    rapidcheck_note = run_rounds(cases, ctx, spec, o, deadline, progress, run_start, &out, *run);
  }
  out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const int unconfirmed = confirm_notes(ctx, deadline, &out);
  finish_outcome(ctx, stop_note_of(ctx, rapidcheck_note), unconfirmed, &out);
  return out;
}

}  // namespace vgc
