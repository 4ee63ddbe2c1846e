// exercised_clauses.h — which clauses a judged step decided.
//
// Spec: every clause of the catalog (clause.h), through the node's rules
// (rule.h) and their clauses (rule_clauses.h).
//
// Rationale: a clause may only be reported `pass` when something in the run
// could have shown it failing (issue 9, item 1). A step that was run on the
// model and on the implementation and found equal "exercised" the clause of
// every rule the reference applied to it (its RuleTrace: the guard of a
// refusal, which includes command.rejected.changes_nothing, ATOMIC-1; every
// alias, placement, write, keep and removal of an applied command), since
// attribution blames a divergence on exactly those rules; and the clause of
// every kind of derived line it changed. A rejected command whose verdict
// the implementation reported also exercises REASON-1.
// Every judged step exercises ACCEPT-1 (it read the canonical line) and
// STABLE-1 (it answered). The runner counts these per clause.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "command.h"
#include "derived_rule.h"
#include "document_digest.h"
#include "node.h"
#include "reason.h"

namespace vgc {

// Appends to *out the clauses that the step `c`, taking the reference to
// `after` with the verdict `expected` by the rules `rules` and changing the
// derived lines `derived_changed` (NodeDigest::update reports them, or
// derived_changes), decided (duplicates removed).
// `verdict_reported` is false when the implementation answered `done`
// (REASON-1 is then not exercised).
//
// derived_only: when not null, the route carries no derived document
// (RouteLimits::derived false), so the derived document decided nothing:
// the clauses that only its changed lines would have decided go to
// *derived_only instead of *out (a clause the step also decided otherwise
// stays in *out only). The runner reports a clause that only such steps
// reached as not judgeable on that route.
void exercised_clauses(const std::vector<DerivedChange>& derived_changed, const Command& c, Reason expected,
                       const RuleTrace& rules, const Node& after, bool verdict_reported,
                       std::vector<std::string_view>* out, std::vector<std::string_view>* derived_only = nullptr);

// The rules of the derived document (reference/geometry/derived_rule.h)
// that decided the derived lines `derived_changed` in `after`, each once, in
// enum order: derived_rule_of each line, and derived.edge_crease.per_corner
// for a polygon's edges when the command (its rules `rules`) created or
// re-defined a polygon. What exercised_clauses maps to clauses, and what
// the runner counts as the derived rules' judged uses.
std::vector<DerivedRule> derived_rules_changed(const std::vector<DerivedChange>& derived_changed, const RuleTrace& rules,
                                               const Node& after);

// Every derived line that differs between the two nodes' derived documents
// (from the printed documents: costs both nodes' size).
std::vector<DerivedChange> derived_changes(const Node& before, const Node& after);

// The clauses a fresh-node check decides (LAYER-BASE-1, CREASE-INITIAL-1,
// STABLE-1).
const std::vector<std::string_view>& fresh_node_clauses();

// The command's keyword ("polygon_set_corner_uint32"), as docs/commands.md
// names it.
std::string command_kind(const Command& c);

}  // namespace vgc
