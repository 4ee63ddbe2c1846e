// node_invariants.cpp — see node_invariants.h.
#include "node_invariants.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>
#include <type_traits>

namespace vgc::fuzz {
namespace {

std::string id_text(std::uint32_t v) { return std::to_string(v); }

bool valid_name(const std::string& s) {
  return s.size() <= kMaxNameBytes && s.find('\0') == std::string::npos;
}

// Keys of one slot map, for comparing a layer with its base layer.
bool same_ids(const std::map<std::uint32_t, Slot>& a, const std::map<std::uint32_t, Slot>& b) {
  if (a.size() != b.size()) return false;
  for (auto i = a.begin(), j = b.begin(); i != a.end(); ++i, ++j)
    if (i->first != j->first) return false;
  return true;
}

std::string check_base_layer(const std::map<std::uint16_t, Layer>& layers, std::uint16_t id,
                             const char* name, LayerType type) {
  auto it = layers.find(id);
  if (it == layers.end()) return "base layer " + id_text(id) + " is missing";
  if (it->second.name != name)
    return "base layer " + id_text(id) + " is named \"" + it->second.name + "\", not \"" + name + "\"";
  if (it->second.type != type) return "base layer " + id_text(id) + " has the wrong type";
  return {};
}

}  // namespace

namespace {
std::string check_bone(const std::map<std::uint16_t, Bone>& bones, std::uint16_t id);  // below
std::string check_polygon(const std::map<std::uint32_t, Slot>& vertices, std::uint32_t pid,
                          const Slot& slot);  // below

// The layer names seen so far in one check, in id order: a linear scan of
// a vector kept between calls (a node holds tens of layers; a std::set
// here was a seventh of a fuzz_stream run, an allocation per layer per
// command). Cleared on each call.
std::vector<std::string_view>& names_seen() {
  thread_local std::vector<std::string_view> names;
  names.clear();
  return names;
}
bool seen_before(std::vector<std::string_view>& seen, std::string_view name) {
  if (std::find(seen.begin(), seen.end(), name) != seen.end()) return true;
  seen.push_back(name);
  return false;
}
}  // namespace

namespace {
// The layer-level rules, O(layers) each: the base layers; every layer's
// id, type and name; its slots against its base layer's, id by id
// (`exact`) or by count (the cheap form check_touched uses after each
// command, with the ids of what the command touched checked apart).
std::string check_layer_list(const std::map<std::uint16_t, Layer>& layers, bool exact) {
  // 2.6.1: the two base layers, rigidly defined.
  if (auto e = check_base_layer(layers, Node::kVertexLayer, "vertex", LayerType::VertexXyz); !e.empty()) return e;
  if (auto e = check_base_layer(layers, Node::kPolygonLayer, "polygon", LayerType::PolygonCornerUint32); !e.empty())
    return e;
  const auto& vertices = layers.at(Node::kVertexLayer).slots;
  const auto& polygons = layers.at(Node::kPolygonLayer).slots;
  std::vector<std::string_view>& names = names_seen();
  for (const auto& [id, layer] : layers) {
    auto where = [&, id = id] { return "layer " + id_text(id); };
    if (layer.id != id) return where() + " is stored under id " + id_text(layer.id);
    if (!is_layer_type(static_cast<std::uint8_t>(layer.type))) return where() + " has no valid type";
    // README: names of at most 15 visible bytes; decision: unique, non-empty.
    if (layer.name.empty()) return where() + " has an empty name";
    if (!valid_name(layer.name)) return where() + " has a name over 15 bytes or with a NUL";
    if (seen_before(names, layer.name)) return where() + " repeats the name \"" + layer.name + "\"";
    // 2.6.1: a layer's size "is controlled by the size of the base layer".
    const auto& base = is_vertex_layer_type(layer.type) ? vertices : polygons;
    if (exact ? !same_ids(layer.slots, base) : layer.slots.size() != base.size())
      return where() + " does not hold exactly the live ids of its base layer";
  }
  return {};
}
}  // namespace

std::string check_state(const std::map<std::uint16_t, Layer>& layers,
                        const std::map<std::uint16_t, Bone>& bones) {
  if (auto e = check_layer_list(layers, true); !e.empty()) return e;
  const auto& vertices = layers.at(Node::kVertexLayer).slots;
  const auto& polygons = layers.at(Node::kPolygonLayer).slots;
  for (const auto& [vid, slot] : vertices)
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(slot.r[i])) return "vertex " + id_text(vid) + " has a non-finite position";
  // 2.6: three or four corners, pairwise distinct, each a live vertex.
  for (const auto& [pid, slot] : polygons)
    if (auto e = check_polygon(vertices, pid, slot); !e.empty()) return e;
  // 2.6.3: bones form a forest (no bone is its own ancestor); names valid.
  for (const auto& entry : bones)
    if (std::string e = check_bone(bones, entry.first); !e.empty()) return e;
  return {};
}

namespace {

// A multiply-xorshift hash over 64-bit words (a short tail padded, its
// length mixed in);
// every variable-length value is preceded by its length so that fields
// cannot run into each other. Word-wise because the digest runs after every
// command over every slot: byte-wise FNV was a third of fuzz_stream's time.
struct Digest {
  std::uint64_t h = 0xcbf29ce484222325ull;
  void word(std::uint64_t w) {
    h = (h ^ w) * 0x9E3779B97F4A7C15ull;
    h ^= h >> 29;
  }
  void bytes(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (; n >= 8; n -= 8, b += 8) {
      std::uint64_t w;
      std::memcpy(&w, b, 8);
      word(w);
    }
    if (n == 0) return;
    std::uint64_t tail = 0;
    std::memcpy(&tail, b, n);
    word(tail ^ (std::uint64_t{n} << 56));
  }
  template <class T> void add(const T& v) { bytes(&v, sizeof v); }
  void add(const std::string& s) {
    add(s.size());
    bytes(s.data(), s.size());
  }
  // Every field a bone_create sets (its id is the map key, added by the caller).
  void add(const Bone& b) {
    add(b.weight);
    add(b.reference);
    add(b.parent);
    bytes(b.pos.data(), sizeof b.pos);
    add(b.pos_label);
    bytes(b.rot.data(), sizeof b.rot);
    add(b.rot_label);
  }
  // What both digests take of every layer, whatever was touched: its id,
  // name, type, defaults (bits: -0.0 and NaN payloads count), subscription
  // and slot count.
  void layer_header(std::uint16_t id, const Layer& layer) {
    add(id);
    add(layer.name);
    add(layer.type);
    add(layer.def_uint);
    add(layer.def_real);
    add(layer.subscription ? static_cast<int>(*layer.subscription) : -1);
    add(layer.slots.size());
  }
  // One slot's values: 16 bytes of unsigned words, 32 of reals.
  void slot(const Slot& s) {
    bytes(s.u.data(), sizeof s.u);
    bytes(s.r.data(), sizeof s.r);
  }
  void all_slots(const Layer& layer) {
    for (const auto& [element, s] : layer.slots) {
      word(element);
      slot(s);
    }
  }
  // The crease settings and the bone count.
  void creases_and_bone_count(const Node& node) {
    add(node.vertex_crease().layer);
    add(node.vertex_crease().def_crease);
    add(node.edge_crease().layer);
    add(node.edge_crease().def_crease);
    add(node.bones().size());
  }
};

}  // namespace

std::uint64_t state_digest(const Node& node) {
  Digest d;
  d.add(node.layers().size());
  for (const auto& [id, layer] : node.layers()) {
    d.layer_header(id, layer);
    d.all_slots(layer);
  }
  d.creases_and_bone_count(node);
  for (const auto& [id, b] : node.bones()) {
    d.add(id);
    d.add(b);
  }
  return d.h;
}

std::string check_step(bool applied, std::uint64_t before, std::uint64_t after) {
  if (!applied && before != after) return "a rejected command changed the node's state";
  return {};
}

std::string check_step(bool applied, const std::string& before, const std::string& after) {
  if (!applied && before != after) return "a rejected command changed the snapshot";
  return {};
}

std::string check_deterministic(const std::string& first, const std::string& second) {
  if (first != second) return "print_snapshot is not deterministic";
  return {};
}

namespace {

// The layer-level rules of check_state, with slot counts for slot ids.
std::string check_layer_headers(const std::map<std::uint16_t, Layer>& layers) {
  return check_layer_list(layers, false);
}

std::string check_polygon(const std::map<std::uint32_t, Slot>& vertices, std::uint32_t pid, const Slot& slot) {
  auto where = [&] { return "polygon " + id_text(pid); };
  for (int i = 0; i < 3; ++i)
    if (slot.u[i] == kNone32) return where() + " has an unused corner " + id_text(i);
  const int n = slot.u[3] == kNone32 ? 3 : 4;
  for (int i = 0; i < n; ++i) {
    if (vertices.count(slot.u[i]) == 0) return where() + " names vertex " + id_text(slot.u[i]) + ", not live";
    for (int j = i + 1; j < n; ++j)
      if (slot.u[i] == slot.u[j]) return where() + " repeats vertex " + id_text(slot.u[i]);
  }
  return {};
}

// Element `e` of one stack: in every layer of the stack exactly when live.
std::string check_element(const std::map<std::uint16_t, Layer>& layers, bool vertex_stack, std::uint32_t e) {
  const auto& base = layers.at(vertex_stack ? Node::kVertexLayer : Node::kPolygonLayer).slots;
  const bool live = base.count(e) > 0;
  for (const auto& [id, layer] : layers)
    if (is_vertex_layer_type(layer.type) == vertex_stack && (layer.slots.count(e) > 0) != live)
      return "layer " + id_text(id) + " does not hold exactly the live ids of its base layer";
  if (!live) return {};
  const Slot& slot = base.at(e);
  if (vertex_stack) {
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(slot.r[i])) return "vertex " + id_text(e) + " has a non-finite position";
    return {};
  }
  return check_polygon(layers.at(Node::kVertexLayer).slots, e, slot);
}

std::string check_bone(const std::map<std::uint16_t, Bone>& bones, std::uint16_t id) {
  auto it = bones.find(id);
  if (it == bones.end()) return {};
  const Bone& bone = it->second;
  auto where = [&] { return "bone " + id_text(id); };
  if (bone.id != id) return where() + " is stored under id " + id_text(bone.id);
  if (bone.weight.empty()) return where() + " has an empty weight layer name";
  for (const std::string* s : {&bone.weight, &bone.reference, &bone.pos_label, &bone.rot_label})
    if (!valid_name(*s)) return where() + " has a name over 15 bytes or with a NUL";
  std::size_t steps = 0;
  for (std::uint16_t p = bone.parent;;) {
    auto pit = bones.find(p);
    if (pit == bones.end()) break;
    if (p == id || ++steps > bones.size()) return where() + " is in a parent cycle";
    p = pit->second.parent;
  }
  return {};
}

template <class T, class = void> struct has_vertex_id : std::false_type {};
template <class T> struct has_vertex_id<T, std::void_t<decltype(T::vertex_id)>> : std::true_type {};
template <class T, class = void> struct has_polygon_id : std::false_type {};
template <class T> struct has_polygon_id<T, std::void_t<decltype(T::polygon_id)>> : std::true_type {};

}  // namespace

Touched touched_by(const Command& command) {
  Touched t;
  std::visit(
      [&t](const auto& c) {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, cmd::LayerCreate> || std::is_same_v<T, cmd::LayerDestroy> ||
                      std::is_same_v<T, cmd::LayerSubscribe> || std::is_same_v<T, cmd::LayerUnsubscribe>) {
          if (c.layer_id == kNone16) t.whole_state = true;
          t.layers.push_back(c.layer_id);
        } else if constexpr (std::is_same_v<T, cmd::VertexDelete>) {
          t.vertices.push_back(c.vertex_id);
          t.vertex_delete = true;
        } else if constexpr (std::is_same_v<T, cmd::PolygonDelete>) {
          t.polygons.push_back(c.polygon_id);
        } else if constexpr (has_vertex_id<T>::value) {
          if (c.vertex_id == kNone32) t.whole_state = true;
          t.vertices.push_back(c.vertex_id);
          t.vertex_delete = true;  // the xyz forms with the max sentinel delete
        } else if constexpr (has_polygon_id<T>::value) {
          if (c.polygon_id == kNone32) t.whole_state = true;
          t.polygons.push_back(c.polygon_id);
        } else if constexpr (std::is_same_v<T, cmd::BoneCreate> || std::is_same_v<T, cmd::BoneDestroy>) {
          if (c.bone_id == kNone16) t.whole_state = true;
          t.bones.push_back(c.bone_id);
        }
        // Crease settings: not part of check_state; in every touched_digest.
      },
      command);
  return t;
}

std::string check_touched(const std::map<std::uint16_t, Layer>& layers, const std::map<std::uint16_t, Bone>& bones,
                          const Touched& t) {
  if (t.whole_state) return check_state(layers, bones);
  if (auto e = check_layer_headers(layers); !e.empty()) return e;
  const auto& vertices = layers.at(Node::kVertexLayer).slots;
  for (std::uint16_t id : t.layers) {
    auto it = layers.find(id);
    if (it == layers.end()) continue;
    const auto& base = is_vertex_layer_type(it->second.type) ? vertices : layers.at(Node::kPolygonLayer).slots;
    if (!same_ids(it->second.slots, base))
      return "layer " + id_text(id) + " does not hold exactly the live ids of its base layer";
  }
  for (std::uint32_t v : t.vertices)
    if (auto e = check_element(layers, true, v); !e.empty()) return e;
  for (std::uint32_t p : t.polygons)
    if (auto e = check_element(layers, false, p); !e.empty()) return e;
  if (t.vertex_delete)
    for (std::uint32_t v : t.vertices)
      if (vertices.count(v) == 0)
        for (const auto& [pid, slot] : layers.at(Node::kPolygonLayer).slots)
          if (std::find(slot.u.begin(), slot.u.end(), v) != slot.u.end())
            return check_polygon(vertices, pid, slot);
  for (std::uint16_t b : t.bones)
    if (auto e = check_bone(bones, b); !e.empty()) return e;
  return {};
}

std::uint64_t touched_digest(const Node& node, const Touched& t) {
  if (t.whole_state) return state_digest(node);
  Digest d;
  d.add(node.layers().size());
  for (const auto& [id, layer] : node.layers()) {
    d.layer_header(id, layer);
    const bool vertex_stack = is_vertex_layer_type(layer.type);
    for (std::uint32_t e : vertex_stack ? t.vertices : t.polygons) {
      auto it = layer.slots.find(e);
      d.word(it == layer.slots.end() ? 0 : 1);
      if (it == layer.slots.end()) continue;
      d.slot(it->second);
    }
    if (std::find(t.layers.begin(), t.layers.end(), id) != t.layers.end()) d.all_slots(layer);
  }
  d.creases_and_bone_count(node);
  for (std::uint16_t b : t.bones) {
    auto it = node.bones().find(b);
    d.word(it == node.bones().end() ? 0 : 1);
    if (it == node.bones().end()) continue;
    d.add(it->second);
  }
  return d.h;
}

}  // namespace vgc::fuzz
