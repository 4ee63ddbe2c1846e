// fault_matrix_test.cpp — every rule of a MUST clause has a seeded fault
// that breaks it alone ("rule:<name>", tests/conformance/faults/
// faulty_node.h), and certification blames that fault on the rule's own
// clause at seeds 1, 2 and 3, with no other clause failing (issue 17,
// item 4). One test per rule, so ctest runs them in parallel.
//
// Also the three MUST bug kinds issue 17 found certified conformant: a
// moved vertex's slots reset, a re-defined polygon's slots reset, a layer
// re-typed into the other stack left without slots. Each must give a
// non-conformant verdict (exit 1) naming its MUST clause at every seed.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "faulty_implementation.h"
#include "rule_clauses.h"
#include "runner.h"
#include "verdict.h"
#include "default_run.h"

namespace vgc {
namespace {

// The run is restricted to the properties that declare the rule's clause
// (RunOptions::clause_glob), to keep 53 rules x 3 seeds within CI's time:
// those properties still judge every step against the whole catalog, and a
// finding in any other clause is still reported by the run (RunResult
// lists every clause with a finding) and fails the test.
RunOptions matrix_options(std::uint64_t seed, const std::string& glob) {
  return unhurried_run(seed, 100, 40, glob);
}

struct SeedOutcome {
  bool blamed = false;       // the expected clause failed
  std::string others;        // any other clause with a finding
  int exit_code = 0;
  std::string first_message;
};

SeedOutcome certify_once(int fault, const std::string& clause, std::uint64_t seed, const std::string& glob) {
  faults::FaultyImplementation impl(fault);
  const RunResult run = run_certification(impl, matrix_options(seed, glob));
  SeedOutcome out;
  for (const auto& co : run.clauses) {
    if (!co.finding) continue;
    if (co.clause->id == clause && co.status == ClauseStatus::Fail) {
      out.blamed = true;
      out.first_message = co.finding->message;
    } else {
      out.others += std::string(co.clause->id) + "(" + clause_status_name(co.status) + ") ";
      if (out.first_message.empty()) out.first_message = co.finding->message;
    }
  }
  out.exit_code = judge(run, nullptr).exit_code;
  return out;
}

// Restricted to the clause's properties first; where those do not reach the
// rule at this seed (a rule the generators draw rarely, e.g. a 15-byte bone
// label), the whole catalog, as a default run would.
SeedOutcome certify(int fault, const std::string& clause, std::uint64_t seed) {
  SeedOutcome o = certify_once(fault, clause, seed, clause);
  if (!o.blamed && o.others.empty()) o = certify_once(fault, clause, seed, "*");
  return o;
}

class FaultMatrix : public ::testing::TestWithParam<Rule> {};

TEST_P(FaultMatrix, TheRulesFaultIsBlamedOnItsClauseAtThreeSeeds) {
  const Rule rule = GetParam();
  const std::string clause(rule_clause(rule));
  const int fault = faults::find_fault("rule:" + std::string(rule_name(rule)));
  ASSERT_GE(fault, 0) << rule_name(rule);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const SeedOutcome o = certify(fault, clause, seed);
    std::printf("%-36s seed %llu: %s %s  others: %s\n", std::string(rule_name(rule)).c_str(),
                static_cast<unsigned long long>(seed), clause.c_str(), o.blamed ? "BLAMED" : "MISSED",
                o.others.c_str());
    EXPECT_TRUE(o.blamed) << rule_name(rule) << " seed " << seed << ": " << clause
                          << " did not fail; others: " << o.others << "\n" << o.first_message;
    EXPECT_TRUE(o.others.empty()) << rule_name(rule) << " seed " << seed << ": other clauses failed: " << o.others
                                  << "\n" << o.first_message;
    EXPECT_EQ(o.exit_code, 1) << rule_name(rule) << " seed " << seed;
  }
}

std::string rule_test_name(const ::testing::TestParamInfo<Rule>& info) {
  std::string n(rule_name(info.param));
  for (char& ch : n)
    if (ch == '.') ch = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(MustRules, FaultMatrix, ::testing::ValuesIn(fault_matrix_rules()), rule_test_name);

TEST(FaultMatrix, TheThreeMustBugKindsFailAtEverySeed) {
  for (const char* name : {"moved-vertex-slots-reset", "redefined-polygon-slots-reset", "retype-other-stack-no-slots"}) {
    const int fault = faults::find_fault(name);
    ASSERT_GE(fault, 0) << name;
    const std::string clause(faults::fault_catalog()[static_cast<std::size_t>(fault)].expected_clause);
    ASSERT_EQ(find_clause(clause)->level, ClauseLevel::Must) << name;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const SeedOutcome o = certify_once(fault, clause, seed, "*");  // a default run, the whole catalog
      EXPECT_TRUE(o.blamed) << name << " seed " << seed << ": others " << o.others << "\n" << o.first_message;
      EXPECT_EQ(o.exit_code, 1) << name << " seed " << seed;
      std::printf("%-30s seed %llu: %s  exit %d  others: %s\n", name, static_cast<unsigned long long>(seed),
                  o.blamed ? "BLAMED" : "MISSED", o.exit_code, o.others.c_str());
    }
  }
}

// The fresh node's crease rule is applied by no command: its fault breaks
// the fresh node itself (faulty_node.cpp, FaultyNode's constructor), and
// the fresh-node check blames it on CREASE-INITIAL-1 alone. Before that
// constructor the fault changed nothing and this test failed (MISSED at
// every seed). IMPLEMENTATION-DEFINED, so not in the MUST matrix above.
TEST(FaultMatrix, TheInitialCreasesFaultIsBlamedOnItsClause) {
  const int fault = faults::find_fault("rule:node.initial_creases");
  ASSERT_GE(fault, 0);
  const std::string clause(rule_clause(Rule::InitialCreases));
  ASSERT_EQ(clause, "CREASE-INITIAL-1");
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const SeedOutcome o = certify_once(fault, clause, seed, clause);
    std::printf("node.initial_creases seed %llu: %s  others: %s\n", static_cast<unsigned long long>(seed),
                o.blamed ? "BLAMED" : "MISSED", o.others.c_str());
    EXPECT_TRUE(o.blamed) << "seed " << seed << ": others " << o.others << "\n" << o.first_message;
    EXPECT_TRUE(o.others.empty()) << "seed " << seed << ": " << o.others;
  }
}

// Issue 29, item 4: every rule of the derived document has a seeded fault
// too ("rule:derived.<...>", faulty_node.h: its lines printed with another
// value, or other lines listed), and certification blames it on the rule's
// own clause (rule_clauses.h, derived_rule_clause) at seeds 1, 2 and 3,
// with no other clause failing, and names the rule: the vertex and edge
// rules of one clause (derived.vertex_crease.constant and
// derived.edge_crease.constant, both CREASE-DEFAULT-1) are told apart by the
// name in the finding. Every level: a MUST rule's fault also gives exit 1;
// an IMPLEMENTATION-DEFINED one is a profile difference.
class DerivedFaultMatrix : public ::testing::TestWithParam<DerivedRule> {};

TEST_P(DerivedFaultMatrix, TheRulesFaultIsBlamedOnItsClauseAndNamedAtThreeSeeds) {
  const DerivedRule rule = GetParam();
  const std::string name(derived_rule_name(rule)), clause(derived_rule_clause(rule));
  const Clause* c = find_clause(clause);
  ASSERT_NE(c, nullptr) << name;
  const int fault = faults::find_fault("rule:" + name);
  ASSERT_GE(fault, 0) << name;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const SeedOutcome o = certify(fault, clause, seed);
    std::printf("%-36s seed %llu: %s %s  others: %s\n", name.c_str(), static_cast<unsigned long long>(seed),
                clause.c_str(), o.blamed ? "BLAMED" : "MISSED", o.others.c_str());
    EXPECT_TRUE(o.blamed) << name << " seed " << seed << ": " << clause << " did not fail; others: " << o.others
                          << "\n" << o.first_message;
    EXPECT_TRUE(o.others.empty()) << name << " seed " << seed << ": other clauses failed: " << o.others << "\n"
                                  << o.first_message;
    EXPECT_NE(o.first_message.find("Blamed on derived rule " + name + " ("), std::string::npos)
        << name << " seed " << seed << ": the finding does not name the rule\n" << o.first_message;
    if (c->level == ClauseLevel::Must) {
      EXPECT_EQ(o.exit_code, 1) << name << " seed " << seed;
    }
  }
}

std::vector<DerivedRule> derived_rules() {
  std::vector<DerivedRule> out;
  for (std::size_t i = 1; i < kDerivedRuleCount; ++i) out.push_back(static_cast<DerivedRule>(i));
  return out;
}

std::string derived_rule_test_name(const ::testing::TestParamInfo<DerivedRule>& info) {
  std::string n(derived_rule_name(info.param));
  for (char& ch : n)
    if (ch == '.') ch = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(DerivedRules, DerivedFaultMatrix, ::testing::ValuesIn(derived_rules()), derived_rule_test_name);

}  // namespace
}  // namespace vgc
