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
// What remains of the old shape-based attribution is clause_for_derived:
// the derived document (effective creases, bone world poses) is computed by
// reference/geometry from the stored state, not decided by a node rule, so
// a derived line is blamed on the geometry clause of its kind.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "command.h"
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

// The derived documents differ at a line of `line_kind` ("vertex_crease",
// "edge_crease", "bone_pose") in the state `after`; `bone_id` is the bone
// of a bone_pose line.
std::string_view clause_for_derived(const Node& after, std::string_view line_kind, long bone_id);

// The same from the whole difference `d` (kind d.kind): edge_crease lines
// that name different edges (or one side lacking the line) mean the two
// sides disagree on a polygon's corners (POLY-TRIANGLE-1: a fourth corner
// that is a vertex reference makes a quad), not on a crease.
std::string_view clause_for_derived(const Node& after, const DocumentDifference& d, long bone_id);

// The clauses only the derived document decides: no rule of the node
// (rule_clauses.h) maps to them, and clause_for_derived can name them
// (BONE-PARENT-1, BONE-DOWNSTREAM-1: a bone's world pose). A route that
// carries no derived document cannot judge them at all, whatever its cases
// draw (clause_status.h).
const std::vector<std::string_view>& derived_only_clauses();

// The bone id of a derived document's "bone_pose <id> ..." line, or -1.
long bone_id_of(const std::string& line);

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

// The identity of a snapshot or derived line: its kind and the ids after
// it ("slot 3 17", "edge_crease 4 2", "vertex 5", "crease_vertex").
std::string line_key(const std::string& line);

}  // namespace vgc
