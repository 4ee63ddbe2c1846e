// rule_clauses.h — which clause of the catalog each rule of the reference
// belongs to: the node's rules and the derived document's.
//
// Spec: the clause catalog (clause.h), the node's rules
// (reference/node/rule.h) and the derived document's
// (reference/geometry/derived_rule.h).
//
// Rationale: the node names its decisions in its own vocabulary; this table
// is the one place where a rule meets the spec sentence it implements, so
// that a divergence blamed on a rule (attribution.h) is reported at that
// rule's clause and level. Every rule maps to exactly one clause (a switch:
// the compiler flags a rule left out), and docs/clauses.md lists each
// clause's rules, generated from this table.
#pragma once

#include <string_view>
#include <vector>

#include "clause.h"
#include "derived_rule.h"
#include "rule.h"

namespace vgc {

// The clause id of `r`; every id is in the catalog (a test checks).
std::string_view rule_clause(Rule r);
// The clause id of a rule of the derived document (a switch, as
// rule_clause); every id is in the catalog (a test checks).
std::string_view derived_rule_clause(DerivedRule r);
// The clause of a rule by its printed name, node or derived ("crease.vertex.layer",
// "derived.bone_pose.root": the keys of RunResult::rule_uses); "" for an
// unknown name.
std::string_view rule_name_clause(std::string_view name);
// The rules whose clause is `clause_id`, in enum order.
std::vector<Rule> rules_of_clause(std::string_view clause_id);
// The derived document's rules whose clause is `clause_id`, in enum order.
std::vector<DerivedRule> derived_rules_of_clause(std::string_view clause_id);
// Why a MUST rule has no seeded fault certified by the fault matrix
// (tests/conformance/fault_matrix_test.cpp), or empty when it has one: the
// rules a default run cannot reach (the storage budgets need 2^22 cells)
// and the fresh node's rules (no command applies them; the fresh-node check
// judges them).
std::string_view rule_fault_exemption(Rule r);
// Why a rule is left out of the rule-coverage threshold (every rule used at
// least 20 times in a default run, tests/conformance/rule_coverage_test.cpp),
// or empty: the rules no bounded run can reach (a storage budget of 2^22
// cells, every one of 65535 or 2^32 - 1 ids in use).
std::string_view rule_coverage_exemption(Rule r);

// The rules of MUST clauses that the fault matrix certifies, in enum order.
std::vector<Rule> fault_matrix_rules();

// Strictness for gating: MUST 2, IMPLEMENTATION-DEFINED 1, SHOULD 0.
int clause_strictness(ClauseLevel level);

}  // namespace vgc
