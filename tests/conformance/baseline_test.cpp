// baseline_test.cpp — the baseline file (baseline.h) and judge() (verdict.h):
// parse errors name their line; a baselined failure is "known" and does not
// fail the verdict, an unbaselined one does; a baselined clause that now
// passes is "stale"; SHOULD failures and incomplete runs keep their meaning.
#include <gtest/gtest.h>

#include <cstdio>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "baseline.h"
#include "clause.h"
#include "runner.h"
#include "verdict.h"

namespace vgc {
namespace {

std::string parse_error(const std::string& text) {
  Baseline b;
  std::string error;
  EXPECT_FALSE(parse_baseline(text, &b, &error)) << "accepted:\n" << text;
  return error;
}

TEST(Baseline, CommentsBlankLinesAndReasons) {
  Baseline b;
  std::string error;
  const std::string text =
      "# known deviations of our host\n"
      "\n"
      "   \t\n"
      "BONE-FOREST-1   r6 stores cycles; fixed in 2.0\n"
      "  # indented comment\n"
      "\tLAYER-NAME-2\tnames are not unique in our host\r\n"
      "REASON-1 we report no reasons\n";
  ASSERT_TRUE(parse_baseline(text, &b, &error)) << error;
  EXPECT_EQ(b.reasons.size(), 3u);
  EXPECT_EQ(b.reasons.at("BONE-FOREST-1"), "r6 stores cycles; fixed in 2.0");
  EXPECT_EQ(b.reasons.at("LAYER-NAME-2"), "names are not unique in our host");  // no '\r'
  EXPECT_EQ(b.reasons.at("REASON-1"), "we report no reasons");

  Baseline empty;
  EXPECT_TRUE(parse_baseline("", &empty, &error));
  EXPECT_TRUE(parse_baseline("# nothing\n\n", &empty, &error));
  EXPECT_TRUE(empty.reasons.empty());
}

TEST(Baseline, AnUnknownIdNamesItsLine) {
  const std::string e = parse_error("# header\n\nBONE-FOREST-1 ok\nBONE-FORREST-1 typo\n");
  EXPECT_EQ(e.rfind("4:1:", 0), 0u) << e;
  EXPECT_NE(e.find("BONE-FORREST-1"), std::string::npos) << e;
  EXPECT_NE(e.find("vgc clauses"), std::string::npos) << "names where the ids are: " << e;
  EXPECT_EQ(parse_error("  BONE-FORREST-1 indented\n").rfind("1:3:", 0), 0u);
}

TEST(Baseline, AMissingReasonNamesItsLine) {
  const std::string e = parse_error("LAYER-BASE-1 fine\nLAYER-BASE-2\n");
  EXPECT_EQ(e.rfind("2:13:", 0), 0u) << "the column after the id: " << e;
  EXPECT_NE(e.find("LAYER-BASE-2"), std::string::npos) << e;
  EXPECT_NE(e.find("reason"), std::string::npos) << e;
  // Blanks after the id are not a reason.
  EXPECT_EQ(parse_error("LAYER-BASE-2   \t\n").rfind("1:13:", 0), 0u);
}

TEST(Baseline, ADuplicateNamesTheSecondLine) {
  const std::string e = parse_error("ATOMIC-1 a\n# between\nSTABLE-1 b\nATOMIC-1 again\n");
  EXPECT_EQ(e.rfind("4:1:", 0), 0u) << e;
  EXPECT_NE(e.find("ATOMIC-1"), std::string::npos) << e;
  EXPECT_NE(e.find("first on line 1"), std::string::npos) << e;
}

TEST(Baseline, LoadNamesTheFileAndLine) {
  const auto path = std::filesystem::temp_directory_path() / ("vgc_baseline_test_" + std::to_string(::getpid()) + ".txt");
  {
    std::ofstream f(path);
    f << "# ok\nNOT-A-CLAUSE-1 reason\n";
  }
  Baseline b;
  std::string error;
  EXPECT_FALSE(load_baseline(path.string(), &b, &error));
  EXPECT_EQ(error.rfind(path.string() + ":2:", 0), 0u) << error;
  std::filesystem::remove(path);
  EXPECT_FALSE(load_baseline(path.string(), &b, &error));
  EXPECT_NE(error.find(path.string()), std::string::npos) << error;
}

// A run result made by hand: `failing` clauses failed, `passing` passed.
RunResult run_with(const std::vector<std::string>& failing, const std::vector<std::string>& passing,
                   bool complete = true) {
  RunResult run;
  run.complete = complete;
  for (const auto& id : passing) {
    ClauseOutcome co;
    co.clause = find_clause(id);
    EXPECT_NE(co.clause, nullptr) << id;
    co.status = ClauseStatus::Pass;
    run.clauses.push_back(co);
  }
  for (const auto& id : failing) {
    ClauseOutcome co;
    co.clause = find_clause(id);
    EXPECT_NE(co.clause, nullptr) << id;
    co.status = ClauseStatus::Fail;
    co.finding = Finding{id, FindingStatus::Fail, "observed something else"};
    run.clauses.push_back(co);
  }
  return run;
}

Baseline baseline_of(const std::string& text) {
  Baseline b;
  std::string error;
  EXPECT_TRUE(parse_baseline(text, &b, &error)) << error;
  return b;
}

TEST(Judge, NoBaseline) {
  const Verdict pass = judge(run_with({}, {"LAYER-BASE-1", "BONE-FOREST-1"}), nullptr);
  EXPECT_EQ(pass.name, "conformant");
  EXPECT_EQ(pass.exit_code, 0);
  const Verdict fail = judge(run_with({"BONE-DOWNSTREAM-1"}, {"LAYER-BASE-1"}), nullptr);
  EXPECT_EQ(fail.name, "not-conformant");
  EXPECT_EQ(fail.exit_code, 1);
  EXPECT_EQ(fail.new_failures, std::vector<std::string>{"BONE-DOWNSTREAM-1"});
}

TEST(Judge, ABaselinedFailureIsKnownAndDoesNotFail) {
  const Baseline b = baseline_of("BONE-FOREST-1 r6 stores cycles\n");
  const Verdict v = judge(run_with({"BONE-FOREST-1"}, {"LAYER-BASE-1"}), &b);
  EXPECT_EQ(v.name, "conformant");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.known_failures, std::vector<std::string>{"BONE-FOREST-1"});
  EXPECT_TRUE(v.new_failures.empty());
  EXPECT_TRUE(v.stale_baseline.empty());
  // A crash of a baselined clause is known too.
  RunResult crashed = run_with({"BONE-FOREST-1"}, {});
  crashed.clauses[0].status = ClauseStatus::Crash;
  crashed.clauses[0].finding->status = FindingStatus::Crash;
  EXPECT_EQ(judge(crashed, &b).exit_code, 0);
}

TEST(Judge, AnUnbaselinedFailureFailsEvenBesideAKnownOne) {
  const Baseline b = baseline_of("BONE-FOREST-1 r6 stores cycles\n");
  const Verdict v = judge(run_with({"BONE-FOREST-1", "LAYER-NAME-1"}, {}), &b);
  EXPECT_EQ(v.name, "not-conformant");
  EXPECT_EQ(v.exit_code, 1);
  EXPECT_EQ(v.new_failures, std::vector<std::string>{"LAYER-NAME-1"});
  EXPECT_EQ(v.known_failures, std::vector<std::string>{"BONE-FOREST-1"});
}

TEST(Judge, ABaselinedPassingClauseIsStale) {
  const Baseline b = baseline_of("BONE-FOREST-1 was broken\nLAYER-NAME-2 not run here\n");
  // LAYER-NAME-2 is not in the run at all (filtered out): not stale, it was not checked.
  const Verdict v = judge(run_with({}, {"BONE-FOREST-1", "LAYER-BASE-1"}), &b);
  EXPECT_EQ(v.stale_baseline, std::vector<std::string>{"BONE-FOREST-1"});
  EXPECT_EQ(v.name, "conformant");
  EXPECT_EQ(v.exit_code, 0);
  // Skipped is not passing.
  RunResult skipped = run_with({}, {"BONE-FOREST-1"});
  skipped.clauses[0].status = ClauseStatus::Skipped;
  EXPECT_TRUE(judge(skipped, &b).stale_baseline.empty());
}

TEST(Judge, ShouldFailuresAndIncompleteRuns) {
  const Verdict should = judge(run_with({"REASON-1"}, {"LAYER-BASE-1"}), nullptr);
  EXPECT_EQ(should.name, "conformant");
  EXPECT_EQ(should.should_failures, std::vector<std::string>{"REASON-1"});
  EXPECT_TRUE(should.new_failures.empty());

  const Verdict incomplete = judge(run_with({}, {"LAYER-BASE-1"}, /*complete=*/false), nullptr);
  EXPECT_EQ(incomplete.name, "incomplete");
  EXPECT_EQ(incomplete.exit_code, 2);
  // A real failure outranks incompleteness; a known one does not.
  EXPECT_EQ(judge(run_with({"ATOMIC-1"}, {}, false), nullptr).exit_code, 1);
  const Baseline b = baseline_of("ATOMIC-1 known\n");
  EXPECT_EQ(judge(run_with({"ATOMIC-1"}, {}, false), &b).exit_code, 2);
}

TEST(Judge, ImplementationDefinedDifferencesGateOnlyWhenStrict) {
  // BONE-FOREST-1 is IMPLEMENTATION-DEFINED (the spec is silent on cycles).
  const RunResult run = run_with({"BONE-FOREST-1"}, {"LAYER-BASE-1"});
  const Verdict lax = judge(run, nullptr);
  EXPECT_EQ(lax.name, "conformant");
  EXPECT_EQ(lax.exit_code, 0);
  EXPECT_EQ(lax.profile_differences, std::vector<std::string>{"BONE-FOREST-1"});
  EXPECT_TRUE(lax.new_failures.empty());
  const Verdict strict = judge(run, nullptr, /*strict=*/true);
  EXPECT_EQ(strict.name, "not-conformant");
  EXPECT_EQ(strict.new_failures, std::vector<std::string>{"BONE-FOREST-1"});
  EXPECT_TRUE(strict.profile_differences.empty());
  // A crash is never a reading of a silent point: it gates without --strict.
  RunResult crashed = run;
  crashed.clauses.back().status = ClauseStatus::Crash;
  crashed.clauses.back().finding->status = FindingStatus::Crash;
  EXPECT_EQ(judge(crashed, nullptr).new_failures, std::vector<std::string>{"BONE-FOREST-1"});
}

TEST(Judge, UncheckedClausesMakeTheRunIncompleteNeverConformant) {
  RunResult run = run_with({}, {"LAYER-BASE-1", "POLY-DELETE-1"});
  run.clauses[1].status = ClauseStatus::Unchecked;
  run.clauses[1].note = "0 judged commands exercised it";
  run.complete = false;
  const Verdict v = judge(run, nullptr);
  EXPECT_EQ(v.name, "incomplete");
  EXPECT_EQ(v.exit_code, 2);
  EXPECT_EQ(v.unchecked, std::vector<std::string>{"POLY-DELETE-1"});
}

}  // namespace
}  // namespace vgc
