// runner_test.cpp — run_certification (runner.h): the same seed gives the
// same verdicts, findings and counterexamples; shards partition the
// properties and together give the unsharded result; --clauses selects
// properties and clauses; the budget makes a run incomplete, never a pass;
// property seeds are per property and stable; a counterexample replays;
// SHOULD findings leave the verdict alone.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "command_text.h"
#include "faulty_implementation.h"
#include "property.h"
#include "reference_implementation.h"
#include "runner.h"
#include "verdict.h"
#include "default_run.h"

namespace vgc {
namespace {

RunOptions small(std::uint64_t seed = 11) { return unhurried_run(seed, 100, 40); }

int fault(std::string_view name) {
  const int f = faults::find_fault(name);
  EXPECT_GE(f, 0) << name;
  return f;
}

RunResult run_fault(std::string_view name, const RunOptions& o) {
  faults::FaultyImplementation impl(fault(name));
  return run_certification(impl, o);
}

RunResult run_reference(const RunOptions& o) {
  ReferenceImplementation impl;
  return run_certification(impl, o);
}

std::string describe(const std::optional<Finding>& f) {
  if (!f) return "-";
  return f->clause + "/" + finding_status_name(f->status) + "/" + f->message;
}

// Every finding of a property, with its counterexample, in the order found.
std::string describe_findings(const PropertyOutcome& p) {
  std::string out;
  for (const auto& f : p.findings)
    out += describe(f.finding) + " <- " + print_commands(f.program.commands) + (f.tolerated_from_start ? " (known)" : "") +
           "\n";
  return out;
}

// Everything a run decides, as comparable text, per clause.
std::map<std::string, std::string> clause_view(const RunResult& run) {
  std::map<std::string, std::string> out;
  for (const ClauseOutcome& co : run.clauses)
    out[std::string(co.clause->id)] =
        std::string(clause_status_name(co.status)) + " | " + describe(co.finding) + " | " + print_commands(co.program.commands);
  return out;
}

const ClauseOutcome* clause_in(const RunResult& run, std::string_view id) {
  for (const auto& co : run.clauses)
    if (co.clause->id == id) return &co;
  return nullptr;
}

const PropertyOutcome* property_in(const RunResult& run, std::string_view id) {
  for (const auto& p : run.properties)
    if (p.id == id) return &p;
  return nullptr;
}

TEST(Runner, SameSeedSameResultAgainstAFault) {
  for (const char* name : {"bone-rotation-not-inherited", "edge-crease-off-by-one"}) {
    const RunResult a = run_fault(name, small(5));
    const RunResult b = run_fault(name, small(5));
    const auto& info = faults::fault_catalog()[static_cast<std::size_t>(fault(name))];
    const ClauseOutcome* found = clause_in(a, info.expected_clause);
    ASSERT_NE(found, nullptr) << name;
    ASSERT_TRUE(found->finding) << name << " was not found with 100 cases; the determinism check would be vacuous";
    EXPECT_FALSE(found->program.commands.empty());
    EXPECT_EQ(clause_view(a), clause_view(b)) << name;
    ASSERT_EQ(a.properties.size(), b.properties.size());
    for (std::size_t i = 0; i < a.properties.size(); ++i) {
      EXPECT_EQ(a.properties[i].status, b.properties[i].status) << a.properties[i].id;
      EXPECT_EQ(a.properties[i].seed, b.properties[i].seed) << a.properties[i].id;
      EXPECT_EQ(a.properties[i].cases, b.properties[i].cases) << a.properties[i].id;
      EXPECT_EQ(a.properties[i].judged, b.properties[i].judged) << a.properties[i].id;
      EXPECT_EQ(a.properties[i].set_aside, b.properties[i].set_aside) << a.properties[i].id;
      EXPECT_EQ(describe_findings(a.properties[i]), describe_findings(b.properties[i])) << a.properties[i].id;
    }
    EXPECT_EQ(judge(a, nullptr).new_failures.empty(), judge(b, nullptr).new_failures.empty());
    EXPECT_FALSE(judge(a, nullptr).new_failures.empty()) << name;
  }
}

// The union over shards 1/n..n/n is the unsharded run; every property runs in
// exactly one shard, with the outcome it has unsharded, but a property at
// scale, whose cases are split over the shards (case k in shard k mod n):
// its cases and judged cases add up to the unsharded ones.
void check_shards(const std::function<RunResult(const RunOptions&)>& run, int n, const std::string& what,
                  bool expect_findings) {
  const RunResult whole = run(small(3));
  std::vector<RunResult> shards;
  for (int i = 0; i < n; ++i) {
    RunOptions o = small(3);
    o.shard_index = i;
    o.shard_count = n;
    shards.push_back(run(o));
  }
  const auto& props = property_catalog();
  for (std::size_t p = 0; p < props.size(); ++p) {
    const PropertyOutcome& w = whole.properties[p];
    ASSERT_NE(w.status, PropertyStatus::Skipped) << what << ": " << w.id;
    int ran_in = 0;
    if (props[p].at_scale) {
      int cases = 0, judged = 0;
      for (int i = 0; i < n; ++i) {
        const PropertyOutcome& s = shards[static_cast<std::size_t>(i)].properties[p];
        EXPECT_EQ(s.seed, w.seed) << what << ": a shard changed the seed of " << w.id;
        cases += s.cases;
        judged += s.judged;
      }
      EXPECT_EQ(cases, w.cases) << what << ": " << w.id << " split over the shards";
      if (!expect_findings) {
        EXPECT_EQ(judged, w.judged) << what << ": " << w.id << " split over the shards";
      }
      continue;
    }
    for (int i = 0; i < n; ++i) {
      const PropertyOutcome& s = shards[static_cast<std::size_t>(i)].properties[p];
      EXPECT_EQ(s.seed, w.seed) << what << ": a shard changed the seed of " << w.id;
      if (s.status == PropertyStatus::Skipped) {
        EXPECT_NE(s.note.find("shard"), std::string::npos) << what << ": " << s.note;
        continue;
      }
      ++ran_in;
      EXPECT_EQ(s.status, w.status) << what << ": " << w.id;
      EXPECT_EQ(describe_findings(s), describe_findings(w)) << what << ": " << w.id;
      ASSERT_EQ(s.notes.size(), w.notes.size()) << what << ": " << w.id;
      for (std::size_t k = 0; k < s.notes.size(); ++k) {
        EXPECT_EQ(describe(s.notes[k].first), describe(w.notes[k].first)) << what << ": " << w.id;
        EXPECT_EQ(print_commands(s.notes[k].second.commands), print_commands(w.notes[k].second.commands));
      }
    }
    EXPECT_EQ(ran_in, 1) << what << ": property " << w.id << " ran in " << ran_in << " of " << n << " shards";
  }
  int whole_findings = 0;
  for (const ClauseOutcome& w : whole.clauses) whole_findings += w.finding.has_value();
  if (expect_findings) EXPECT_GE(whole_findings, 1) << what << ": the fault was not found; the check is vacuous";
  else EXPECT_EQ(whole_findings, 0) << what;
  // Per clause: a finding in the whole run is the finding of some shard;
  // a clause that passes whole passes in a shard and fails in none.
  for (const ClauseOutcome& w : whole.clauses) {
    const std::string id(w.clause->id);
    std::set<ClauseStatus> statuses;
    bool same_finding = false;
    for (const auto& s : shards) {
      const ClauseOutcome* c = clause_in(s, id);
      ASSERT_NE(c, nullptr) << what << ": shard lacks " << id;
      statuses.insert(c->status);
      if (w.finding && c->finding && describe(c->finding) == describe(w.finding) &&
          print_commands(c->program.commands) == print_commands(w.program.commands))
        same_finding = true;
    }
    if (w.finding) {
      EXPECT_TRUE(same_finding) << what << ": " << id << " " << describe(w.finding) << " is in no shard";
    } else {
      EXPECT_EQ(w.status, ClauseStatus::Pass) << what << ": " << id << " (" << w.note << ")";
      EXPECT_TRUE(statuses.count(ClauseStatus::Pass)) << what << ": " << id;
      for (const auto& st : statuses) EXPECT_TRUE(st == ClauseStatus::Pass || st == ClauseStatus::Skipped) << what << ": " << id << " " << st;
    }
  }
  // And no shard finds anything the whole run does not report.
  for (const auto& s : shards)
    for (const auto& c : s.clauses)
      if (c.finding) {
        const ClauseOutcome* w = clause_in(whole, c.clause->id);
        ASSERT_NE(w, nullptr);
        EXPECT_TRUE(w->finding) << what << ": only a shard found " << c.clause->id;
      }
  for (const auto& s : shards) {
    EXPECT_TRUE(s.complete) << what << ": a shard's other-shard clauses are not missing work";
    if (judge(whole, nullptr).new_failures.empty()) {
      EXPECT_TRUE(judge(s, nullptr).new_failures.empty()) << what;
    }
  }
  bool any_nonconformant = false;
  for (const auto& s : shards) any_nonconformant = any_nonconformant || !judge(s, nullptr).new_failures.empty();
  EXPECT_EQ(any_nonconformant, !judge(whole, nullptr).new_failures.empty()) << what;
}

TEST(Runner, ShardsPartitionTheReferenceRun) {
  check_shards(run_reference, 3, "reference", false);
}

TEST(Runner, ShardsPartitionAFaultyRun) {
  // One fault found by a failing case, one seen as SHOULD notes in many properties.
  for (const char* name : {"bone-rotation-not-inherited", "wrong-reason-codes"})
    check_shards([name](const RunOptions& o) { return run_fault(name, o); }, 3, name, true);
}

// A property at scale does not confirm and shrink again what an earlier
// property of the run found (the same clause, the same or a milder kind):
// its case is set aside where it diverges, the divergence is listed as
// first seen (not shrunk), and the clause keeps the earlier, shorter
// counterexample. Through an out-of-process route the shrinking of one
// such case at scale took about a minute (Cli.EveryReportGivesTheSameCountsPerStatus:
// 63 s of a 64 s certify); the clause statuses are the same either way.
TEST(Runner, AtScaleAClauseAnEarlierPropertyFoundIsNotShrunkAgain) {
  const RunResult run = run_fault("polygon-delete-ignored", small(1));
  const ClauseOutcome* found = clause_in(run, "POLY-DELETE-1");
  ASSERT_NE(found, nullptr);
  ASSERT_TRUE(found->finding) << "the fault was not found: the check below would be vacuous";
  EXPECT_NE(found->found_by, "storage.scale");
  const PropertyOutcome* scale = property_in(run, "storage.scale");
  ASSERT_NE(scale, nullptr);
  bool seen_at_scale = false;
  for (const auto& pf : scale->findings) {
    if (pf.finding.clause != "POLY-DELETE-1") continue;
    seen_at_scale = true;
    EXPECT_TRUE(pf.tolerated_from_start) << "shrunk again at scale: " << describe_findings(*scale);
  }
  EXPECT_TRUE(seen_at_scale) << "storage.scale did not reach the divergence: " << describe_findings(*scale);
  EXPECT_EQ(scale->rounds, 1) << describe_findings(*scale);
  EXPECT_NE(scale->status, PropertyStatus::Stopped) << scale->note;
}

TEST(Runner, ClauseSelectedIsACommaSeparatedGlob) {
  EXPECT_TRUE(clause_selected("*", "LAYER-BASE-1"));
  EXPECT_TRUE(clause_selected("", "LAYER-BASE-1"));  // empty: everything
  EXPECT_TRUE(clause_selected("LAYER-*", "LAYER-BASE-1"));
  EXPECT_FALSE(clause_selected("LAYER-*", "BONE-FOREST-1"));
  EXPECT_TRUE(clause_selected("LAYER-*,BONE-*", "BONE-FOREST-1"));
  EXPECT_TRUE(clause_selected("BONE-FOREST-1", "BONE-FOREST-1"));
  EXPECT_FALSE(clause_selected("BONE-FOREST-1", "BONE-FOREST-10"));  // whole id, not a prefix
  EXPECT_FALSE(clause_selected("BONE-FOREST", "BONE-FOREST-1"));
  EXPECT_TRUE(clause_selected("LAYER-BASE-?", "LAYER-BASE-2"));
  EXPECT_FALSE(clause_selected("LAYER-BASE-?", "LAYER-BASE-12"));
  EXPECT_TRUE(clause_selected("[LB]*-1", "BONE-VALUE-1"));
  EXPECT_FALSE(clause_selected("[LB]*-1", "CREASE-NAME-1"));
  EXPECT_TRUE(clause_selected(",,CREASE-*,", "CREASE-NAME-1"));  // empty alternatives are ignored
  EXPECT_FALSE(clause_selected(",", "CREASE-NAME-1"));
  EXPECT_FALSE(clause_selected("layer-*", "LAYER-BASE-1"));  // ids are upper case; matching is exact
}

TEST(Runner, ClauseFilterRunsOnlyDeclaringPropertiesAndReportsFindingsOutsideIt) {
  // BONE-CREATE-1 is declared by bones.stateful only; the fault breaks
  // BONE-FOREST-1, which bones.stateful finds although it was not asked for.
  RunOptions o = small(4);
  o.clause_glob = "BONE-CREATE-1";
  const RunResult run = run_fault("bone-cycles-accepted", o);
  for (const auto& p : property_catalog()) {
    bool declares = false;
    for (auto c : p.clauses) declares = declares || clause_selected(o.clause_glob, c);
    const PropertyOutcome* po = property_in(run, p.id);
    ASSERT_NE(po, nullptr);
    if (declares) EXPECT_NE(po->status, PropertyStatus::Skipped) << p.id;
    else EXPECT_EQ(po->status, PropertyStatus::Skipped) << p.id;
  }
  EXPECT_NE(property_in(run, "bones.stateful")->status, PropertyStatus::Skipped);
  std::set<std::string> reported;
  for (const auto& co : run.clauses) {
    reported.insert(std::string(co.clause->id));
    EXPECT_TRUE(clause_selected(o.clause_glob, co.clause->id) || co.finding)
        << co.clause->id << " is reported but neither selected nor found";
  }
  EXPECT_TRUE(reported.count("BONE-CREATE-1"));
  ASSERT_TRUE(reported.count("BONE-FOREST-1")) << "a finding outside the filter was dropped";
  EXPECT_EQ(clause_in(run, "BONE-FOREST-1")->status, ClauseStatus::Fail);
  EXPECT_FALSE(reported.count("LAYER-BASE-1"));
  EXPECT_TRUE(judge(run, nullptr).new_failures.empty()) << "BONE-FOREST-1 is IMPLEMENTATION-DEFINED: a profile difference";
  EXPECT_EQ(judge(run, nullptr).exit_code, 0);
  EXPECT_EQ(judge(run, nullptr, /*strict=*/true).exit_code, 1);

  // A glob over several groups runs each declaring property, and only those.
  RunOptions two = small(4);
  two.clause_glob = "CREASE-*,ID-BOUND-1";
  two.cases = 200;  // the default: enough for every selected clause to be exercised (else it is unchecked)
  const RunResult r2 = run_reference(two);
  std::set<std::string> ran;
  for (const auto& p : r2.properties)
    if (p.status != PropertyStatus::Skipped) ran.insert(p.id);
  // (storage.scale declares CREASE-VERTEX-LAYER-1, CREASE-EDGE-LAYER-1 and ID-BOUND-1 too.)
  EXPECT_EQ(ran, (std::set<std::string>{"creases.stateful", "ids.stateful", "storage.scale"}));
  for (const auto& co : r2.clauses) EXPECT_TRUE(clause_selected(two.clause_glob, co.clause->id)) << co.clause->id;
  EXPECT_TRUE(judge(r2, nullptr).new_failures.empty());
  EXPECT_TRUE(r2.complete);
  for (const auto& co : r2.clauses) EXPECT_EQ(co.status, ClauseStatus::Pass) << co.clause->id << ": " << co.note;
}

TEST(Runner, ATinyBudgetMakesTheRunIncomplete) {
  RunOptions o = small(1);
  o.budget_seconds = 1e-6;
  const RunResult run = run_reference(o);
  int incomplete = 0;
  for (const auto& p : run.properties) {
    EXPECT_NE(p.status, PropertyStatus::Pass) << p.id << " passed without running its cases";
    incomplete += p.status == PropertyStatus::Stopped;
  }
  EXPECT_GE(incomplete, 1);
  for (const auto& co : run.clauses) EXPECT_NE(co.status, ClauseStatus::Pass) << co.clause->id;
  EXPECT_FALSE(run.complete);
  const Verdict v = judge(run, nullptr);
  EXPECT_EQ(v.name, "incomplete");
  EXPECT_EQ(v.exit_code, 2);
}

TEST(Runner, PropertySeedsArePerPropertyAndStable) {
  for (std::uint64_t run_seed : {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{2}, ~std::uint64_t{0}}) {
    std::set<std::uint64_t> seeds;
    for (const auto& p : property_catalog()) {
      const std::uint64_t s = property_seed(run_seed, p.id);
      EXPECT_EQ(s, property_seed(run_seed, p.id));
      seeds.insert(s);
    }
    EXPECT_EQ(seeds.size(), property_catalog().size()) << "two properties share a seed for run seed " << run_seed;
  }
  EXPECT_NE(property_seed(1, "layers.stateful"), property_seed(2, "layers.stateful"));
  // The seed a property runs with depends on the run seed and its id only:
  // not on the clause filter, nor on which other properties run.
  RunOptions o = small(9);
  o.budget_seconds = 1e-6;
  const RunResult all = run_reference(o);
  o.clause_glob = "BONE-*";
  const RunResult bones = run_reference(o);
  for (std::size_t i = 0; i < all.properties.size(); ++i) {
    EXPECT_EQ(all.properties[i].seed, property_seed(9, all.properties[i].id));
    EXPECT_EQ(bones.properties[i].seed, all.properties[i].seed);
  }
}

TEST(Runner, ACounterexampleReplaysAgainstTheFaultAndPassesTheReference) {
  for (const char* name : {"bone-cycles-accepted", "edge-crease-off-by-one"}) {
    const auto& info = faults::fault_catalog()[static_cast<std::size_t>(fault(name))];
    const RunResult run = run_fault(name, small(5));
    const ClauseOutcome* co = clause_in(run, info.expected_clause);
    ASSERT_NE(co, nullptr);
    ASSERT_TRUE(co->finding) << name;
    Program program = co->program;
    // Through the text form, as a counterexample file travels.
    std::vector<Command> parsed;
    TextError error;
    ASSERT_TRUE(parse_commands(print_commands(program.commands), &parsed, &error)) << error.to_string();
    program.commands = parsed;

    faults::FaultyImplementation faulty(fault(name));
    const ReplayResult again = replay_program(program, faulty);
    ASSERT_TRUE(again.failure) << name;
    EXPECT_EQ(again.failure->clause, info.expected_clause);
    EXPECT_EQ(again.failure->status, co->finding->status);
    EXPECT_EQ(again.failed_at, static_cast<int>(program.commands.size()) - 1)
        << "the shrunk program should fail on its last command";

    ReferenceImplementation reference;
    const ReplayResult clean = replay_program(program, reference);
    EXPECT_FALSE(clean.failure) << describe(clean.failure);
    EXPECT_TRUE(clean.notes.empty());
  }
}

TEST(Runner, ShouldOnlyFindingsLeaveTheVerdictConformant) {
  RunOptions o = small(2);
  const RunResult run = run_fault("wrong-reason-codes", o);
  const ClauseOutcome* reason = clause_in(run, "REASON-1");
  ASSERT_NE(reason, nullptr);
  ASSERT_TRUE(reason->finding) << "the wrong reason codes were not noticed";
  EXPECT_EQ(reason->status, ClauseStatus::Fail);
  for (const auto& co : run.clauses)
    if (co.clause->id != "REASON-1") {
      EXPECT_FALSE(co.finding) << co.clause->id << ": " << describe(co.finding);
    }
  EXPECT_TRUE(judge(run, nullptr).new_failures.empty());
  const Verdict v = judge(run, nullptr);
  EXPECT_EQ(v.name, "conformant");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.should_failures, std::vector<std::string>{"REASON-1"});
  EXPECT_TRUE(v.new_failures.empty());

  // The note's program replays to the same SHOULD note, not to a failure.
  faults::FaultyImplementation faulty(fault("wrong-reason-codes"));
  const ReplayResult r = replay_program(reason->program, faulty);
  EXPECT_FALSE(r.failure) << describe(r.failure);
  ASSERT_FALSE(r.notes.empty());
  EXPECT_EQ(r.notes.back().clause, "REASON-1");
}

}  // namespace
}  // namespace vgc
