// no_oracle_test.cpp — a claimed optional capability that this build
// cannot judge (conformance/capability.h: no check registered, "no oracle
// linked") is reported as not judged — status "unchecked", note "not judged:
// no oracle linked", the run incomplete, verdict "incomplete", exit code 2
// (verdict.h) — never as a pass; and `replay_program` says it cannot
// repeat such a check, or one the implementation does not claim.
//
// This binary links the conformance library alone: nothing calls
// register_capability_checks, so the registry is empty, as in a vgc built
// without the oracles. Generic over capability names: every capability a
// property of the catalog checks is claimed.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "../capability_test_util.h"
#include "capability.h"
#include "property.h"
#include "reference_implementation.h"
#include "report.h"
#include "runner.h"
#include "verdict.h"

namespace vgc {
namespace {

// Every capability name a property checks, and the clauses those properties declare.
using test::capability_clause_ids;
using test::catalog_capabilities;

// The reference, claiming exactly `claims` (whatever it could answer).
class Claims final : public Implementation {
 public:
  explicit Claims(std::vector<std::string> claims) : claims_(std::move(claims)) {}
  std::string name() const override { return "claims"; }
  Answer reset() override { return ref_.reset(); }
  Answer apply(const Command& c) override { return ref_.apply(c); }
  Document snapshot() override { return ref_.snapshot(); }
  Document derived() override { return ref_.derived(); }
  Document request(const std::string& line) override {
    if (line != "?capabilities") return ref_.request(line);
    std::string text = "capabilities";
    for (const auto& c : claims_) text += " " + c;
    return {CallStatus::Ok, text + "\nend\n", ""};
  }

 private:
  std::vector<std::string> claims_;
  ReferenceImplementation ref_;
};

TEST(NoOracle, AClaimedCapabilityWithoutACheckIsNotJudgedAndTheRunIsIncomplete) {
  const auto names = catalog_capabilities();
  ASSERT_FALSE(names.empty()) << "no property checks an optional capability";
  for (const auto& n : names) ASSERT_EQ(find_capability_check(n), nullptr) << n << " has a check in this binary";
  const auto ids = capability_clause_ids();
  std::string glob;
  for (const auto& id : ids) glob += (glob.empty() ? "" : ",") + id;

  Claims impl(names);
  RunOptions o;
  o.seed = 5;
  o.cases = 8;
  o.clause_glob = glob;
  const RunResult run = run_certification(impl, o);

  std::set<std::string> seen;
  for (const auto& co : run.clauses) {
    const std::string id(co.clause->id);
    if (!ids.count(id)) continue;
    seen.insert(id);
    EXPECT_EQ(co.status, ClauseStatus::Unchecked) << id;
    EXPECT_EQ(co.note, "not judged: no oracle linked") << id;
    EXPECT_FALSE(co.finding.has_value()) << id;
    EXPECT_TRUE(co.properties.empty()) << id << ": a property is said to have checked it";
  }
  EXPECT_EQ(seen, ids);
  for (const auto& po : run.properties) {
    const PropertySpec* spec = find_property(po.id);
    ASSERT_NE(spec, nullptr) << po.id;
    if (spec->capability.empty()) continue;
    EXPECT_EQ(po.status, PropertyStatus::Skipped) << po.id;
    EXPECT_EQ(po.note, "no oracle linked") << po.id;
    EXPECT_EQ(po.cases, 0) << po.id;
  }
  EXPECT_FALSE(run.complete);
  EXPECT_TRUE(judge(run, nullptr).new_failures.empty());  // nothing failed; it is just not judged

  const Verdict v = judge(run, nullptr);
  EXPECT_EQ(v.name, "incomplete");
  EXPECT_EQ(v.exit_code, 2);
  EXPECT_TRUE(v.new_failures.empty());

  // The reports say so: report.json (parsed) and the summary's reasons.
  ReportContext ctx;
  ctx.implementation_spec = "claims";
  const auto j = nlohmann::json::parse(render_report_json(run, v, ctx));
  EXPECT_EQ(j.at("verdict"), "incomplete");
  EXPECT_EQ(j.at("exit_code"), 2);
  EXPECT_EQ(j.at("counts").at("unchecked"), static_cast<int>(ids.size()));
  EXPECT_EQ(j.at("counts").at("pass"), 0);
  for (const auto& c : j.at("clauses")) {
    EXPECT_EQ(c.at("status"), "unchecked") << c.dump();
    EXPECT_EQ(c.at("note"), "not judged: no oracle linked") << c.dump();
  }
  const std::string summary = render_summary(run, v, ctx);
  EXPECT_NE(summary.find("INCOMPLETE"), std::string::npos) << summary;
  for (const auto& id : ids)
    EXPECT_NE(summary.find("- clause " + id + " is unchecked: not judged: no oracle linked"), std::string::npos) << summary;
}

TEST(NoOracle, AnUnclaimedCapabilityIsNotClaimedEvenWithoutACheck) {
  // The other side of the same decision: claiming nothing is complete.
  Claims impl({});
  RunOptions o;
  o.seed = 5;
  o.cases = 8;
  std::string glob;
  for (const auto& id : capability_clause_ids()) glob += (glob.empty() ? "" : ",") + id;
  o.clause_glob = glob;
  const RunResult run = run_certification(impl, o);
  for (const auto& co : run.clauses) EXPECT_EQ(co.status, ClauseStatus::NotClaimed) << co.clause->id;
  EXPECT_TRUE(run.complete);
  EXPECT_EQ(judge(run, nullptr).exit_code, 0);
}

TEST(NoOracle, ReplayCannotRepeatACheckWithoutAnOracleOrAClaim) {
  // A fake capability name, claimed: no property and no check know it.
  Program p;
  p.request = CapabilityRequest{"no-such-capability", 2, std::nullopt};
  Claims claims_it({"no-such-capability"});
  const ReplayResult r = replay_program(p, claims_it);
  EXPECT_FALSE(r.failure.has_value());
  EXPECT_NE(r.not_judged.find("no oracle linked"), std::string::npos) << r.not_judged;
  EXPECT_NE(r.not_judged.find("no-such-capability"), std::string::npos) << r.not_judged;

  // A real capability name the implementation does not claim.
  const auto names = catalog_capabilities();
  ASSERT_FALSE(names.empty());
  p.request = CapabilityRequest{names.front(), 1, std::nullopt};
  Claims claims_nothing({});
  const ReplayResult n = replay_program(p, claims_nothing);
  EXPECT_FALSE(n.failure.has_value());
  EXPECT_NE(n.not_judged.find("does not claim"), std::string::npos) << n.not_judged;
  EXPECT_NE(n.not_judged.find(capability_clauses(names.front())), std::string::npos) << n.not_judged;
  EXPECT_FALSE(capability_clauses(names.front()).empty());

  // Without a request nothing is left unjudged.
  const ReplayResult plain = replay_program(Program{}, claims_nothing);
  EXPECT_FALSE(plain.failure.has_value());
  EXPECT_TRUE(plain.not_judged.empty());
}

}  // namespace
}  // namespace vgc
