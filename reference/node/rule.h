// rule.h — every decision the reference node makes, as a named rule.
//
// Spec: 000 section 2.6 and docs/commands.md section 4 (each rule's text
// says which step of 4.2 .. 4.9 it is). The vocabulary is the node's own:
// no clause ids here (reference/ stays free of the catalog;
// conformance/rule_clauses.cpp maps each rule to exactly one clause).
//
// Rationale: in the manner of OpenSubdiv's sdc crease rules, each thing the
// node decides has a name: every guard that refuses a command (with its
// reason code), every wire alias it follows, and every kind of state it
// writes (a line placed at an id, a line's values written, a slot value
// kept, reset or defaulted, a line removed). Node::apply records the rules
// a command applied in a RuleTrace (a fixed array: no allocation), and
// every stored element remembers which rule last wrote it and at which
// step (Written), so a difference from an implementation can be blamed on
// the rule that decided it rather than guessed from the difference's shape.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "reason.h"

namespace vgc {

enum class Rule : std::uint8_t {
  None,
  // ---- guards: the command is refused, nothing changes ----------------------
  LayerCreateBaseId,       // layer_create on id 0 or 1
  LayerDestroyBaseId,      // layer_destroy on id 0 or 1
  LayerTypeUnknown,        // type byte not one of Table 2-1's eight
  LayerNameInvalid,        // name over 15 bytes or holding a NUL
  LayerNameInUse,          // another layer has the name
  LayerNoFreeId,           // 0xFFFF asked, no id free
  LayerStackLimit,         // a new or re-stacked layer passes the cell budget
  LayerDestroyMissing,     // no such layer to destroy
  SubscribeMissing,        // subscribe: no such layer
  UnsubscribeMissing,      // unsubscribe: no such layer
  WriteNoSuchLayer,        // a slot write names no layer
  WriteWrongType,          // a slot write for another type than the layer's
  WriteNoSuchElement,      // a slot write for an element that is not live
  VertexNotFinite,         // a base position with a NaN or infinite coordinate
  VertexNoFreeId,          // 0xFFFFFFFF asked, no vertex id free
  ElementLimit,            // a new vertex or polygon passes the cell budget
  VertexDeleteMissing,     // deleting a vertex that is not live
  PolygonCornerUnused,     // 0xFFFFFFFF among the first three corners
  PolygonCornerRepeated,   // two corners equal
  PolygonCornerNoVertex,   // a corner names no live vertex
  PolygonNoFreeId,         // 0xFFFFFFFF asked, no polygon id free
  PolygonDeleteMissing,    // deleting a polygon that is not live
  CreaseNameInvalid,       // crease layer name over 15 bytes or holding a NUL
  BoneNameInvalid,         // a bone name or label over 15 bytes or holding a NUL
  BoneValueInvalid,        // non-finite position or rotation, or the zero quaternion
  BoneWeightInvalid,       // weight layer missing or of another type
  BoneReferenceInvalid,    // reference layer missing or not VERTEX_UINT32
  BoneNoFreeId,            // 0xFFFF asked, no bone id free
  BoneCycle,               // the parent link would make the bone its own ancestor
  BoneDestroyMissing,      // no such bone to destroy
  // ---- wire aliases: the command is read as another ----------------------------
  LayerEmptyNameDestroys,      // layer_create with an empty name
  SubscribeFormatUnsubscribes, // layer_subscribe with a format > 1
  VertexMaxCoordinateDeletes,  // FLT_MAX / DBL_MAX in a coordinate, on any layer
  PolygonNoneCornerDeletes,    // v0 = 0xFFFFFFFF on layer 1
  BoneEmptyWeightDestroys,     // bone_create with an empty weight name
  // ---- acceptances at a guard's boundary ------------------------------------
  LayerNameLongest,        // a 15-byte layer name accepted
  CreaseNameLongest,       // a 15-byte crease layer name accepted
  BoneNameLongest,         // a 15-byte bone name or label accepted
  // ---- effects: what an applied command writes ---------------------------------
  LayerCreate,             // a new layer at the id asked, name/type/defaults as sent
  LayerIdPick,             // 0xFFFF: the layer goes to the lowest free id from 2
  LayerRecreateSameType,   // same id, same type: renamed, new defaults
  LayerRecreateKeepsSlots, // ... its slot values and subscription kept
  LayerRetype,             // same id, other type: re-typed, subscription cleared
  LayerRetypeResetsSlots,  // ... every slot takes the new default
  LayerSlotsForStack,      // a new or re-typed layer has one slot per live element of its stack
  LayerRetypeLeavesStack,  // a layer re-typed into the other stack drops its old stack's slots
  LayerNewSlotDefault,     // a new layer's slots take its default
  LayerDestroy,            // the layer and all its slots removed
  Subscribe,               // the subscription recorded
  Unsubscribe,             // the subscription cleared
  SlotWriteUint,           // an integer slot write stored as sent
  SlotWriteReal64,         // a 64-bit real slot write stored bit for bit
  SlotWriteReal32,         // a 32-bit real slot write widened exactly
  VertexCreate,            // a new vertex at the position sent
  VertexMove,              // a live vertex's position replaced
  VertexMoveKeepsSlots,    // ... its slots in the other vertex layers kept
  VertexIdPick,            // 0xFFFFFFFF: the vertex goes to the lowest free id
  ElementIdSparse,         // an id of 2^24 or more stored like any other
  ElementGrowsLayers,      // a new element gets a slot in every other layer of its stack
  ElementNewSlotDefault,   // ... holding that layer's default
  VertexDelete,            // the vertex removed
  ElementShrinksLayers,    // a deleted element's slot removed from every layer of its stack
  PolygonCascadeDelete,    // every polygon using a deleted vertex deleted with it
  PolygonCreate,           // a new polygon with the corners sent
  PolygonRedefine,         // a live polygon's corners replaced
  PolygonRedefineKeepsSlots, // ... its slots in the other polygon layers kept
  PolygonIdPick,           // 0xFFFFFFFF: the polygon goes to the lowest free id
  PolygonDelete,           // the polygon removed
  CreaseVertexConstant,    // vertex creases: the constant, no layer named
  CreaseVertexLayer,       // vertex creases: a layer named, stored as sent
  CreaseEdgeConstant,      // edge creases: the constant
  CreaseEdgeLayer,         // edge creases: a layer named
  CreaseLayerUnresolved,   // a crease layer named that is not (yet) a layer of the right type
  BoneCreate,              // a bone stored with every field as sent
  BoneIdPick,              // 0xFFFF: the bone goes to the lowest free id from 0
  BoneDestroy,             // the bone removed
  RejectedChangesNothing,  // any refused command leaves every line as it was
  // ---- the state of a fresh node ----------------------------------------------
  BaseLayers,              // layers 0 "vertex" and 1 "polygon" present from the start
  InitialCreases,          // both creases the constant 0 at the start
  kCount
};

inline constexpr std::size_t kRuleCount = static_cast<std::size_t>(Rule::kCount);

// What kind of decision a rule is, for reading a difference:
//   Guard   refuses the command (its reason code is RuleInfo::reason);
//   Alias   reads the command as another (a wire alias);
//   Accept  lets the command pass a guard at the guard's boundary (the
//           longest name allowed): refusing it, or storing the value
//           cut, breaks that guard's rule;
//   Place   decides at which id a line exists (creates it there);
//   Value   writes a line's values (creating it when no Place rule does);
//   Keep    leaves lines as they were (the command must not change them);
//   Remove  removes lines.
enum class RuleRole : std::uint8_t { Guard, Alias, Accept, Place, Value, Keep, Remove };

// The snapshot lines a rule acts on, as a bit set (docs/commands.md 6.1).
enum LineKindBits : std::uint8_t {
  kLineNone = 0,
  kLineLayer = 1,
  kLineVertex = 2,
  kLinePolygon = 4,
  kLineSlot = 8,
  kLineCreaseVertex = 16,
  kLineCreaseEdge = 32,
  kLineBone = 64,
  kLineAll = 127,
};
// The bit of a snapshot line kind ("layer", "slot", ...); kLineNone for
// any other word.
std::uint8_t line_kind_bit(std::string_view kind);

struct RuleInfo {
  Rule rule;
  std::string_view name;  // "vertex.move.keeps_slots": stable, printed in findings
  RuleRole role;
  std::uint8_t lines;     // LineKindBits
  Reason reason;          // a guard's reason code; Reason::Ok otherwise
  std::string_view says;  // what the node does, and why, in one sentence
};

const RuleInfo& rule_info(Rule r);
std::string_view rule_name(Rule r);
// Inverse of rule_name; false for an unknown name.
bool parse_rule_name(std::string_view name, Rule* out);
std::string_view rule_role_name(RuleRole role);  // "guard", "alias", ...

// The rules one command applied, in the order it applied them (each once).
// A fixed array: recording costs no allocation.
struct RuleTrace {
  static constexpr std::size_t kCapacity = 16;
  std::array<Rule, kCapacity> rules{};
  std::uint8_t count = 0;

  void add(Rule r) {
    if (has(r) || count == kCapacity) return;
    rules[count++] = r;
  }
  bool has(Rule r) const {
    for (std::uint8_t i = 0; i < count; ++i)
      if (rules[i] == r) return true;
    return false;
  }
  const Rule* begin() const { return rules.data(); }
  const Rule* end() const { return rules.data() + count; }
  void clear() { count = 0; }
};

// Which rule last wrote a stored element, and at which step (the node's
// apply count then; 0 for a fresh node's base state).
struct Written {
  Rule rule = Rule::None;
  std::uint32_t step = 0;
};

}  // namespace vgc
