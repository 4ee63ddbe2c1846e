// derived_rule.h — every decision the derived document makes, as a named rule.
//
// Spec: 000 section 2.6.2 (effective creases: "either they can all be set
// to a single constant, or crease information can be stored in a layer";
// the layer "must be of type VN_G_LAYER_VERTEX_UINT32 for vertex creases,
// and VN_G_LAYER_POLYGON_CORNER_UINT32 for edges"; "each corner holds the
// crease data for the edge that starts in that corner"), 2.6.3 (a parent
// "can be set to a non-existing bone to indicate that no parent exists";
// "if you rotate any bone, all bones 'downstream' of it will rotate, too")
// and 2.6.4 (a new node's creases, from the cube that must set them
// "explicitly"); docs/commands.md 6.2 defines the document.
//
// Rationale: the node's rules (reference/node/rule.h) name what a command
// writes; the derived document (derived_document.h) is written by no
// command but read from the stored state when it is printed, and each
// reading is a decision too: where an effective crease comes from, how
// many edges a polygon has, how a bone's pose is composed. Each has a name
// here, and the functions that compute a derived line (crease.h,
// bone_pose.h) return the rule that decided it from the same branch that
// computes its value, so a difference on a derived line is blamed on the
// rule that decided it (conformance/attribution.h) rather than on a clause
// guessed from the line's shape. Standard library only and no clause ids
// (reference/ stays free of the catalog); conformance/rule_clauses.cpp maps
// each rule to exactly one clause.
//
// The crease rules come in a vertex and an edge variant, as the node's
// (crease.vertex.constant, crease.edge.constant): the two settings are
// independent, and a fault in one must not be blamed on the other.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace vgc {

enum class DerivedRule : std::uint8_t {
  None,
  // ---- effective creases (2.6.2): one rule decides every line of a kind ----
  VertexCreaseConstant,      // no layer named: the constant crease_set_vertex sent
  VertexCreaseLayer,         // a VERTEX_UINT32 layer named: the vertex's slot in it
  VertexCreaseLayerMissing,  // a layer named that is missing or of another type: the constant
  VertexCreaseInitial,       // never set: a fresh node's constant 0
  EdgeCreaseConstant,        // the same for polygon edges ...
  EdgeCreaseLayer,           // ... a POLYGON_CORNER_UINT32 layer: slot p, component i
  EdgeCreaseLayerMissing,
  EdgeCreaseInitial,
  EdgePerCorner,             // a polygon has one edge_crease line per used corner: 3 or 4
  // ---- bone world poses (2.6.3) ----------------------------------------------
  BonePoseRoot,              // parent 0xFFFF: the bone's own position, rotation normalized
  BonePoseParentMissing,     // a parent id that names no live bone: a root as well
  BonePoseChained,           // a live parent: composed with the parent's world pose
  BonePosePerBone,           // one bone_pose line per live bone, none for any other id
  kCount
};

inline constexpr std::size_t kDerivedRuleCount = static_cast<std::size_t>(DerivedRule::kCount);

struct DerivedRuleInfo {
  DerivedRule rule;
  std::string_view name;  // "derived.vertex_crease.layer": stable, printed in findings
  // Whether the rule decides which lines exist (EdgePerCorner,
  // BonePosePerBone) rather than a line's values: a difference in which
  // lines the two sides list is blamed on it.
  bool places;
  std::string_view says;  // what the reference reads, and why, in one sentence
};

const DerivedRuleInfo& derived_rule_info(DerivedRule r);
std::string_view derived_rule_name(DerivedRule r);
// Inverse of derived_rule_name; false for an unknown name.
bool parse_derived_rule_name(std::string_view name, DerivedRule* out);

}  // namespace vgc
