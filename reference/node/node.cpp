// node.cpp — see node.h. Each rule quotes or names the spec text it comes
// from; "Decision:" marks where the spec is silent and this suite chose.
#include "node.h"

#include <cfloat>
#include <cmath>
#include <set>
#include <type_traits>

namespace vgc {
namespace {

bool valid_name(const std::string& s) {
  // README: names are at most 16 bytes including the terminating NUL, so a
  // NUL inside a name cannot be sent either.
  return s.size() <= kMaxNameBytes && s.find('\0') == std::string::npos;
}

// Ids from here up are far past any dense array an implementation might
// keep (rule element.create.sparse_id).
constexpr std::uint32_t kSparseId = std::uint32_t{1} << 24;

bool all_finite(const double* v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

// Lowest id in [first, last] that `used` does not contain, or nullopt.
template <class Map, class Id>
std::optional<Id> lowest_free(const Map& used, Id first, Id last) {
  Id candidate = first;
  for (auto it = used.lower_bound(first); it != used.end() && it->first == candidate; ++it) {
    if (candidate == last) return std::nullopt;
    ++candidate;
  }
  return candidate;
}

}  // namespace

Slot default_slot(const Layer& layer) {
  Slot s;
  // Decision: a POLYGON_FACE_UINT8 layer keeps the low 8 bits of def_uint,
  // as the wire's uint32 default converts to the layer's uint8 in C.
  const std::uint32_t u =
      layer.type == LayerType::PolygonFaceUint8 ? (layer.def_uint & 0xFFu) : layer.def_uint;
  s.u.fill(u);
  s.r.fill(layer.def_real);
  return s;
}

Node::Node(NodeLimits limits) : limits_(limits) {
  // 2.6.1: layer 0 "vertex" VERTEX_XYZ and layer 1 "polygon"
  // POLYGON_CORNER_UINT32 "are always present in every geometry node".
  Layer v;
  v.id = kVertexLayer;
  v.name = "vertex";
  v.type = LayerType::VertexXyz;
  Layer p;
  p.id = kPolygonLayer;
  p.name = "polygon";
  p.type = LayerType::PolygonCornerUint32;
  v.written = p.written = {Rule::BaseLayers, 0};
  layers_.emplace(v.id, v);
  layers_.emplace(p.id, p);
  // Decision: a new node is smooth everywhere: both creases are the
  // constant 0. 2.6.4 says a cube must "explicitly set" sharp creasing.
}

Reason Node::apply(const Command& c, RuleTrace* trace, ChangeLog* changes) {
  ++step_;
  trace_ = trace;
  changes_ = changes;
  if (changes_) changes_->clear();
  const Reason r = std::visit([this](const auto& x) { return apply_one(x); }, c);
  if (r != Reason::Ok) note(Rule::RejectedChangesNothing);
  trace_ = nullptr;
  changes_ = nullptr;
  return r;
}

const Layer* Node::find_layer(std::uint16_t id) const {
  auto it = layers_.find(id);
  return it == layers_.end() ? nullptr : &it->second;
}

const Layer* Node::find_layer_by_name(const std::string& name) const {
  for (const auto& [id, layer] : layers_)
    if (layer.name == name) return &layer;
  return nullptr;
}

std::size_t Node::layers_in_stack(bool vertex_stack) const {
  std::size_t n = 0;
  for (const auto& [id, layer] : layers_)
    if (is_vertex_layer_type(layer.type) == vertex_stack) ++n;
  return n;
}

// ---- layers (2.6.1) --------------------------------------------------------

Reason Node::apply_one(const cmd::LayerCreate& c) {
  // README: "an empty name means g_layer_destroy(layer_id)".
  if (c.name.empty()) {
    note(Rule::LayerEmptyNameDestroys);
    return apply_one(cmd::LayerDestroy{c.layer_id});
  }
  // 2.6.1: the two base layers "are rigidly defined". Decision: creating on
  // id 0 or 1 is rejected (the r6 host silently picks another id instead).
  const bool bad_type = !is_layer_type(c.type), bad_name = !valid_name(c.name);
  if (c.layer_id == kVertexLayer || c.layer_id == kPolygonLayer) {
    const Reason r = refuse(Rule::LayerCreateBaseId, Reason::BaseLayer);
    also_refusing({{Rule::LayerTypeUnknown, bad_type}, {Rule::LayerNameInvalid, bad_name}});
    return r;
  }
  // Table 2-1 lists eight types; README: "Any other value is not a layer type".
  if (bad_type) {
    const Reason r = refuse(Rule::LayerTypeUnknown, Reason::BadLayerType);
    also_refusing({{Rule::LayerNameInvalid, bad_name}});
    return r;
  }
  if (bad_name) return refuse(Rule::LayerNameInvalid, Reason::BadName);
  if (c.name.size() == kMaxNameBytes) note(Rule::LayerNameLongest);
  // Decision: names are unique within the node (so that creases and bones,
  // which name layers, are unambiguous). A clash with another layer is
  // rejected; re-creating a layer under its own name is fine.
  if (const Layer* other = find_layer_by_name(c.name); other && other->id != c.layer_id)
    return refuse(Rule::LayerNameInUse, Reason::NameInUse);

  std::uint16_t id = c.layer_id;
  if (id == kNone16) {  // README: 0xFFFF asks the host to pick a free id.
    auto free = lowest_free(layers_, std::uint16_t{2}, std::uint16_t{0xFFFE});
    if (!free) return refuse(Rule::LayerNoFreeId, Reason::NoFreeId);
    id = *free;
  }
  const LayerType type = static_cast<LayerType>(c.type);
  const bool vertex_stack = is_vertex_layer_type(type);
  const auto& base = vertex_stack ? vertices() : polygons();

  auto existing = layers_.find(id);
  const bool keeps_data = existing != layers_.end() && existing->second.type == type;
  if (existing == layers_.end() || is_vertex_layer_type(existing->second.type) != vertex_stack) {
    if ((layers_in_stack(vertex_stack) + 1) * std::max<std::size_t>(base.size(), 1) >
        limits_.max_cells_per_stack)
      return refuse(Rule::LayerStackLimit, Reason::Limit);
  }
  if (c.layer_id == kNone16) note(Rule::LayerIdPick);

  Layer layer;
  layer.id = id;
  layer.name = c.name;
  layer.type = type;
  layer.def_uint = c.def_uint;
  layer.def_real = c.def_real;
  if (keeps_data) {
    // Decision: re-creating a layer with its own type renames it and changes
    // its defaults but keeps its data and subscription.
    note(Rule::LayerRecreateSameType);
    note(Rule::LayerRecreateKeepsSlots);
    layer.written = written(Rule::LayerRecreateSameType);
    layer.slots = std::move(existing->second.slots);
    layer.subscription = existing->second.subscription;
  } else {
    // 2.6.1: every layer of a stack has a slot per element of its base
    // layer, "initialized with a default value". Decision: re-creating with
    // another type (as the r6 host does) resets every slot to the new default.
    const bool retype = existing != layers_.end();
    const Rule value_rule = retype ? Rule::LayerRetypeResetsSlots : Rule::LayerNewSlotDefault;
    note(retype ? Rule::LayerRetype : Rule::LayerCreate);
    if (retype && is_vertex_layer_type(existing->second.type) != vertex_stack && !existing->second.slots.empty())
      note(Rule::LayerRetypeLeavesStack);
    if (!base.empty()) {
      note(Rule::LayerSlotsForStack);
      note(value_rule);
    }
    layer.written = written(retype ? Rule::LayerRetype : Rule::LayerCreate);
    Slot fresh = default_slot(layer);
    fresh.written = written(value_rule);
    for (const auto& [element, unused] : base) layer.slots.emplace(element, fresh);
  }
  layers_[id] = std::move(layer);
  if (changes_) changes_->whole_layers.push_back(id);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::LayerDestroy& c) {
  // 2.6.1: the base layers "are always present". Decision: destroying them
  // is rejected rather than ignored.
  if (c.layer_id == kVertexLayer || c.layer_id == kPolygonLayer)
    return refuse(Rule::LayerDestroyBaseId, Reason::BaseLayer);
  if (layers_.erase(c.layer_id) == 0) return refuse(Rule::LayerDestroyMissing, Reason::NoSuchLayer);
  if (changes_) changes_->whole_layers.push_back(c.layer_id);
  note(Rule::LayerDestroy);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::LayerSubscribe& c) {
  // README: "a real_format above REAL64 (any value > 1) means
  // g_layer_unsubscribe(layer_id): on the wire there is no separate
  // unsubscribe command". The two forms are the same bytes, so the alias is
  // exactly the unsubscribe (same verdict, same effect); BAD_REAL_FORMAT is
  // no longer produced.
  if (c.real_format > 1) {
    note(Rule::SubscribeFormatUnsubscribes);
    return apply_one(cmd::LayerUnsubscribe{c.layer_id});
  }
  auto it = layers_.find(c.layer_id);
  if (it == layers_.end()) return refuse(Rule::SubscribeMissing, Reason::NoSuchLayer);
  // README: "REAL32=0, REAL64=1".
  note(Rule::Subscribe);
  it->second.subscription = static_cast<RealFormat>(c.real_format);
  it->second.written = written(Rule::Subscribe);
  if (changes_) changes_->layer_lines.push_back(c.layer_id);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::LayerUnsubscribe& c) {
  auto it = layers_.find(c.layer_id);
  if (it == layers_.end()) return refuse(Rule::UnsubscribeMissing, Reason::NoSuchLayer);
  // Decision: unsubscribing a layer that has no subscription is a no-op.
  note(Rule::Unsubscribe);
  it->second.subscription.reset();
  it->second.written = written(Rule::Unsubscribe);
  if (changes_) changes_->layer_lines.push_back(c.layer_id);
  return Reason::Ok;
}

// ---- vertices --------------------------------------------------------------

Reason Node::find_slot(std::uint16_t layer_id, LayerType type, std::uint32_t id, Slot** out) {
  auto it = layers_.find(layer_id);
  if (it == layers_.end()) return refuse(Rule::WriteNoSuchLayer, Reason::NoSuchLayer);
  if (it->second.type != type) return refuse(Rule::WriteWrongType, Reason::WrongLayerType);
  // 2.6.1: a layer's size "is controlled by the size of the base layer":
  // only live elements have slots. Decision: writing a non-base layer at an
  // id with no live vertex (polygon) is rejected; it never creates one.
  auto slot = it->second.slots.find(id);
  if (slot == it->second.slots.end())
    return refuse(Rule::WriteNoSuchElement, is_vertex_layer_type(type) ? Reason::NoSuchVertex : Reason::NoSuchPolygon);
  *out = &slot->second;
  touch_slot(layer_id, id);
  return Reason::Ok;
}

Reason Node::new_element(std::uint16_t base_layer, std::uint32_t id, const Slot& base_value) {
  const bool vertex_stack = base_layer == kVertexLayer;
  const auto& base = layers_.at(base_layer).slots;
  if ((base.size() + 1) * layers_in_stack(vertex_stack) > limits_.max_cells_per_stack)
    return refuse(Rule::ElementLimit, Reason::Limit);
  if (id >= kSparseId) note(Rule::ElementIdSparse);
  note(vertex_stack ? Rule::VertexCreate : Rule::PolygonCreate);
  // 2.6.1: "all other layers are grown to provide a slot ... initialized
  // with a default value".
  for (auto& [lid, layer] : layers_) {
    if (is_vertex_layer_type(layer.type) != vertex_stack) continue;
    Slot& slot = layer.slots[id];
    touch_slot(lid, id);
    if (lid == base_layer) {
      slot = base_value;
      slot.written = written(vertex_stack ? Rule::VertexCreate : Rule::PolygonCreate);
    } else {
      note(Rule::ElementGrowsLayers);
      note(Rule::ElementNewSlotDefault);
      slot = default_slot(layer);
      slot.written = written(Rule::ElementNewSlotDefault);
    }
  }
  return Reason::Ok;
}

void Node::erase_element(bool vertex_stack, std::uint32_t id) {
  for (auto& [lid, layer] : layers_) {
    if (is_vertex_layer_type(layer.type) != vertex_stack) continue;
    touch_slot(lid, id);
    if (layer.slots.erase(id) && lid != kVertexLayer && lid != kPolygonLayer) note(Rule::ElementShrinksLayers);
  }
}

Reason Node::set_xyz(std::uint16_t layer_id, std::uint32_t vertex_id, std::array<double, 3> xyz, Rule value_rule) {
  // (layer 0 always exists and is VERTEX_XYZ; find_slot checks the others)
  if (layer_id != kVertexLayer) {
    Slot* slot = nullptr;
    if (Reason r = find_slot(layer_id, LayerType::VertexXyz, vertex_id, &slot); r != Reason::Ok)
      return r;
    note(value_rule);
    std::copy(xyz.begin(), xyz.end(), slot->r.begin());  // any value: it is data
    slot->written = written(value_rule);
    return Reason::Ok;
  }
  // Decision: base-layer positions must be finite; they are the geometry
  // that gets subdivided. Other XYZ layers hold any value.
  if (!all_finite(xyz.data(), 3)) return refuse(Rule::VertexNotFinite, Reason::BadValue);
  std::uint32_t id = vertex_id;
  auto& base = layers_.at(kVertexLayer).slots;
  if (id == kNone32) {  // README: 0xFFFFFFFF asks the host to pick a free id.
    auto free = lowest_free(base, std::uint32_t{0}, std::uint32_t{0xFFFFFFFE});
    if (!free) return refuse(Rule::VertexNoFreeId, Reason::NoFreeId);
    id = *free;
    note(Rule::VertexIdPick);
  }
  if (auto slot = base.find(id); slot != base.end()) {  // moving a live vertex
    note(Rule::VertexMove);
    if (layers_in_stack(true) > 1) note(Rule::VertexMoveKeepsSlots);
    std::copy(xyz.begin(), xyz.end(), slot->second.r.begin());
    slot->second.written = written(Rule::VertexMove);
    touch_slot(kVertexLayer, id);
    return Reason::Ok;
  }
  Slot value;
  std::copy(xyz.begin(), xyz.end(), value.r.begin());
  return new_element(kVertexLayer, id, value);
}

Reason Node::apply_one(const cmd::VertexSetXyzReal32& c) {
  // README: "x, y or z equal to FLT_MAX means g_vertex_delete_real32".
  if (c.x == FLT_MAX || c.y == FLT_MAX || c.z == FLT_MAX) {
    note(Rule::VertexMaxCoordinateDeletes);
    return apply_one(cmd::VertexDelete{c.vertex_id});
  }
  // 2.6.1: REAL data is held in 64 bits; float to double is exact.
  return set_xyz(c.layer_id, c.vertex_id, {double(c.x), double(c.y), double(c.z)}, Rule::SlotWriteReal32);
}

Reason Node::apply_one(const cmd::VertexSetXyzReal64& c) {
  if (c.x == DBL_MAX || c.y == DBL_MAX || c.z == DBL_MAX) {
    note(Rule::VertexMaxCoordinateDeletes);
    return apply_one(cmd::VertexDelete{c.vertex_id});
  }
  return set_xyz(c.layer_id, c.vertex_id, {c.x, c.y, c.z}, Rule::SlotWriteReal64);
}

Reason Node::apply_one(const cmd::VertexDelete& c) {
  if (vertices().count(c.vertex_id) == 0) return refuse(Rule::VertexDeleteMissing, Reason::NoSuchVertex);
  // Decision: deleting a vertex deletes every polygon that uses it, so that
  // every live polygon always names live vertices (the r6 host leaves such
  // polygons dangling).
  std::vector<std::uint32_t> users;
  for (const auto& [pid, slot] : polygons())
    for (std::uint32_t v : slot.u)
      if (v == c.vertex_id) {
        users.push_back(pid);
        break;
      }
  note(Rule::VertexDelete);
  if (!users.empty()) note(Rule::PolygonCascadeDelete);
  for (std::uint32_t pid : users) erase_element(false, pid);
  erase_element(true, c.vertex_id);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::VertexSetUint32& c) {
  Slot* slot = nullptr;
  if (Reason r = find_slot(c.layer_id, LayerType::VertexUint32, c.vertex_id, &slot); r != Reason::Ok) return r;
  note(Rule::SlotWriteUint);
  slot->u[0] = c.value;
  slot->written = written(Rule::SlotWriteUint);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::VertexSetReal64& c) {
  Slot* slot = nullptr;
  if (Reason r = find_slot(c.layer_id, LayerType::VertexReal, c.vertex_id, &slot); r != Reason::Ok) return r;
  note(Rule::SlotWriteReal64);
  slot->r[0] = c.value;
  slot->written = written(Rule::SlotWriteReal64);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::VertexSetReal32& c) {
  Slot* slot = nullptr;
  if (Reason r = find_slot(c.layer_id, LayerType::VertexReal, c.vertex_id, &slot); r != Reason::Ok) return r;
  note(Rule::SlotWriteReal32);
  slot->r[0] = double(c.value);  // 2.6.1: 32-bit writes, 64-bit storage
  slot->written = written(Rule::SlotWriteReal32);
  return Reason::Ok;
}

// ---- polygons --------------------------------------------------------------

Reason Node::set_corners(std::uint16_t layer_id, std::uint32_t polygon_id, std::array<std::uint32_t, 4> v) {
  if (layer_id != kPolygonLayer) {
    Slot* slot = nullptr;
    if (Reason r = find_slot(layer_id, LayerType::PolygonCornerUint32, polygon_id, &slot); r != Reason::Ok)
      return r;
    note(Rule::SlotWriteUint);
    slot->u = v;  // any values: e.g. edge creases (2.6.2)
    slot->written = written(Rule::SlotWriteUint);
    return Reason::Ok;
  }
  // 2.6: "All polygons have exactly three or four corners"; "if the three
  // first references are valid and the fourth unused, the polygon is a
  // triangle"; README: "Polygon corners must be pairwise distinct".
  for (int i = 0; i < 3; ++i)
    if (v[i] == kNone32) return refuse(Rule::PolygonCornerUnused, Reason::BadPolygon);
  const int n = v[3] == kNone32 ? 3 : 4;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (v[i] == v[j]) return refuse(Rule::PolygonCornerRepeated, Reason::BadPolygon);
  // 2.6: corners are "references to a valid vertex". Decision: checked (the
  // r6 host does not).
  for (int i = 0; i < n; ++i)
    if (vertices().count(v[i]) == 0) return refuse(Rule::PolygonCornerNoVertex, Reason::NoSuchVertex);

  std::uint32_t id = polygon_id;
  auto& base = layers_.at(kPolygonLayer).slots;
  if (id == kNone32) {
    auto free = lowest_free(base, std::uint32_t{0}, std::uint32_t{0xFFFFFFFE});
    if (!free) return refuse(Rule::PolygonNoFreeId, Reason::NoFreeId);
    id = *free;
    note(Rule::PolygonIdPick);
  }
  if (auto slot = base.find(id); slot != base.end()) {  // re-defining a live polygon
    note(Rule::PolygonRedefine);
    if (layers_in_stack(false) > 1) note(Rule::PolygonRedefineKeepsSlots);
    slot->second.u = v;
    slot->second.written = written(Rule::PolygonRedefine);
    touch_slot(kPolygonLayer, id);
    return Reason::Ok;
  }
  Slot value;
  value.u = v;
  return new_element(kPolygonLayer, id, value);
}

Reason Node::apply_one(const cmd::PolygonSetCornerUint32& c) {
  // README: "on layer 1 with v0 = 0xFFFFFFFF it means g_polygon_delete".
  if (c.layer_id == kPolygonLayer && c.v[0] == kNone32) {
    note(Rule::PolygonNoneCornerDeletes);
    return apply_one(cmd::PolygonDelete{c.polygon_id});
  }
  return set_corners(c.layer_id, c.polygon_id, c.v);
}

Reason Node::apply_one(const cmd::PolygonSetCornerReal64& c) {
  Slot* slot = nullptr;
  if (Reason r = find_slot(c.layer_id, LayerType::PolygonCornerReal, c.polygon_id, &slot); r != Reason::Ok)
    return r;
  note(Rule::SlotWriteReal64);
  std::copy(c.v.begin(), c.v.end(), slot->r.begin());
  slot->written = written(Rule::SlotWriteReal64);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::PolygonSetCornerReal32& c) {
  Slot* slot = nullptr;
  if (Reason r = find_slot(c.layer_id, LayerType::PolygonCornerReal, c.polygon_id, &slot); r != Reason::Ok)
    return r;
  note(Rule::SlotWriteReal32);
  for (int i = 0; i < 4; ++i) slot->r[i] = double(c.v[i]);
  slot->written = written(Rule::SlotWriteReal32);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::PolygonDelete& c) {
  if (polygons().count(c.polygon_id) == 0) return refuse(Rule::PolygonDeleteMissing, Reason::NoSuchPolygon);
  note(Rule::PolygonDelete);
  erase_element(false, c.polygon_id);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::PolygonSetFaceUint8& c) {
  Slot* slot = nullptr;
  if (Reason r = find_slot(c.layer_id, LayerType::PolygonFaceUint8, c.polygon_id, &slot); r != Reason::Ok)
    return r;
  note(Rule::SlotWriteUint);
  slot->u[0] = c.value;
  slot->written = written(Rule::SlotWriteUint);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::PolygonSetFaceUint32& c) {
  Slot* slot = nullptr;
  if (Reason r = find_slot(c.layer_id, LayerType::PolygonFaceUint32, c.polygon_id, &slot); r != Reason::Ok)
    return r;
  note(Rule::SlotWriteUint);
  slot->u[0] = c.value;
  slot->written = written(Rule::SlotWriteUint);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::PolygonSetFaceReal64& c) {
  Slot* slot = nullptr;
  if (Reason r = find_slot(c.layer_id, LayerType::PolygonFaceReal, c.polygon_id, &slot); r != Reason::Ok)
    return r;
  note(Rule::SlotWriteReal64);
  slot->r[0] = c.value;
  slot->written = written(Rule::SlotWriteReal64);
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::PolygonSetFaceReal32& c) {
  Slot* slot = nullptr;
  if (Reason r = find_slot(c.layer_id, LayerType::PolygonFaceReal, c.polygon_id, &slot); r != Reason::Ok)
    return r;
  note(Rule::SlotWriteReal32);
  slot->r[0] = double(c.value);
  slot->written = written(Rule::SlotWriteReal32);
  return Reason::Ok;
}

// ---- creases (2.6.2) -------------------------------------------------------

Rule Node::crease_rule(const std::string& layer, LayerType type, Rule constant, Rule named) const {
  if (layer.empty()) return constant;
  const Layer* l = find_layer_by_name(layer);
  return l && l->type == type ? named : Rule::CreaseLayerUnresolved;
}

Reason Node::apply_one(const cmd::CreaseSetVertex& c) {
  if (!valid_name(c.layer)) return refuse(Rule::CreaseNameInvalid, Reason::BadName);
  // Decision: the name is stored as sent and resolved whenever creases are
  // read (see geometry/crease.h): a layer may be created after it is named.
  if (c.layer.size() == kMaxNameBytes) note(Rule::CreaseNameLongest);
  const Rule rule = crease_rule(c.layer, LayerType::VertexUint32, Rule::CreaseVertexConstant, Rule::CreaseVertexLayer);
  note(rule);
  vertex_crease_ = {c.layer, c.def_crease, written(rule)};
  if (changes_) changes_->creases = true;
  return Reason::Ok;
}

Reason Node::apply_one(const cmd::CreaseSetEdge& c) {
  if (!valid_name(c.layer)) return refuse(Rule::CreaseNameInvalid, Reason::BadName);
  if (c.layer.size() == kMaxNameBytes) note(Rule::CreaseNameLongest);
  const Rule rule =
      crease_rule(c.layer, LayerType::PolygonCornerUint32, Rule::CreaseEdgeConstant, Rule::CreaseEdgeLayer);
  note(rule);
  edge_crease_ = {c.layer, c.def_crease, written(rule)};
  if (changes_) changes_->creases = true;
  return Reason::Ok;
}

// ---- bones (2.6.3) ---------------------------------------------------------

Reason Node::apply_one(const cmd::BoneCreate& c) {
  // README: "an empty weight name means g_bone_destroy(bone_id)".
  if (c.weight.empty()) {
    note(Rule::BoneEmptyWeightDestroys);
    return apply_one(cmd::BoneDestroy{c.bone_id});
  }
  const bool bad_name =
      !valid_name(c.weight) || !valid_name(c.reference) || !valid_name(c.pos_label) || !valid_name(c.rot_label);
  const bool bad_value = !all_finite(c.pos.data(), 3) || !all_finite(c.rot.data(), 4) ||
                         (c.rot[0] == 0 && c.rot[1] == 0 && c.rot[2] == 0 && c.rot[3] == 0);
  const Layer* w = find_layer_by_name(c.weight);
  const bool bad_weight = !w || (w->type != LayerType::VertexUint32 && w->type != LayerType::VertexReal);
  const Layer* ref = c.reference.empty() ? nullptr : find_layer_by_name(c.reference);
  const bool bad_reference = !c.reference.empty() && (!ref || ref->type != LayerType::VertexUint32);
  if (bad_name) {
    const Reason r = refuse(Rule::BoneNameInvalid, Reason::BadName);
    also_refusing({{Rule::BoneValueInvalid, bad_value},
                   {Rule::BoneWeightInvalid, bad_weight},
                   {Rule::BoneReferenceInvalid, bad_reference}});
    return r;
  }
  for (const std::string* s : {&c.weight, &c.reference, &c.pos_label, &c.rot_label})
    if (s->size() == kMaxNameBytes) note(Rule::BoneNameLongest);
  // Decision: position and rotation must be finite and the rotation
  // quaternion non-zero, so that every bone has a well-defined pose.
  // Decision: position and rotation must be finite and the rotation
  // quaternion non-zero, so that every bone has a well-defined pose.
  if (bad_value) {
    const Reason r = refuse(Rule::BoneValueInvalid, Reason::BadValue);
    also_refusing({{Rule::BoneWeightInvalid, bad_weight}, {Rule::BoneReferenceInvalid, bad_reference}});
    return r;
  }
  // 2.6.3: weight layers "must be of type VN_G_LAYER_VERTEX_UINT32 or
  // VN_G_LAYER_VERTEX_REAL". Decision: checked when the bone is created; a
  // later destroy or re-type of that layer is allowed (the bone keeps the name).
  if (bad_weight) {
    const Reason r = refuse(Rule::BoneWeightInvalid, Reason::BadWeightLayer);
    also_refusing({{Rule::BoneReferenceInvalid, bad_reference}});
    return r;
  }
  // 2.6.3: the reference field names "a VN_G_LAYER_VERTEX_UINT32 layer".
  if (bad_reference) return refuse(Rule::BoneReferenceInvalid, Reason::BadReferenceLayer);
  std::uint16_t id = c.bone_id;
  if (id == kNone16) {
    auto free = lowest_free(bones_, std::uint16_t{0}, std::uint16_t{0xFFFE});
    if (!free) return refuse(Rule::BoneNoFreeId, Reason::NoFreeId);
    id = *free;
  }
  // 2.6.3: "The parent link defines hierarchies of bones", and a parent
  // that does not exist makes a root. Decision: links are by id, resolved
  // when read, and a link that would make a bone its own ancestor is
  // rejected, so the bones always form a forest. Before this command there
  // is no cycle, so any new one passes through `id`: walk up from it.
  std::set<std::uint16_t> seen{id};
  for (std::uint16_t p = c.parent;;) {
    if (seen.count(p)) return refuse(Rule::BoneCycle, Reason::BoneCycle);
    auto it = bones_.find(p);
    if (it == bones_.end()) break;  // a missing parent: the chain ends at a root
    seen.insert(p);
    p = it->second.parent;
  }
  if (c.bone_id == kNone16) note(Rule::BoneIdPick);
  note(Rule::BoneCreate);
  Bone& b = bones_[id] = bone_from_command(c, id);
  b.written = written(Rule::BoneCreate);
  if (changes_) changes_->bones.push_back(id);
  return Reason::Ok;
}

Bone bone_from_command(const cmd::BoneCreate& c, std::uint16_t id) {
  Bone b;
  b.id = id;
  b.weight = c.weight;
  b.reference = c.reference;
  b.parent = c.parent;
  b.pos = c.pos;
  b.pos_label = c.pos_label;
  b.rot = c.rot;
  b.rot_label = c.rot_label;
  return b;
}

Reason Node::apply_one(const cmd::BoneDestroy& c) {
  // Decision: destroying a bone leaves its children's parent links as they
  // are: they are roots until a bone with that id exists again.
  if (bones_.erase(c.bone_id) == 0) return refuse(Rule::BoneDestroyMissing, Reason::NoSuchBone);
  if (changes_) changes_->bones.push_back(c.bone_id);
  note(Rule::BoneDestroy);
  return Reason::Ok;
}

}  // namespace vgc
