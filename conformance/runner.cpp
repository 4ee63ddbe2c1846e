// runner.cpp — see runner.h. run_certification is a spine of named steps:
// ask what the implementation claims, check that it can show a fresh node,
// plan which properties run here, run them (property_run.h), then isolate
// blame, decide each clause (clause_outcome.h) and summarize.
#include "runner.h"

#include <fcntl.h>
#include <rapidcheck.h>
#include <rapidcheck/detail/Configuration.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "cancel.h"
#include "capability.h"
#include "clause_outcome.h"
#include "clause_status.h"
#include "confirm_finding.h"
#include "derived_rule.h"
#include "isolate_blame.h"
#include "property.h"
#include "property_case.h"
#include "property_run.h"
#include "run_budget.h"
#include "shard_plan.h"

namespace vgc {

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

// One certification run, from the first question to the implementation to
// the summary: what the steps of run_certification share.
struct CertificationRun {
  CertificationRun(Implementation& implementation, const RunOptions& options)
      : o(options), recorder(implementation), sut(recorder), budget(options.budget_seconds) {}
  const RunOptions& o;
  // Every call goes through the recorder: a call failure's history since the
  // instance started is then at hand to confirm it (confirm_finding.h).
  HistoryRecorder recorder;
  Implementation& sut;
  RunResult run;
  const Clock::time_point start = Clock::now();
  // --budget counts CPU seconds (run_budget.h) with a wall-clock guard
  // that moves on with the machine's load: every wait asks the budget
  // (past_deadline), so no fixed deadline is set.
  RunBudget budget;
  const Clock::time_point deadline = Clock::time_point::max();
  bool claims_known = false;  // what the implementation claims was asked and answered
  std::vector<std::string> claimed;
  RouteLimits limits;
  // Per property of the catalog: why it does not run here, or nullopt.
  std::vector<std::optional<PropertyOutcome>> not_run;
};

// The run's settings, and every rule of the node and of the derived document counted from 0.
void start_run(CertificationRun* r) {
  r->run.implementation = r->sut.name();
  r->run.options = r->o;
  for (std::size_t i = 1; i < kRuleCount; ++i) r->run.rule_uses[std::string(rule_name(static_cast<Rule>(i)))] = 0;
  for (std::size_t i = 1; i < kDerivedRuleCount; ++i)
    r->run.rule_uses[std::string(derived_rule_name(static_cast<DerivedRule>(i)))] = 0;
}

// ?capabilities first: its answer is also where an exec program declares
// what it does not show (declared_profile.h), which the limits and the
// fresh-node check follow. A cancelled run asks nothing more: the
// question would end unanswered and read as "claims nothing"
// (stopped_before_claims).
void ask_claims(CertificationRun* r) {
  r->claims_known = !cancel_signal();
  if (r->claims_known) r->claimed = query_capabilities(r->sut);
  r->claims_known = r->claims_known && !cancel_signal();
  r->limits = r->sut.limits();
}

// Which properties run at all (why_not_run), then which of them run in this
// shard (shard_plan.h): every other one's outcome says why not.
void plan_properties(CertificationRun* r) {
  const auto& props = property_catalog();
  std::vector<bool> runs;
  for (const PropertySpec& spec : props) {
    r->not_run.push_back(why_not_run(spec, r->o, r->run, r->limits, r->claimed));
    if (!r->claims_known && r->not_run.back() && r->not_run.back()->skip == PropertySkip::NotClaimed)
      r->not_run.back() = stopped_before_claims(*r->not_run.back(), spec, r->o);
    runs.push_back(!r->not_run.back());
  }
  const std::vector<int> shard = assign_shards(runs, r->o.shard_count, r->o.cases, !r->limits.at_scale);
  for (std::size_t i = 0; i < props.size(); ++i) {
    if (r->not_run[i] || shard[i] < 0 || shard[i] == r->o.shard_index) continue;
    PropertyOutcome elsewhere;
    elsewhere.id = std::string(props[i].id);
    elsewhere.seed = property_seed(r->o.seed, props[i].id);
    elsewhere.status = PropertyStatus::Skipped;
    elsewhere.skip = PropertySkip::OtherShard;
    elsewhere.note = "in shard " + std::to_string(shard[i] + 1) + "/" + std::to_string(r->o.shard_count);
    r->not_run[i] = elsewhere;
  }
}

// The properties in catalog order: each one planned here runs, every other
// one's outcome is recorded as planned.
void run_properties(CertificationRun* r) {
  RunProgress progress;
  progress.property_count = static_cast<int>(property_catalog().size());
  for (std::size_t i = 0; i < r->not_run.size(); ++i) {
    if (r->not_run[i]) r->run.properties.push_back(*r->not_run[i]);
    else run_one_property(i, r->sut, r->o, r->deadline, r->start, &progress, &r->run);
  }
}

// Blame isolated, each clause decided, the run summarized.
void finish_run(CertificationRun* r) {
  r->run.route = r->limits.route;
  isolate_findings(r->sut, &r->run);
  decide_clauses(r->o, r->limits, &r->run);
  if (cancel_signal()) r->run.cancelled_by = cancel_signal_name();
  summarize_run(&r->run);
  r->run.seconds = std::chrono::duration<double>(Clock::now() - r->start).count();
}

}  // namespace

RunResult run_certification(Implementation& implementation, const RunOptions& o) {
  load_rapidcheck_configuration_quietly();
  CertificationRun r(implementation, o);
  RunBudgetScope budget_scope(&r.budget);
  start_run(&r);
  ask_claims(&r);
  r.run.preflight = preflight(r.sut);
  plan_properties(&r);
  run_properties(&r);
  finish_run(&r);
  return std::move(r.run);
}

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
