// rule.cpp — see rule.h. One entry per rule, in enum order (a test checks).
#include "rule.h"

namespace vgc {
namespace {

constexpr RuleRole G = RuleRole::Guard, A = RuleRole::Alias, B = RuleRole::Accept, P = RuleRole::Place, V = RuleRole::Value,
                   K = RuleRole::Keep, X = RuleRole::Remove;

// clang-format off
constexpr RuleInfo kRules[] = {
    {Rule::None, "none", K, kLineNone, Reason::Ok, "no rule"},
    // guards (docs/commands.md 4.4 .. 4.9)
    {Rule::LayerCreateBaseId, "layer.create.base_id", G, kLineNone, Reason::BaseLayer,
     "layer_create on id 0 or 1 is refused: the base layers are rigidly defined (4.4 step 2)"},
    {Rule::LayerDestroyBaseId, "layer.destroy.base_id", G, kLineNone, Reason::BaseLayer,
     "layer_destroy on id 0 or 1 is refused: the base layers are always present (4.4)"},
    {Rule::LayerTypeUnknown, "layer.create.type_unknown", G, kLineNone, Reason::BadLayerType,
     "a type byte that is none of Table 2-1's eight values is refused (4.4 step 3)"},
    {Rule::LayerNameInvalid, "layer.create.name_invalid", G, kLineNone, Reason::BadName,
     "a layer name over 15 bytes or holding a NUL byte is refused (4.1, 4.4 step 4)"},
    {Rule::LayerNameInUse, "layer.create.name_in_use", G, kLineNone, Reason::NameInUse,
     "a name another layer already has is refused: names are unique in a node (4.4 step 5)"},
    {Rule::LayerNoFreeId, "layer.create.no_free_id", G, kLineNone, Reason::NoFreeId,
     "id 0xFFFF with every layer id in use is refused (4.3)"},
    {Rule::LayerStackLimit, "layer.create.stack_limit", G, kLineNone, Reason::Limit,
     "a layer whose slots would pass the stack's cell budget is refused (4.4 step 7, 4.9)"},
    {Rule::LayerDestroyMissing, "layer.destroy.missing", G, kLineNone, Reason::NoSuchLayer,
     "destroying an id with no layer is refused (4.4)"},
    {Rule::SubscribeMissing, "layer.subscribe.missing", G, kLineNone, Reason::NoSuchLayer,
     "subscribing to an id with no layer is refused (4.4)"},
    {Rule::UnsubscribeMissing, "layer.unsubscribe.missing", G, kLineNone, Reason::NoSuchLayer,
     "unsubscribing from an id with no layer is refused (4.4)"},
    {Rule::WriteNoSuchLayer, "slot.write.no_such_layer", G, kLineNone, Reason::NoSuchLayer,
     "a slot write naming no layer is refused (4.5 slot writes, step 1)"},
    {Rule::WriteWrongType, "slot.write.wrong_type", G, kLineNone, Reason::WrongLayerType,
     "a write for another type than the layer's is refused (4.5 slot writes, step 2)"},
    {Rule::WriteNoSuchElement, "slot.write.no_such_element", G, kLineNone, Reason::NoSuchVertex,
     "a write to a non-base layer at an id that is no live element is refused; it never creates one "
     "(4.5 slot writes, step 3)"},
    {Rule::VertexNotFinite, "vertex.set.not_finite", G, kLineNone, Reason::BadValue,
     "a base-layer position with a NaN or infinite coordinate is refused (4.5 step 2)"},
    {Rule::VertexNoFreeId, "vertex.set.no_free_id", G, kLineNone, Reason::NoFreeId,
     "id 0xFFFFFFFF with every vertex id in use is refused (4.3)"},
    {Rule::ElementLimit, "element.create.limit", G, kLineNone, Reason::Limit,
     "a new vertex or polygon whose slots would pass the stack's cell budget is refused (4.5, 4.9)"},
    {Rule::VertexDeleteMissing, "vertex.delete.missing", G, kLineNone, Reason::NoSuchVertex,
     "deleting a vertex that is not live is refused (4.5)"},
    {Rule::PolygonCornerUnused, "polygon.set.corner_unused", G, kLineNone, Reason::BadPolygon,
     "0xFFFFFFFF among the first three corners is refused: a polygon has 3 or 4 corners (4.5 step 1)"},
    {Rule::PolygonCornerRepeated, "polygon.set.corner_repeated", G, kLineNone, Reason::BadPolygon,
     "a polygon with two equal corners is refused (4.5 step 2)"},
    {Rule::PolygonCornerNoVertex, "polygon.set.corner_no_vertex", G, kLineNone, Reason::NoSuchVertex,
     "a corner that names no live vertex is refused (4.5 step 3)"},
    {Rule::PolygonNoFreeId, "polygon.set.no_free_id", G, kLineNone, Reason::NoFreeId,
     "id 0xFFFFFFFF with every polygon id in use is refused (4.3)"},
    {Rule::PolygonDeleteMissing, "polygon.delete.missing", G, kLineNone, Reason::NoSuchPolygon,
     "deleting a polygon that is not live is refused (4.5)"},
    {Rule::CreaseNameInvalid, "crease.set.name_invalid", G, kLineNone, Reason::BadName,
     "a crease layer name over 15 bytes or holding a NUL byte is refused (4.1, 4.7)"},
    {Rule::BoneNameInvalid, "bone.create.name_invalid", G, kLineNone, Reason::BadName,
     "a weight, reference or curve label over 15 bytes or holding a NUL byte is refused (4.1, 4.8)"},
    {Rule::BoneValueInvalid, "bone.create.value_invalid", G, kLineNone, Reason::BadValue,
     "a non-finite position or rotation, or the zero quaternion, is refused (4.8)"},
    {Rule::BoneWeightInvalid, "bone.create.weight_invalid", G, kLineNone, Reason::BadWeightLayer,
     "a weight name that names no VERTEX_UINT32 or VERTEX_REAL layer is refused (4.8)"},
    {Rule::BoneReferenceInvalid, "bone.create.reference_invalid", G, kLineNone, Reason::BadReferenceLayer,
     "a non-empty reference name that names no VERTEX_UINT32 layer is refused (4.8)"},
    {Rule::BoneNoFreeId, "bone.create.no_free_id", G, kLineNone, Reason::NoFreeId,
     "id 0xFFFF with every bone id in use is refused (4.3)"},
    {Rule::BoneCycle, "bone.create.cycle", G, kLineNone, Reason::BoneCycle,
     "a parent link that would make the bone its own ancestor is refused: bones form a forest (4.8)"},
    {Rule::BoneDestroyMissing, "bone.destroy.missing", G, kLineNone, Reason::NoSuchBone,
     "destroying an id with no bone is refused (4.8)"},
    // aliases (4.2)
    {Rule::LayerEmptyNameDestroys, "alias.layer_create.empty_name", A, kLineNone, Reason::Ok,
     "layer_create with an empty name is layer_destroy (4.2)"},
    {Rule::SubscribeFormatUnsubscribes, "alias.layer_subscribe.format", A, kLineNone, Reason::Ok,
     "layer_subscribe with a real format above 1 is layer_unsubscribe (4.2)"},
    {Rule::VertexMaxCoordinateDeletes, "alias.vertex_set_xyz.max", A, kLineNone, Reason::Ok,
     "vertex_set_xyz with FLT_MAX / DBL_MAX in a coordinate is vertex_delete, whatever layer it names (4.2)"},
    {Rule::PolygonNoneCornerDeletes, "alias.polygon_set_corner.none", A, kLineNone, Reason::Ok,
     "polygon_set_corner_uint32 on layer 1 with v0 = 0xFFFFFFFF is polygon_delete (4.2)"},
    {Rule::BoneEmptyWeightDestroys, "alias.bone_create.empty_weight", A, kLineNone, Reason::Ok,
     "bone_create with an empty weight name is bone_destroy (4.2)"},
    // acceptances at a guard's boundary (4.1)
    {Rule::LayerNameLongest, "layer.create.name_longest", B, kLineLayer, Reason::Ok,
     "a layer name of exactly 15 bytes is valid and stored whole (4.1)"},
    {Rule::CreaseNameLongest, "crease.set.name_longest", B, kLineCreaseVertex | kLineCreaseEdge, Reason::Ok,
     "a crease layer name of exactly 15 bytes is valid and stored whole (4.1)"},
    {Rule::BoneNameLongest, "bone.create.name_longest", B, kLineBone, Reason::Ok,
     "a bone name or label of exactly 15 bytes is valid and stored whole (4.1)"},
    // effects
    {Rule::LayerCreate, "layer.create", V, kLineLayer, Reason::Ok,
     "a new layer is created at exactly the id asked, with the name, type and defaults sent (4.4)"},
    {Rule::LayerIdPick, "layer.create.pick_id", P, kLineLayer, Reason::Ok,
     "id 0xFFFF puts the new layer at the lowest free id from 2 up (4.3)"},
    {Rule::LayerRecreateSameType, "layer.recreate.same_type", V, kLineLayer, Reason::Ok,
     "layer_create on a live layer with its own type renames it and sets the new defaults (4.4)"},
    {Rule::LayerRecreateKeepsSlots, "layer.recreate.keeps_slots", K, kLineSlot | kLineLayer, Reason::Ok,
     "re-creating a layer with its own type keeps its slot values and subscription (4.4)"},
    {Rule::LayerRetype, "layer.retype", V, kLineLayer, Reason::Ok,
     "layer_create on a live layer with another type re-types it and clears its subscription (4.4)"},
    {Rule::LayerRetypeResetsSlots, "layer.retype.resets_slots", V, kLineSlot, Reason::Ok,
     "a re-typed layer's slots all take the new default (4.4, 4.6)"},
    {Rule::LayerSlotsForStack, "layer.slots_for_stack", P, kLineSlot, Reason::Ok,
     "a new or re-typed layer has one slot for each live element of its type's stack: vertices for "
     "VERTEX_*, polygons for POLYGON_* (4.4)"},
    {Rule::LayerRetypeLeavesStack, "layer.retype.leaves_stack", X, kLineSlot, Reason::Ok,
     "a layer re-typed into the other stack no longer has slots for its old stack's elements (4.4)"},
    {Rule::LayerNewSlotDefault, "layer.create.slot_default", V, kLineSlot, Reason::Ok,
     "a new layer's slots hold its default: def_uint for integer types, def_real for real and XYZ (4.6)"},
    {Rule::LayerDestroy, "layer.destroy", X, kLineLayer | kLineSlot, Reason::Ok,
     "the layer and all its slots are removed (4.4)"},
    {Rule::Subscribe, "layer.subscribe", V, kLineLayer, Reason::Ok,
     "the layer's subscription becomes REAL32 or REAL64 (4.4)"},
    {Rule::Unsubscribe, "layer.unsubscribe", V, kLineLayer, Reason::Ok,
     "the layer's subscription is cleared (4.4)"},
    {Rule::SlotWriteUint, "slot.write.uint", V, kLineSlot, Reason::Ok,
     "an integer slot write stores every component as sent (4.5 slot writes)"},
    {Rule::SlotWriteReal64, "slot.write.real64", V, kLineSlot, Reason::Ok,
     "a 64-bit real write stores the value bit for bit, NaN payloads and -0.0 included (4.5 slot writes)"},
    {Rule::SlotWriteReal32, "slot.write.real32", V, kLineSlot, Reason::Ok,
     "a 32-bit real write stores the float widened exactly to 64 bits (4.5 slot writes)"},
    {Rule::VertexCreate, "vertex.create", V, kLineVertex, Reason::Ok,
     "a set on layer 0 at an id with no live vertex creates the vertex at the position sent (4.5 step 5)"},
    {Rule::VertexMove, "vertex.move", V, kLineVertex, Reason::Ok,
     "a set on layer 0 at a live vertex replaces its position (4.5 step 4)"},
    {Rule::VertexMoveKeepsSlots, "vertex.move.keeps_slots", K, kLineSlot, Reason::Ok,
     "a moved vertex keeps its slot values in every other vertex-stack layer (4.5 step 4)"},
    {Rule::VertexIdPick, "vertex.create.pick_id", P, kLineVertex, Reason::Ok,
     "id 0xFFFFFFFF puts the new vertex at the lowest free id (4.3)"},
    {Rule::ElementIdSparse, "element.create.sparse_id", P, kLineVertex | kLinePolygon, Reason::Ok,
     "an id of 2^24 or more is stored like any other, without storage for the ids below it (4.5)"},
    {Rule::ElementGrowsLayers, "element.create.grows_layers", P, kLineSlot, Reason::Ok,
     "a new vertex (polygon) gets a slot in every other layer of its stack (4.5 steps 5 and 6)"},
    {Rule::ElementNewSlotDefault, "element.create.slot_default", V, kLineSlot, Reason::Ok,
     "a new element's slot in another layer holds that layer's default (4.6)"},
    {Rule::VertexDelete, "vertex.delete", X, kLineVertex, Reason::Ok,
     "the vertex is removed (4.5)"},
    {Rule::ElementShrinksLayers, "element.delete.shrinks_layers", X, kLineSlot, Reason::Ok,
     "a deleted vertex (polygon) loses its slot in every layer of its stack (4.5)"},
    {Rule::PolygonCascadeDelete, "vertex.delete.cascades", X, kLinePolygon | kLineSlot, Reason::Ok,
     "every polygon that has a deleted vertex among its corners is deleted with it (4.5)"},
    {Rule::PolygonCreate, "polygon.create", V, kLinePolygon, Reason::Ok,
     "a set on layer 1 at an id with no live polygon creates it with the corners sent (4.5 step 6)"},
    {Rule::PolygonRedefine, "polygon.redefine", V, kLinePolygon, Reason::Ok,
     "a set on layer 1 at a live polygon replaces its corners (4.5 step 5)"},
    {Rule::PolygonRedefineKeepsSlots, "polygon.redefine.keeps_slots", K, kLineSlot, Reason::Ok,
     "a re-defined polygon keeps its slot values in every other polygon-stack layer (4.5 step 5)"},
    {Rule::PolygonIdPick, "polygon.create.pick_id", P, kLinePolygon, Reason::Ok,
     "id 0xFFFFFFFF puts the new polygon at the lowest free id (4.3)"},
    {Rule::PolygonDelete, "polygon.delete", X, kLinePolygon, Reason::Ok,
     "the polygon is removed (4.5)"},
    {Rule::CreaseVertexConstant, "crease.vertex.constant", V, kLineCreaseVertex, Reason::Ok,
     "with no layer named, the constant is every vertex's crease (4.7)"},
    {Rule::CreaseVertexLayer, "crease.vertex.layer", V, kLineCreaseVertex, Reason::Ok,
     "a named vertex crease layer is stored as sent and resolved when creases are read (4.7)"},
    {Rule::CreaseEdgeConstant, "crease.edge.constant", V, kLineCreaseEdge, Reason::Ok,
     "with no layer named, the constant is every edge's crease (4.7)"},
    {Rule::CreaseEdgeLayer, "crease.edge.layer", V, kLineCreaseEdge, Reason::Ok,
     "a named edge crease layer is stored as sent and resolved when creases are read (4.7)"},
    {Rule::CreaseLayerUnresolved, "crease.layer_unresolved", V, kLineCreaseVertex | kLineCreaseEdge, Reason::Ok,
     "a crease layer name that names no layer of the right type is stored as sent; the constant applies "
     "until such a layer exists (4.7)"},
    {Rule::BoneCreate, "bone.create", V, kLineBone, Reason::Ok,
     "the bone is stored at the id asked with every field as sent, replacing a live one (4.8)"},
    {Rule::BoneIdPick, "bone.create.pick_id", P, kLineBone, Reason::Ok,
     "id 0xFFFF puts the bone at the lowest free id from 0 up (4.3)"},
    {Rule::BoneDestroy, "bone.destroy", X, kLineBone, Reason::Ok,
     "the bone is removed; its children keep their parent links (4.8)"},
    {Rule::RejectedChangesNothing, "command.rejected.changes_nothing", K, kLineAll, Reason::Ok,
     "a refused command leaves every line of the snapshot as it was (4)"},
    {Rule::BaseLayers, "node.base_layers", V, kLineLayer, Reason::Ok,
     "a fresh node has layer 0 \"vertex\" VERTEX_XYZ and layer 1 \"polygon\" POLYGON_CORNER_UINT32 (4.4)"},
    {Rule::InitialCreases, "node.initial_creases", V, kLineCreaseVertex | kLineCreaseEdge, Reason::Ok,
     "a fresh node's vertex and edge creases are the constant 0: smooth everywhere (4.7)"},
};
// clang-format on
static_assert(sizeof(kRules) / sizeof(kRules[0]) == kRuleCount, "one RuleInfo per Rule");

}  // namespace

std::uint8_t line_kind_bit(std::string_view kind) {
  if (kind == "layer") return kLineLayer;
  if (kind == "vertex") return kLineVertex;
  if (kind == "polygon") return kLinePolygon;
  if (kind == "slot") return kLineSlot;
  if (kind == "crease_vertex") return kLineCreaseVertex;
  if (kind == "crease_edge") return kLineCreaseEdge;
  if (kind == "bone") return kLineBone;
  return kLineNone;
}

const RuleInfo& rule_info(Rule r) {
  const auto i = static_cast<std::size_t>(r);
  return i < kRuleCount ? kRules[i] : kRules[0];
}

std::string_view rule_name(Rule r) { return rule_info(r).name; }

bool parse_rule_name(std::string_view name, Rule* out) {
  for (const auto& info : kRules)
    if (info.name == name) {
      *out = info.rule;
      return true;
    }
  return false;
}

std::string_view rule_role_name(RuleRole role) {
  switch (role) {
    case RuleRole::Guard: return "guard";
    case RuleRole::Alias: return "alias";
    case RuleRole::Accept: return "accept";
    case RuleRole::Place: return "place";
    case RuleRole::Value: return "value";
    case RuleRole::Keep: return "keep";
    case RuleRole::Remove: return "remove";
  }
  return "?";
}

}  // namespace vgc
