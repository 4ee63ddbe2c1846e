// verse_node_mirror.cpp — see verse_node_mirror.h.
#include "verse_node_mirror.h"

#include <cfloat>
#include <cmath>
#include <set>

#include "command_text.h"
#include "snapshot.h"

namespace vgc {
namespace {

bool is_vertex_stack(LayerType t) { return is_vertex_layer_type(t); }

std::string what(const Command& c) { return "`" + print_command(c) + "`"; }

}  // namespace

void VerseNodeMirror::clear() {
  layers_.clear();
  vertex_crease_ = {};
  edge_crease_ = {};
  bones_.clear();
}

std::size_t VerseNodeMirror::cells() const {
  std::size_t n = 0;
  for (const auto& [id, layer] : layers_) n += layer.slots.size();
  return n;
}

bool VerseNodeMirror::new_element(bool vertex_stack, std::uint32_t id, std::string* error) {
  std::size_t stack_layers = 0;
  for (const auto& [lid, layer] : layers_) stack_layers += is_vertex_stack(layer.type) == vertex_stack;
  if (cells() + stack_layers > max_cells_) {
    *error = "the host sent more state than vgc keeps (" + std::to_string(max_cells_) + " layer slots)";
    return false;
  }
  for (auto& [lid, layer] : layers_)
    if (is_vertex_stack(layer.type) == vertex_stack && !layer.slots.count(id)) layer.slots[id] = default_slot(layer);
  return true;
}

void VerseNodeMirror::erase_element(bool vertex_stack, std::uint32_t id) {
  for (auto& [lid, layer] : layers_)
    if (is_vertex_stack(layer.type) == vertex_stack) layer.slots.erase(id);
}

// The slot of `element` in `layer_id`, made (holding the layer's default)
// when the host writes a value for an element it never made live: the
// snapshot then shows that slot, and the suite judges it.
Slot* VerseNodeMirror::slot(std::uint16_t layer_id, std::uint32_t element, std::string* error, bool* ok) {
  *ok = false;
  auto it = layers_.find(layer_id);
  if (it == layers_.end()) {
    *error = "the host sent a value for layer " + std::to_string(layer_id) + ", which it never announced";
    return nullptr;
  }
  auto s = it->second.slots.find(element);
  if (s == it->second.slots.end()) {
    if (cells() + 1 > max_cells_) {
      *error = "the host sent more state than vgc keeps (" + std::to_string(max_cells_) + " layer slots)";
      return nullptr;
    }
    s = it->second.slots.emplace(element, default_slot(it->second)).first;
  }
  *ok = true;
  return &s->second;
}

bool VerseNodeMirror::set_xyz(std::uint16_t layer_id, std::uint32_t id, double x, double y, double z,
                              std::string* error) {
  if (layer_id == Node::kVertexLayer) {
    auto base = layers_.find(Node::kVertexLayer);
    if (base != layers_.end() && !base->second.slots.count(id) && !new_element(true, id, error)) return false;
  }
  bool ok = false;
  Slot* s = slot(layer_id, id, error, &ok);
  if (!ok) return false;
  s->r[0] = x, s->r[1] = y, s->r[2] = z;
  return true;
}

// Each command a host sends is one statement of fact, applied by its own
// step (apply_one, one per kind, as reference/node/node.cpp's): a kind
// without one does not compile.
bool VerseNodeMirror::apply(const Command& sent, std::string* error) {
  return std::visit([&](const auto& c) { return apply_one(c, error); }, sent);
}

// A value command must name a layer of the type it writes (a layer the host
// never announced is left to slot(), which says so).
bool VerseNodeMirror::typed(std::uint16_t layer_id, LayerType type, const Command& sent, std::string* error) const {
  auto it = layers_.find(layer_id);
  if (it != layers_.end() && it->second.type != type) {
    *error = "the host sent " + what(sent) + " for layer " + std::to_string(layer_id) + ", which it announced as " +
             std::string(layer_type_name(static_cast<std::uint8_t>(it->second.type)));
    return false;
  }
  return true;
}

// The first value of `element` in a uint layer (2.6.1: vertex_set_uint32,
// polygon_set_face_uint8 / _uint32).
bool VerseNodeMirror::set_uint(const Command& sent, std::uint16_t layer_id, LayerType type, std::uint32_t element,
                               std::uint32_t value, std::string* error) {
  if (!typed(layer_id, type, sent, error)) return false;
  bool ok = false;
  Slot* s = slot(layer_id, element, error, &ok);
  if (ok) s->u[0] = value;
  return ok;
}

// The first value of `element` in a real layer (2.6.1: vertex_set_real*,
// polygon_set_face_real*).
bool VerseNodeMirror::set_real(const Command& sent, std::uint16_t layer_id, LayerType type, std::uint32_t element,
                               double value, std::string* error) {
  if (!typed(layer_id, type, sent, error)) return false;
  bool ok = false;
  Slot* s = slot(layer_id, element, error, &ok);
  if (ok) s->r[0] = value;
  return ok;
}

// The four corner values of `polygon` in a POLYGON_CORNER_REAL layer.
bool VerseNodeMirror::set_corner_reals(const Command& sent, std::uint16_t layer_id, std::uint32_t polygon,
                                       const std::array<double, 4>& v, std::string* error) {
  if (!typed(layer_id, LayerType::PolygonCornerReal, sent, error)) return false;
  bool ok = false;
  Slot* s = slot(layer_id, polygon, error, &ok);
  if (ok)
    for (int i = 0; i < 4; ++i) s->r[i] = v[i];
  return ok;
}

// A layer announced for the first time, or with a new type: one slot per
// live element of its stack (the base layer's slots), holding the default,
// until the host sends values (2.6.1: a new slot takes the layer's default).
bool VerseNodeMirror::add_layer(const cmd::LayerCreate& c, LayerType type, std::string* error) {
  Layer layer;
  layer.id = c.layer_id;
  layer.name = c.name;
  layer.type = type;
  layer.def_uint = c.def_uint;
  layer.def_real = c.def_real;
  const std::uint16_t base_id = is_vertex_stack(type) ? Node::kVertexLayer : Node::kPolygonLayer;
  if (c.layer_id != base_id) {
    if (auto base = layers_.find(base_id); base != layers_.end()) {
      if (cells() + base->second.slots.size() > max_cells_) {
        *error = "the host sent more state than vgc keeps (" + std::to_string(max_cells_) + " layer slots)";
        return false;
      }
      const Slot fresh = default_slot(layer);
      for (const auto& [element, unused] : base->second.slots) layer.slots.emplace(element, fresh);
    }
  }
  layers_[c.layer_id] = std::move(layer);
  return true;
}

// layer_create: the wire's layer_destroy when the name is empty; a known
// layer of the same type renamed (or announced again) keeps its slots;
// otherwise a new layer (add_layer).
bool VerseNodeMirror::apply_one(const cmd::LayerCreate& c, std::string* error) {
  if (c.name.empty()) return apply_one(cmd::LayerDestroy{c.layer_id}, error);
  if (!is_layer_type(c.type)) {
    *error = "the host announced layer " + std::to_string(c.layer_id) + " with type byte " + std::to_string(c.type) +
             ", which is no layer type";
    return false;
  }
  auto it = layers_.find(c.layer_id);
  const LayerType type = static_cast<LayerType>(c.type);
  if (it != layers_.end() && it->second.type == type) {  // renamed, or announced again
    it->second.name = c.name;
    it->second.def_uint = c.def_uint;
    it->second.def_real = c.def_real;
    return true;
  }
  return add_layer(c, type, error);
}

bool VerseNodeMirror::apply_one(const cmd::LayerDestroy& c, std::string*) {
  layers_.erase(c.layer_id);
  return true;
}

// Subscription state is the sender's own; a host broadcasts none.
bool VerseNodeMirror::apply_one(const cmd::LayerSubscribe&, std::string*) { return true; }
bool VerseNodeMirror::apply_one(const cmd::LayerUnsubscribe&, std::string*) { return true; }

// vertex_set_xyz_real32: a coordinate FLT_MAX is the vertex_delete alias
// (docs/spec_facts.md section 4).
bool VerseNodeMirror::apply_one(const cmd::VertexSetXyzReal32& c, std::string* error) {
  if (c.x == FLT_MAX || c.y == FLT_MAX || c.z == FLT_MAX) return apply_one(cmd::VertexDelete{c.vertex_id}, error);
  return typed(c.layer_id, LayerType::VertexXyz, c, error) && set_xyz(c.layer_id, c.vertex_id, c.x, c.y, c.z, error);
}

// vertex_set_xyz_real64: a coordinate DBL_MAX is the vertex_delete alias.
bool VerseNodeMirror::apply_one(const cmd::VertexSetXyzReal64& c, std::string* error) {
  if (c.x == DBL_MAX || c.y == DBL_MAX || c.z == DBL_MAX) return apply_one(cmd::VertexDelete{c.vertex_id}, error);
  return typed(c.layer_id, LayerType::VertexXyz, c, error) && set_xyz(c.layer_id, c.vertex_id, c.x, c.y, c.z, error);
}

// A deleted vertex leaves its stack and nothing else: a host that also
// removes the polygons using it says so with polygon deletes.
bool VerseNodeMirror::apply_one(const cmd::VertexDelete& c, std::string*) {
  erase_element(true, c.vertex_id);
  return true;
}

bool VerseNodeMirror::apply_one(const cmd::VertexSetUint32& c, std::string* error) {
  return set_uint(c, c.layer_id, LayerType::VertexUint32, c.vertex_id, c.value, error);
}
bool VerseNodeMirror::apply_one(const cmd::VertexSetReal64& c, std::string* error) {
  return set_real(c, c.layer_id, LayerType::VertexReal, c.vertex_id, c.value, error);
}
bool VerseNodeMirror::apply_one(const cmd::VertexSetReal32& c, std::string* error) {
  return set_real(c, c.layer_id, LayerType::VertexReal, c.vertex_id, double(c.value), error);
}

// polygon_set_corner_uint32: on layer 1 a first corner 0xFFFFFFFF is the
// polygon_delete alias, and any other write there makes the polygon live.
bool VerseNodeMirror::apply_one(const cmd::PolygonSetCornerUint32& c, std::string* error) {
  if (c.layer_id == Node::kPolygonLayer && c.v[0] == kNone32) return apply_one(cmd::PolygonDelete{c.polygon_id}, error);
  if (!typed(c.layer_id, LayerType::PolygonCornerUint32, c, error)) return false;
  if (c.layer_id == Node::kPolygonLayer) {
    auto base = layers_.find(Node::kPolygonLayer);
    if (base != layers_.end() && !base->second.slots.count(c.polygon_id) && !new_element(false, c.polygon_id, error))
      return false;
  }
  bool ok = false;
  Slot* s = slot(c.layer_id, c.polygon_id, error, &ok);
  if (ok) s->u = c.v;
  return ok;
}

bool VerseNodeMirror::apply_one(const cmd::PolygonSetCornerReal64& c, std::string* error) {
  return set_corner_reals(c, c.layer_id, c.polygon_id, c.v, error);
}
bool VerseNodeMirror::apply_one(const cmd::PolygonSetCornerReal32& c, std::string* error) {
  return set_corner_reals(c, c.layer_id, c.polygon_id, {double(c.v[0]), double(c.v[1]), double(c.v[2]), double(c.v[3])},
                          error);
}

// A deleted polygon leaves its stack.
bool VerseNodeMirror::apply_one(const cmd::PolygonDelete& c, std::string*) {
  erase_element(false, c.polygon_id);
  return true;
}

bool VerseNodeMirror::apply_one(const cmd::PolygonSetFaceUint8& c, std::string* error) {
  return set_uint(c, c.layer_id, LayerType::PolygonFaceUint8, c.polygon_id, c.value, error);
}
bool VerseNodeMirror::apply_one(const cmd::PolygonSetFaceUint32& c, std::string* error) {
  return set_uint(c, c.layer_id, LayerType::PolygonFaceUint32, c.polygon_id, c.value, error);
}
bool VerseNodeMirror::apply_one(const cmd::PolygonSetFaceReal64& c, std::string* error) {
  return set_real(c, c.layer_id, LayerType::PolygonFaceReal, c.polygon_id, c.value, error);
}
bool VerseNodeMirror::apply_one(const cmd::PolygonSetFaceReal32& c, std::string* error) {
  return set_real(c, c.layer_id, LayerType::PolygonFaceReal, c.polygon_id, double(c.value), error);
}

// The crease settings (2.6.2), taken as sent.
bool VerseNodeMirror::apply_one(const cmd::CreaseSetVertex& c, std::string*) {
  vertex_crease_ = CreaseSetting{c.layer, c.def_crease};
  return true;
}
bool VerseNodeMirror::apply_one(const cmd::CreaseSetEdge& c, std::string*) {
  edge_crease_ = CreaseSetting{c.layer, c.def_crease};
  return true;
}

// bone_create (2.6.3): the wire's bone_destroy when the weight name is empty.
bool VerseNodeMirror::apply_one(const cmd::BoneCreate& c, std::string* error) {
  if (c.weight.empty()) return apply_one(cmd::BoneDestroy{c.bone_id}, error);
  bones_[c.bone_id] = bone_from_command(c, c.bone_id);
  return true;
}
bool VerseNodeMirror::apply_one(const cmd::BoneDestroy& c, std::string*) {
  bones_.erase(c.bone_id);
  return true;
}

void VerseNodeMirror::take_real32_differences(const VerseNodeMirror& real32) {
  const auto same = [](double v64, double v32) {
    const double rounded = static_cast<double>(static_cast<float>(v64));
    return (std::isnan(rounded) && std::isnan(v32)) || rounded == v32;
  };
  // A vertex with a coordinate that rounds to FLT_MAX in some XYZ layer
  // cannot be sent to a REAL32 subscriber: its real32 form is the
  // vertex_delete alias (docs/spec_facts.md section 4), which the REAL32
  // view then applied to the whole vertex. Such vertices keep this view's.
  std::set<std::uint32_t> unsendable;
  for (const auto& [lid, layer] : layers_)
    if (layer.type == LayerType::VertexXyz)
      for (const auto& [e, slot] : layer.slots)
        for (int i = 0; i < 3; ++i)
          if (static_cast<float>(slot.r[i]) == FLT_MAX) unsendable.insert(e);
  for (auto& [lid, layer] : layers_) {
    const bool vertex_stack = is_vertex_stack(layer.type);
    const auto skip = [&](std::uint32_t e) { return vertex_stack && unsendable.count(e) > 0; };
    const auto other = real32.layers_.find(lid);
    if (other == real32.layers_.end() || other->second.type != layer.type) continue;
    int components = 0;
    switch (layer.type) {
      case LayerType::VertexXyz: components = 3; break;
      case LayerType::VertexReal: case LayerType::PolygonFaceReal: components = 1; break;
      case LayerType::PolygonCornerReal: components = 4; break;
      default: continue;  // no real values: both views hold the same
    }
    for (auto it = layer.slots.begin(); it != layer.slots.end();) {
      if (skip(it->first)) {
        ++it;
        continue;
      }
      const auto o = other->second.slots.find(it->first);
      if (o == other->second.slots.end()) {
        it = layer.slots.erase(it);
        continue;
      }
      for (int i = 0; i < components; ++i)
        if (!same(it->second.r[i], o->second.r[i])) {
          it->second = o->second;
          break;
        }
      ++it;
    }
    for (const auto& [e, slot] : other->second.slots)
      if (!layer.slots.count(e) && !skip(e)) layer.slots[e] = slot;
  }
}

std::string VerseNodeMirror::snapshot() const {
  return print_snapshot(SnapshotParts{layers_, vertex_crease_, edge_crease_, bones_});
}

}  // namespace vgc
