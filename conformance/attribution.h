// attribution.h — which rule, and so which clause, a divergence from the
// reference breaks.
//
// Spec: the clause catalog (clause.h), reached through the node's rules
// (reference/node/rule.h) and their clauses (rule_clauses.h).
//
// Rationale: the reference node records which of its rules decided each
// verdict (RuleTrace) and which rule last wrote each snapshot line
// (Written), so a difference is blamed by provenance, not guessed from its
// shape: a divergent verdict on the rule that decided it (a refusal's
// guard; for an applied command, the rules it applied); a divergent line
// on the rule that wrote it in this command, or, for a line the command
// left alone, the rule that keeps it; a line the implementation lacks on
// the rule that placed it; a line it has and the model does not on the
// rule that removed it or, for a line nobody removed, the rule that placed
// it. Where several rules could explain one difference, all are named and
// the blame goes to the strictest level among them (MUST, then
// IMPLEMENTATION-DEFINED, then SHOULD): a MUST rule is never hidden behind
// a weaker one.
//
// The derived document (effective creases, bone world poses) is written by
// no command: the reference reads it from the stored state, and each
// reading is a named rule of its own (reference/geometry/derived_rule.h).
// A derived line is blamed the same way, by provenance: on the derived rule
// that decided the model's line (derived_rule_of), or, where the two sides
// list different lines of a kind whose lines a derived rule places, on that
// rule; never on a clause guessed from the line's shape.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "command.h"
#include "derived_rule.h"
#include "document_diff.h"
#include "node.h"
#include "reason.h"
#include "rule.h"

namespace vgc {

struct Blame {
  std::vector<Rule> rules;  // every rule that could explain it; rules[0] is blamed
  std::string clause;       // rules[0]'s clause (the strictest level among them)
  std::string explanation;  // names the rules, what the model did and why
};

// The verdicts differ: the reference gave `expected` on `c` with the rules
// `trace` (Node::apply), the implementation the other verdict (or crashed,
// or timed out on it).
Blame blame_verdict(const Command& c, Reason expected, const RuleTrace& trace);

// The reference's snapshot after `c` (state `after`, rules `trace`, from
// `before`) differs from the implementation's `observed` snapshot at `d`.
Blame blame_snapshot(const Node& before, const Node& after, Reason expected, const RuleTrace& trace,
                     const DocumentDifference& d, const std::string& observed);

// A fresh node's document differs from the model's `fresh` (as a reset
// leaves it) at `d` (of the snapshot, or with `derived` of the derived
// document): blamed on the fresh-node rule of the line, node.base_layers
// (LAYER-BASE-1) or node.initial_creases (CREASE-INITIAL-1): the rule that
// placed the model's line, or for a line the model has not, the rule of its
// kind (a crease setting, or an effective crease derived from one, is the
// initial creases'; any other line the base layers': a fresh node holds
// nothing else).
Blame blame_fresh(const Node& fresh, const DocumentDifference& d, bool derived);

// The derived documents differ at `d` in the state `after` of an applied
// command: the derived rule that decided the difference (the rule that
// places lines of its kind, derived_place_rule, where the two sides list
// different edges of a polygon; otherwise derived_rule_of the model's line,
// or of the implementation's where the model has none), its clause
// (rule_clauses.h, derived_rule_clause) and an explanation naming it.
struct DerivedBlame {
  DerivedRule rule = DerivedRule::None;
  std::string clause;
  std::string explanation;  // "Blamed on derived rule derived.edge_crease.layer (CREASE-EDGE-LAYER-1, MUST): ..."
};
DerivedBlame blame_derived(const Node& after, const DocumentDifference& d);

// The clause of the derived rule that decides a derived line of
// `line_kind` ("vertex_crease", "edge_crease", "bone_pose") in `node`;
// `bone_id` is the bone of a bone_pose line (derived_rule_of answers it).
std::string_view clause_for_derived(const Node& node, std::string_view line_kind, long bone_id);

// The clauses only the derived document decides: a derived rule maps to
// them (derived_rule_clause) and no rule of the node does (BONE-PARENT-1,
// BONE-DOWNSTREAM-1: a bone's world pose). A route that carries no derived
// document cannot judge them at all, whatever its cases draw
// (clause_status.h).
const std::vector<std::string_view>& derived_only_clauses();

// A short name for the shape of a snapshot difference from the model
// `after`: the kind of line, which side lacks it, and the rule that last
// wrote the model's line ("slot changed element.create.slot_default").
// Differences of one shape are blamed alike, as a rule: what a caller that
// has already localized one (the late view, program_checker.h) uses to
// spare localizing the others.
std::string difference_shape(const Node& after, const DocumentDifference& d);

// A late subscriber (program_checker.h check_late_view) shown, for a slot
// of a real layer of `after`, the layer's default where the model holds a
// value equal to it as a number but not bit for bit (-0.0 where the
// default is 0, or 0 where it is -0.0): the host sent the newcomer nothing
// for that slot, as for a slot at the default, comparing by value (r6's
// layer_subscribe does). What a new subscriber is sent of a layer is the
// subscription's, rule layer.subscribe (LAYER-SUBSCRIBE-1), not the
// write's: every watcher was sent the value the model holds. nullopt for
// any other difference `d`.
std::optional<Blame> blame_subscription_dump(const Node& after, const DocumentDifference& d);

// A late subscriber shown, for a slot where the model `after` holds its
// layer's default, that layer's default as the host told it (the layer
// line of `observed`, the late view, with other defaults than the
// model's): a host sends a newcomer no slot at the default, so the slot
// is the layer line's difference, not one of its own.
bool slot_at_told_default(const Node& after, const DocumentDifference& d, const std::string& observed);

}  // namespace vgc
