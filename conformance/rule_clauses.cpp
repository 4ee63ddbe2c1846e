// rule_clauses.cpp — see rule_clauses.h.
#include "rule_clauses.h"

namespace vgc {

std::string_view rule_clause(Rule r) {
  switch (r) {
    case Rule::None: return "ACCEPT-1";
    case Rule::LayerCreateBaseId:
    case Rule::LayerDestroyBaseId: return "LAYER-BASE-2";
    case Rule::LayerTypeUnknown: return "LAYER-TYPE-1";
    case Rule::LayerNameInvalid:
    case Rule::LayerNameLongest: return "LAYER-NAME-1";
    case Rule::LayerNameInUse: return "LAYER-NAME-2";
    case Rule::LayerNoFreeId:
    case Rule::LayerIdPick: return "LAYER-ID-PICK-1";
    case Rule::LayerStackLimit:
    case Rule::ElementLimit:
    case Rule::ElementIdSparse: return "ID-BOUND-1";
    case Rule::LayerDestroyMissing:
    case Rule::LayerEmptyNameDestroys:
    case Rule::LayerDestroy: return "LAYER-DESTROY-1";
    case Rule::SubscribeMissing:
    case Rule::UnsubscribeMissing:
    case Rule::SubscribeFormatUnsubscribes:
    case Rule::Subscribe:
    case Rule::Unsubscribe: return "LAYER-SUBSCRIBE-1";
    case Rule::WriteNoSuchLayer:
    case Rule::WriteWrongType:
    case Rule::WriteNoSuchElement: return "LAYER-WRITE-1";
    case Rule::VertexNotFinite: return "VERTEX-FINITE-1";
    case Rule::VertexNoFreeId:
    case Rule::PolygonNoFreeId:
    case Rule::VertexIdPick:
    case Rule::PolygonIdPick: return "VERTEX-ID-PICK-1";
    case Rule::VertexDeleteMissing:
    case Rule::VertexMaxCoordinateDeletes:
    case Rule::VertexDelete: return "VERTEX-DELETE-1";
    case Rule::PolygonCornerUnused: return "POLY-CORNERS-1";
    case Rule::PolygonCornerRepeated: return "POLY-DISTINCT-1";
    case Rule::PolygonCornerNoVertex: return "POLY-VERTEX-REF-1";
    case Rule::PolygonDeleteMissing:
    case Rule::PolygonNoneCornerDeletes:
    case Rule::PolygonDelete: return "POLY-DELETE-1";
    case Rule::CreaseNameInvalid:
    case Rule::CreaseNameLongest: return "CREASE-NAME-1";
    case Rule::BoneNameInvalid:
    case Rule::BoneNameLongest: return "BONE-NAME-1";
    case Rule::BoneValueInvalid: return "BONE-VALUE-1";
    case Rule::BoneWeightInvalid: return "BONE-WEIGHT-1";
    case Rule::BoneReferenceInvalid: return "BONE-REFERENCE-1";
    case Rule::BoneNoFreeId:
    case Rule::BoneIdPick: return "BONE-ID-PICK-1";
    case Rule::BoneCycle: return "BONE-FOREST-1";
    case Rule::BoneDestroyMissing:
    case Rule::BoneEmptyWeightDestroys:
    case Rule::BoneDestroy: return "BONE-DESTROY-1";
    case Rule::LayerCreate: return "LAYER-CREATE-1";
    case Rule::LayerRecreateSameType:
    case Rule::LayerRecreateKeepsSlots:
    case Rule::LayerRetype:
    case Rule::LayerRetypeResetsSlots: return "LAYER-RECREATE-1";
    case Rule::LayerSlotsForStack:
    case Rule::LayerRetypeLeavesStack: return "LAYER-STACK-1";
    case Rule::LayerNewSlotDefault:
    case Rule::ElementNewSlotDefault: return "LAYER-DEFAULT-1";
    case Rule::SlotWriteUint: return "LAYER-VALUE-1";
    case Rule::SlotWriteReal64: return "REAL-STORAGE-1";
    case Rule::SlotWriteReal32: return "REAL-32BIT-1";
    case Rule::VertexCreate:
    case Rule::VertexMove:
    case Rule::VertexMoveKeepsSlots: return "VERTEX-SET-1";
    case Rule::ElementGrowsLayers:
    case Rule::ElementShrinksLayers: return "LAYER-SIZE-1";
    case Rule::PolygonCascadeDelete: return "POLY-VERTEX-DELETE-1";
    case Rule::PolygonCreate:
    case Rule::PolygonRedefine:
    case Rule::PolygonRedefineKeepsSlots: return "POLY-TRIANGLE-1";
    case Rule::CreaseVertexConstant:
    case Rule::CreaseEdgeConstant: return "CREASE-DEFAULT-1";
    case Rule::CreaseVertexLayer: return "CREASE-VERTEX-LAYER-1";
    case Rule::CreaseEdgeLayer: return "CREASE-EDGE-LAYER-1";
    case Rule::CreaseLayerUnresolved: return "CREASE-LAYER-MISSING-1";
    case Rule::BoneCreate: return "BONE-CREATE-1";
    case Rule::RejectedChangesNothing: return "ATOMIC-1";
    case Rule::BaseLayers: return "LAYER-BASE-1";
    case Rule::InitialCreases: return "CREASE-INITIAL-1";
    case Rule::kCount: break;
  }
  return "ACCEPT-1";
}

std::string_view derived_rule_clause(DerivedRule r) {
  switch (r) {
    case DerivedRule::None: return "ACCEPT-1";
    case DerivedRule::VertexCreaseConstant:
    case DerivedRule::EdgeCreaseConstant: return "CREASE-DEFAULT-1";
    case DerivedRule::VertexCreaseLayer: return "CREASE-VERTEX-LAYER-1";
    case DerivedRule::EdgeCreaseLayer: return "CREASE-EDGE-LAYER-1";
    case DerivedRule::VertexCreaseLayerMissing:
    case DerivedRule::EdgeCreaseLayerMissing: return "CREASE-LAYER-MISSING-1";
    case DerivedRule::VertexCreaseInitial:
    case DerivedRule::EdgeCreaseInitial: return "CREASE-INITIAL-1";
    // A polygon's edge count is its corner count: whether the fourth corner
    // is a vertex reference (a quad) or unused (a triangle).
    case DerivedRule::EdgePerCorner: return "POLY-TRIANGLE-1";
    case DerivedRule::BonePoseRoot:
    case DerivedRule::BonePoseParentMissing: return "BONE-PARENT-1";
    case DerivedRule::BonePoseChained:
    case DerivedRule::BonePosePerBone: return "BONE-DOWNSTREAM-1";
    case DerivedRule::kCount: break;
  }
  return "ACCEPT-1";
}

std::string_view rule_name_clause(std::string_view name) {
  Rule r = Rule::None;
  if (parse_rule_name(name, &r)) return rule_clause(r);
  DerivedRule d = DerivedRule::None;
  if (parse_derived_rule_name(name, &d)) return derived_rule_clause(d);
  return "";
}

std::vector<Rule> rules_of_clause(std::string_view clause_id) {
  std::vector<Rule> out;
  for (std::size_t i = 1; i < kRuleCount; ++i)
    if (rule_clause(static_cast<Rule>(i)) == clause_id) out.push_back(static_cast<Rule>(i));
  return out;
}

std::vector<DerivedRule> derived_rules_of_clause(std::string_view clause_id) {
  std::vector<DerivedRule> out;
  for (std::size_t i = 1; i < kDerivedRuleCount; ++i)
    if (derived_rule_clause(static_cast<DerivedRule>(i)) == clause_id) out.push_back(static_cast<DerivedRule>(i));
  return out;
}

std::string_view rule_fault_exemption(Rule r) {
  switch (r) {
    case Rule::LayerStackLimit:
    case Rule::ElementLimit:
      return "not reachable in a bounded run: the cell budget is 2^22 slots per stack (docs/commands.md 4.9)";
    case Rule::BaseLayers:
      return "a fresh node's state, applied by no command: judged by the fresh-node check, not by a rule fault";
    default: return "";
  }
}

std::string_view rule_coverage_exemption(Rule r) {
  switch (r) {
    case Rule::LayerStackLimit:
    case Rule::ElementLimit: return "the cell budget is 2^22 slots per stack (docs/commands.md 4.9)";
    case Rule::LayerNoFreeId: return "needs all 65533 layer ids from 2 to 0xFFFE in use";
    case Rule::BoneNoFreeId: return "needs all 65535 bone ids in use";
    case Rule::VertexNoFreeId:
    case Rule::PolygonNoFreeId: return "needs 2^32 - 1 ids in use";
    default: return "";
  }
}

std::vector<Rule> fault_matrix_rules() {
  std::vector<Rule> out;
  for (std::size_t i = 1; i < kRuleCount; ++i) {
    const Rule r = static_cast<Rule>(i);
    const Clause* c = find_clause(rule_clause(r));
    if (c && c->level == ClauseLevel::Must && rule_fault_exemption(r).empty()) out.push_back(r);
  }
  return out;
}

int clause_strictness(ClauseLevel level) {
  switch (level) {
    case ClauseLevel::Must: return 2;
    case ClauseLevel::ImplementationDefined: return 1;
    case ClauseLevel::Should: return 0;
  }
  return 0;
}

}  // namespace vgc
