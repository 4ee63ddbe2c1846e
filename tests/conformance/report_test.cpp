// report_test.cpp — write_report (report.h): a run directory holding
// report.json, junit.xml, summary.md and one replayable counterexample per
// failing clause, written whole or not at all, with reports/latest pointing
// at it. Every file is read back with a real parser (nlohmann::json,
// pugixml, vgc::parse_commands), not searched for strings only.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <fmt/format.h>
#include <pugixml.hpp>
#include <set>
#include <sstream>

#include "confirm_finding.h"
#include "capability_test_util.h"
#include "command_text.h"
#include "exec_implementation.h"  // shell_quote
#include "faulty_implementation.h"
#include "merge_runs.h"
#include "property.h"
#include "reference_implementation.h"
#include "report.h"
#include "runner.h"
#include "verdict.h"

namespace vgc {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFault = "bone-rotation-not-inherited";
constexpr const char* kClause = "BONE-DOWNSTREAM-1";  // MUST: it gates

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  EXPECT_TRUE(in) << "cannot read " << p;
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() / ("vgc_report_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter_++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  static inline int counter_ = 0;
  fs::path path_;
};

// One certification of the faulty node, restricted to the bone clauses so
// that it takes a second; BONE-DOWNSTREAM-1 fails, the other BONE-* pass.
const RunResult& faulty_run() {
  static const RunResult run = [] {
    faults::FaultyImplementation impl(faults::find_fault(kFault));
    RunOptions o;
    o.seed = 21;
    o.cases = 30;
    o.max_size = 30;
    o.clause_glob = "BONE-*";
    return run_certification(impl, o);
  }();
  return run;
}

const ClauseOutcome& failing_clause(const RunResult& run) {
  for (const auto& co : run.clauses)
    if (co.clause->id == kClause) return co;
  ADD_FAILURE() << kClause << " not in the run";
  return run.clauses.front();
}

struct Written {
  ReportContext ctx;
  Verdict verdict;
  fs::path root, dir;
  bool ok = false;
  std::string error;
};

Written write(const fs::path& root, const RunResult& run, const std::string& impl_spec, const std::string& started) {
  Written w;
  w.ctx.implementation_spec = impl_spec;
  w.ctx.command_line = "./vgc certify --impl " + shell_quote(impl_spec) + " --seed " + std::to_string(run.options.seed);
  w.ctx.started = started;
  w.root = root;
  w.ctx.run_dir = default_run_dir(root.string(), run, w.ctx);
  w.dir = w.ctx.run_dir;
  w.verdict = judge(run, nullptr);
  w.ok = write_report(root.string(), run, w.verdict, w.ctx, &w.error);
  return w;
}

class Report : public ::testing::Test {
 protected:
  void SetUp() override {
    const RunResult& run = faulty_run();
    ASSERT_TRUE(failing_clause(run).finding) << "the fault was not found; nothing to report";
    w_ = write(tmp_.path() / "reports", run, "exec:./my host --serve", "2026-11-22T04:00:00Z");
    ASSERT_TRUE(w_.ok) << w_.error;
  }
  TempDir tmp_;
  Written w_;
};

TEST_F(Report, JsonHasVerdictSeedAndEveryClause) {
  const RunResult& run = faulty_run();
  const auto j = nlohmann::json::parse(read(w_.dir / "report.json"));
  EXPECT_EQ(j.at("verdict"), "not-conformant");
  EXPECT_EQ(j.at("exit_code"), 1);
  EXPECT_EQ(j.at("seed"), 21);
  EXPECT_EQ(j.at("implementation"), "exec:./my host --serve");
  ASSERT_TRUE(j.at("clauses").is_array());
  ASSERT_EQ(j.at("clauses").size(), run.clauses.size());
  int failures = 0;
  for (std::size_t i = 0; i < run.clauses.size(); ++i) {
    const auto& c = j.at("clauses")[i];
    const ClauseOutcome& co = run.clauses[i];
    EXPECT_EQ(c.at("id"), std::string(co.clause->id));
    EXPECT_EQ(c.at("status"), clause_status_name(co.status));
    EXPECT_EQ(c.at("level"), std::string(clause_level_name(co.clause->level)));
    if (c.at("status") == "pass") {
      EXPECT_FALSE(c.contains("counterexample")) << c.dump();
    }
    if (co.finding) {
      ++failures;
      const std::string file = c.at("counterexample");
      EXPECT_TRUE(fs::is_regular_file(w_.dir / file)) << file;
      const std::string replay = c.at("replay");
      EXPECT_NE(replay.find("./vgc replay "), std::string::npos) << replay;
      EXPECT_NE(replay.find((w_.dir / file).string()), std::string::npos) << replay;
      EXPECT_NE(replay.find("--impl " + shell_quote("exec:./my host --serve")), std::string::npos) << replay;
      ASSERT_EQ(c.at("counterexample_commands").size(), co.program.commands.size()) << c.dump();
      for (std::size_t k = 0; k < co.program.commands.size(); ++k)
        EXPECT_EQ(c.at("counterexample_commands")[k], print_command(co.program.commands[k]));
    }
  }
  EXPECT_GE(failures, 1);
  const auto it = std::find_if(j.at("clauses").begin(), j.at("clauses").end(),
                               [](const auto& c) { return c.at("id") == kClause; });
  ASSERT_NE(it, j.at("clauses").end());
  EXPECT_EQ(it->at("status"), "fail");
  EXPECT_EQ(it->at("level"), "MUST");
  EXPECT_EQ(it->at("counterexample"), std::string("counterexamples/") + kClause + ".vgc");
  EXPECT_EQ(j.at("new_failures"), nlohmann::json::array({kClause}));
}

TEST_F(Report, JunitHasATestcasePerClauseAndAFailureForTheFailingOne) {
  const RunResult& run = faulty_run();
  pugi::xml_document doc;
  const auto parsed = doc.load_string(read(w_.dir / "junit.xml").c_str());
  ASSERT_TRUE(parsed) << parsed.description();
  const auto suites = doc.child("testsuites");
  ASSERT_TRUE(suites);
  int testcases = 0, failures = 0;
  bool failing_has_failure = false;
  for (auto suite : suites.children("testsuite")) {
    int in_suite = 0, failures_in_suite = 0;
    for (auto tc : suite.children("testcase")) {
      ++testcases, ++in_suite;
      const std::string name = tc.attribute("name").as_string();
      const bool failed = tc.child("failure") || tc.child("error");
      failures += failed;
      failures_in_suite += failed;
      // Stable names: the clause id alone (a level change must not break a
      // CI's per-test history); the level is a property; every case has a time.
      EXPECT_EQ(name.find(' '), std::string::npos) << name;
      bool has_level = false;
      for (auto p : tc.child("properties").children("property"))
        has_level = has_level || std::string(p.attribute("name").as_string()) == "level";
      EXPECT_TRUE(has_level) << name;
      EXPECT_TRUE(tc.attribute("time")) << name << " has no time";
      if (name == kClause) {
        ASSERT_TRUE(tc.child("failure")) << name;
        failing_has_failure = true;
        const std::string body = tc.child("failure").text().as_string();
        EXPECT_NE(body.find("vgc replay"), std::string::npos) << body;
        EXPECT_FALSE(std::string(tc.child("failure").attribute("message").as_string()).empty());
      }
      for (const auto& co : run.clauses)
        if (name == co.clause->id && co.status == ClauseStatus::Pass) {
          EXPECT_FALSE(failed) << name << " passed but has a failure element";
        }
    }
    EXPECT_EQ(suite.attribute("tests").as_int(), in_suite);
    EXPECT_EQ(suite.attribute("failures").as_int() + suite.attribute("errors").as_int(), failures_in_suite);
  }
  EXPECT_TRUE(failing_has_failure);
  EXPECT_EQ(testcases, static_cast<int>(run.clauses.size()));
  EXPECT_EQ(suites.attribute("tests").as_int(), testcases);
  int findings = 0;
  for (const auto& co : run.clauses) findings += co.finding && co.clause->level != ClauseLevel::Should;
  EXPECT_EQ(failures, findings);
}

TEST_F(Report, SummaryStartsWithTheVerdictAndShowsTheReplay) {
  const RunResult& run = faulty_run();
  const ClauseOutcome& co = failing_clause(run);
  const std::string s = read(w_.dir / "summary.md");
  const std::string first = s.substr(0, s.find('\n'));
  EXPECT_EQ(first.rfind("# vgc certify: exec:./my host --serve", 0), 0u) << first;
  EXPECT_NE(first.find("NOT CONFORMANT"), std::string::npos) << first;
  EXPECT_NE(s.find(std::string("### ") + kClause), std::string::npos);
  EXPECT_NE(s.find("```\n" + print_commands(co.program.commands) + "```"), std::string::npos)
      << "the shrunk counterexample is not inline";
  const std::string replay = replay_command((w_.dir / counterexample_path(co)).string(), "exec:./my host --serve");
  EXPECT_NE(s.find("Replay: `" + replay + "`"), std::string::npos) << replay;
}

// kClause's finding as `vgc merge` reads the run in `dir` back; nullopt
// (and a failure) when the merge fails or the clause has no finding.
std::optional<Finding> merged_finding(const fs::path& dir) {
  MergedRun merged;
  std::string error;
  EXPECT_TRUE(merge_runs({dir.string()}, &merged, &error)) << error;
  for (const auto& co : merged.run.clauses)
    if (co.clause->id == kClause && co.finding) return co.finding;
  ADD_FAILURE() << "no " << kClause << " finding read back from " << dir;
  return std::nullopt;
}

// Issue 29 item 7: what a host sent back after the last command (the
// Verse wire, Finding::host_sent) is in summary.md, report.html and
// report.json, bounded, and `vgc merge` reads it back; a finding from a
// route that answers for itself (this in-process fault) shows no such line.
TEST(ReportHostSent, WhatTheHostSentBackIsShownBoundedAndReadBack) {
  RunResult run = faulty_run();
  ClauseOutcome* failing = nullptr;
  for (auto& co : run.clauses)
    if (co.clause->id == kClause) failing = &co;
  ASSERT_TRUE(failing && failing->finding);
  TempDir tmp;
  {
    const Written plain = write(tmp.path() / "plain", run, "verse:127.0.0.1:4950", "2026-11-22T04:00:00Z");
    ASSERT_TRUE(plain.ok) << plain.error;
    EXPECT_EQ(read(plain.dir / "summary.md").find("What the host sent back"), std::string::npos);
  }
  failing->finding->host_sent_seen = true;
  failing->finding->host_sent = {"bone_destroy 1", "layer_destroy 3"};
  failing->finding->host_sent_count = 20;
  const Written w = write(tmp.path() / "wire", run, "verse:127.0.0.1:4950", "2026-11-22T04:00:00Z");
  ASSERT_TRUE(w.ok) << w.error;
  const std::string summary = read(w.dir / "summary.md");
  EXPECT_NE(summary.find("**What the host sent back after the last command** (as vgc's mirror applied it, the "
                         "first 2 of 20):\n\n```\nbone_destroy 1\nlayer_destroy 3\n```"),
            std::string::npos)
      << summary;
  const std::string html = read(w.dir / "report.html");
  EXPECT_NE(html.find("What the host sent back after the last command"), std::string::npos);
  EXPECT_NE(html.find("<code>layer_destroy 3</code>"), std::string::npos);
  const auto j = nlohmann::json::parse(read(w.dir / "report.json"));
  bool in_json = false;
  for (const auto& c : j["clauses"])
    if (c["id"] == kClause) {
      in_json = true;
      EXPECT_EQ(c["host_sent"], nlohmann::json::array({"bone_destroy 1", "layer_destroy 3"}));
      EXPECT_EQ(c["host_sent_count"], 20);
    }
  EXPECT_TRUE(in_json);
  const std::optional<Finding> back = merged_finding(w.dir);
  ASSERT_TRUE(back);
  EXPECT_TRUE(back->host_sent_seen);
  EXPECT_EQ(back->host_sent_count, 20u);
  EXPECT_EQ(back->host_sent, (std::vector<std::string>{"bone_destroy 1", "layer_destroy 3"}));
}

// A finding's kind is set where it is made (Finding::late_view,
// Finding::history_kind), not read from its message: report.json says it
// (`kind`, `history_kind`) and `vgc merge` reads both back, so a merged
// run tolerates and groups as the unsharded one did, whatever the message.
TEST(ReportFindingKind, TheKindIsWrittenAndReadBackNotTakenFromTheMessage) {
  for (const int variant : {0, 1, 2}) {
    const bool history = variant == 1;
    RunResult run = faulty_run();
    ClauseOutcome* failing = nullptr;
    for (auto& co : run.clauses)
      if (co.clause->id == kClause) failing = &co;
    ASSERT_TRUE(failing && failing->finding);
    failing->finding->message = "a message that names no kind";
    if (history) {
      failing->finding->history_kind = FindingKind::Timeout;
      failing->program.history_kind = FindingKind::Timeout;
    } else if (variant == 0) {
      failing->finding->late_view = true;
    } else {
      failing->finding->protocol_error = true;
    }
    const std::string kind = history ? "timeout" : variant == 0 ? "hidden-state" : "protocol-error";
    EXPECT_EQ(finding_kind(*failing->finding), kind);
    EXPECT_EQ(depends_on_history(*failing->finding), history);
    TempDir tmp;
    const Written w = write(tmp.path() / "r", run, "verse:127.0.0.1:4950", "2026-11-22T04:00:00Z");
    ASSERT_TRUE(w.ok) << w.error;
    const auto j = nlohmann::json::parse(read(w.dir / "report.json"));
    for (const auto& c : j["clauses"])
      if (c["id"] == kClause) {
        EXPECT_EQ(c.value("kind", std::string()), kind);
        EXPECT_EQ(c.contains("history_kind"), history);
      }
    const std::optional<Finding> back = merged_finding(w.dir);
    ASSERT_TRUE(back);
    EXPECT_EQ(finding_kind(*back), kind) << "variant " << variant;
    EXPECT_EQ(depends_on_history(*back), history);
    EXPECT_EQ(back->late_view, variant == 0);
    EXPECT_EQ(back->protocol_error, variant == 2);
  }
}

TEST_F(Report, CounterexamplesParseAndReplayToTheSameClause) {
  const RunResult& run = faulty_run();
  int files = 0;
  for (const auto& e : fs::directory_iterator(w_.dir / "counterexamples")) {
    ++files;
    std::vector<Command> commands;
    TextError error;
    ASSERT_TRUE(parse_commands(read(e.path()), &commands, &error)) << e.path() << ": " << error.to_string();
    const std::string id = e.path().stem().string();
    const ClauseOutcome* co = nullptr;
    for (const auto& c : run.clauses)
      if (c.clause->id == id) co = &c;
    ASSERT_NE(co, nullptr) << "a counterexample for " << id << ", which the run does not report";
    ASSERT_TRUE(co->finding);
    ASSERT_EQ(commands.size(), co->program.commands.size());
    for (std::size_t i = 0; i < commands.size(); ++i) EXPECT_TRUE(bit_equal(commands[i], co->program.commands[i]));
    faults::FaultyImplementation impl(faults::find_fault(kFault));
    const ReplayResult r = replay_program(Program{commands, std::nullopt}, impl);
    ASSERT_TRUE(r.failure) << id;
    EXPECT_EQ(r.failure->clause, id);
  }
  int findings = 0;
  for (const auto& co : run.clauses) findings += co.finding.has_value();
  EXPECT_EQ(files, findings);
  EXPECT_TRUE(fs::is_regular_file(w_.dir / "counterexamples" / (std::string(kClause) + ".vgc")));
}

TEST_F(Report, NothingPartialIsLeftAndLatestPointsAtTheRun) {
  for (const auto& e : fs::recursive_directory_iterator(tmp_.path()))
    EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos) << e.path();
  const fs::path latest = w_.root / "latest";
  ASSERT_TRUE(fs::is_symlink(latest));
  EXPECT_EQ(fs::canonical(latest), fs::canonical(w_.dir));
  // A second run moves latest to it; the first run stays whole.
  ReferenceImplementation ref;
  RunOptions o;
  o.seed = 22;
  o.cases = 20;  // enough cases for BONE-VALUE-1 to be exercised: a clause nothing exercised is unchecked
  o.clause_glob = "BONE-VALUE-1";
  const RunResult second = run_certification(ref, o);
  const Written w2 = write(w_.root, second, "reference", "2026-11-22T04:05:00Z");
  ASSERT_TRUE(w2.ok) << w2.error;
  EXPECT_NE(w2.dir, w_.dir);
  EXPECT_EQ(fs::canonical(latest), fs::canonical(w2.dir));
  EXPECT_TRUE(fs::is_regular_file(w_.dir / "summary.md"));
  const auto j = nlohmann::json::parse(read(w2.dir / "report.json"));
  EXPECT_EQ(j.at("verdict"), "conformant");
  EXPECT_EQ(j.at("exit_code"), 0);
  EXPECT_TRUE(fs::is_empty(w2.dir / "counterexamples"));
  for (const auto& e : fs::recursive_directory_iterator(tmp_.path()))
    EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos) << e.path();
}

using test::capability_clause_ids;
using ClaimsNothing = test::ReferenceClaimingNothing;

// The cells of the summary's table row for `id` ("| ID | LEVEL | status |"), or empty.
std::vector<std::string> table_row(const std::string& summary, const std::string& id) {
  std::istringstream in(summary);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| " + id + " |", 0) != 0) continue;
    std::vector<std::string> cells;
    std::istringstream row(line.substr(1));
    std::string cell;
    while (std::getline(row, cell, '|')) {
      const auto b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
      cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
    }
    return cells;
  }
  return {};
}

TEST(ReportNotClaimed, JsonJunitAndSummaryShowANotClaimedCapability) {
  const std::set<std::string> ids = capability_clause_ids();
  ASSERT_FALSE(ids.empty());
  std::string glob = "BONE-VALUE-1";  // one core clause, so that a pass sits next to them
  for (const auto& id : ids) glob += "," + id;
  ClaimsNothing impl;
  RunOptions o;
  o.seed = 23;
  o.cases = 5;
  o.clause_glob = glob;
  const RunResult run = run_certification(impl, o);
  TempDir tmp;
  const Written w = write(tmp.path() / "reports", run, "exec:./old-host", "2026-11-22T04:10:00Z");
  ASSERT_TRUE(w.ok) << w.error;
  EXPECT_EQ(w.verdict.name, "conformant");

  // report.json: status "not-claimed" with its note, counted, no finding.
  const auto j = nlohmann::json::parse(read(w.dir / "report.json"));
  EXPECT_EQ(j.at("verdict"), "conformant");
  EXPECT_EQ(j.at("exit_code"), 0);
  EXPECT_EQ(j.at("counts").at("not-claimed"), static_cast<int>(ids.size()));
  EXPECT_EQ(j.at("counts").at("pass"), 1);
  EXPECT_EQ(j.at("counts").at("skipped"), 0);
  std::set<std::string> in_json;
  for (const auto& c : j.at("clauses")) {
    const std::string id = c.at("id");
    if (!ids.count(id)) {
      EXPECT_EQ(c.at("status"), "pass") << c.dump();
      continue;
    }
    in_json.insert(id);
    EXPECT_EQ(c.at("status"), "not-claimed") << c.dump();
    EXPECT_EQ(c.at("note"), "not claimed") << c.dump();
    EXPECT_FALSE(c.contains("counterexample")) << c.dump();
    EXPECT_FALSE(c.contains("message")) << c.dump();
  }
  EXPECT_EQ(in_json, ids);

  // junit.xml: each a testcase with <skipped message="not claimed">, neither failure nor error.
  pugi::xml_document doc;
  const auto parsed = doc.load_string(read(w.dir / "junit.xml").c_str());
  ASSERT_TRUE(parsed) << parsed.description();
  const auto suites = doc.child("testsuites");
  std::set<std::string> in_junit;
  int skipped_in_suites = 0;
  for (auto suite : suites.children("testsuite")) {
    int skipped_here = 0;
    for (auto tc : suite.children("testcase")) {
      const std::string name = tc.attribute("name").as_string();
      const std::string id = name;
      skipped_here += static_cast<bool>(tc.child("skipped"));
      if (!ids.count(id)) continue;
      in_junit.insert(id);
      EXPECT_FALSE(tc.child("failure")) << name;
      EXPECT_FALSE(tc.child("error")) << name;
      ASSERT_TRUE(tc.child("skipped")) << name;
      EXPECT_STREQ(tc.child("skipped").attribute("message").as_string(), "not claimed") << name;
    }
    EXPECT_EQ(suite.attribute("skipped").as_int(), skipped_here) << suite.attribute("name").as_string();
    EXPECT_EQ(suite.attribute("failures").as_int(), 0);
    EXPECT_EQ(suite.attribute("errors").as_int(), 0);
    skipped_in_suites += skipped_here;
  }
  EXPECT_EQ(in_junit, ids);
  EXPECT_EQ(suites.attribute("skipped").as_int(), skipped_in_suites);
  EXPECT_EQ(skipped_in_suites, static_cast<int>(ids.size()));

  // summary.md: counted in the headline counts, and one table row each.
  const std::string s = read(w.dir / "summary.md");
  EXPECT_NE(s.find(fmt::format("{} not-claimed", ids.size())), std::string::npos) << s;
  const std::string counts_line = s.substr(s.find(" clauses: "), s.find('\n', s.find(" clauses: ")) - s.find(" clauses: "));
  EXPECT_EQ(counts_line.find("skipped"), std::string::npos) << counts_line;  // a count of zero is not shown
  for (const auto& id : ids) {
    const auto cells = table_row(s, id);
    ASSERT_EQ(cells.size(), 4u) << id << " has no row in\n" << s;  // id, level, status, exercised
    EXPECT_EQ(cells[3], "0") << id << ": a capability not claimed exercised nothing";
    EXPECT_EQ(cells[2].rfind("not-claimed", 0), 0u) << cells[2];
  }
  EXPECT_EQ(table_row(s, "BONE-VALUE-1").at(2), "pass");
}

TEST(ReportFailure, AnUncreatablePathFailsAndLeavesNothing) {
  TempDir tmp;
  const fs::path blocker = tmp.path() / "not-a-directory";
  {
    std::ofstream f(blocker);
    f << "a file where the reports directory should go\n";
  }
  RunResult run;  // an empty run is enough: the directory cannot be made
  run.options.seed = 1;
  run.complete = true;
  const Written w = write(blocker / "reports", run, "reference", "2026-11-22T04:00:00Z");
  EXPECT_FALSE(w.ok);
  EXPECT_FALSE(w.error.empty());
  std::vector<fs::path> entries;
  for (const auto& e : fs::recursive_directory_iterator(tmp.path())) entries.push_back(e.path());
  EXPECT_EQ(entries, std::vector<fs::path>{blocker});
  EXPECT_EQ(read(blocker), "a file where the reports directory should go\n");
}

}  // namespace
}  // namespace vgc
