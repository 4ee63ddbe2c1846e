// node_invariants.cpp — see node_invariants.h.
#include "node_invariants.h"

#include <cmath>
#include <cstring>
#include <set>
#include <string_view>

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

std::string check_state(const std::map<std::uint16_t, Layer>& layers,
                        const std::map<std::uint16_t, Bone>& bones) {
  // 2.6.1: the two base layers, rigidly defined.
  if (auto e = check_base_layer(layers, Node::kVertexLayer, "vertex", LayerType::VertexXyz); !e.empty()) return e;
  if (auto e = check_base_layer(layers, Node::kPolygonLayer, "polygon", LayerType::PolygonCornerUint32); !e.empty())
    return e;
  const auto& vertices = layers.at(Node::kVertexLayer).slots;
  const auto& polygons = layers.at(Node::kPolygonLayer).slots;

  std::set<std::string_view> names;
  for (const auto& [id, layer] : layers) {
    auto where = [&, id = id] { return "layer " + id_text(id); };
    if (layer.id != id) return where() + " is stored under id " + id_text(layer.id);
    if (!is_layer_type(static_cast<std::uint8_t>(layer.type))) return where() + " has no valid type";
    // README: names of at most 15 visible bytes; decision: unique, non-empty.
    if (layer.name.empty()) return where() + " has an empty name";
    if (!valid_name(layer.name)) return where() + " has a name over 15 bytes or with a NUL";
    if (!names.insert(layer.name).second) return where() + " repeats the name \"" + layer.name + "\"";
    // 2.6.1: a layer's size "is controlled by the size of the base layer".
    const auto& base = is_vertex_layer_type(layer.type) ? vertices : polygons;
    if (!same_ids(layer.slots, base)) return where() + " does not hold exactly the live ids of its base layer";
  }
  for (const auto& [vid, slot] : vertices)
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(slot.r[i])) return "vertex " + id_text(vid) + " has a non-finite position";
  // 2.6: three or four corners, pairwise distinct, each a live vertex.
  for (const auto& [pid, slot] : polygons) {
    auto where = [&, pid = pid] { return "polygon " + id_text(pid); };
    for (int i = 0; i < 3; ++i)
      if (slot.u[i] == kNone32) return where() + " has an unused corner " + id_text(i);
    const int n = slot.u[3] == kNone32 ? 3 : 4;
    for (int i = 0; i < n; ++i) {
      if (vertices.count(slot.u[i]) == 0) return where() + " names vertex " + id_text(slot.u[i]) + ", not live";
      for (int j = i + 1; j < n; ++j)
        if (slot.u[i] == slot.u[j]) return where() + " repeats vertex " + id_text(slot.u[i]);
    }
  }
  // 2.6.3: bones form a forest (no bone is its own ancestor); names valid.
  for (const auto& [id, bone] : bones) {
    auto where = [&, id = id] { return "bone " + id_text(id); };
    if (bone.id != id) return where() + " is stored under id " + id_text(bone.id);
    if (bone.weight.empty()) return where() + " has an empty weight layer name";
    for (const std::string* s : {&bone.weight, &bone.reference, &bone.pos_label, &bone.rot_label})
      if (!valid_name(*s)) return where() + " has a name over 15 bytes or with a NUL";
    // A walk longer than the number of bones has met a cycle.
    std::size_t steps = 0;
    for (std::uint16_t p = bone.parent;;) {
      auto it = bones.find(p);
      if (it == bones.end()) break;
      if (p == id || ++steps > bones.size()) return where() + " is in a parent cycle";
      p = it->second.parent;
    }
  }
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
};

}  // namespace

std::uint64_t state_digest(const Node& node) {
  Digest d;
  d.add(node.layers().size());
  for (const auto& [id, layer] : node.layers()) {
    d.add(id);
    d.add(layer.name);
    d.add(layer.type);
    d.add(layer.def_uint);
    d.add(layer.def_real);  // bits: -0.0 and NaN payloads count
    d.add(layer.subscription ? static_cast<int>(*layer.subscription) : -1);
    d.add(layer.slots.size());
    for (const auto& [element, slot] : layer.slots) {
      d.word(element);
      d.bytes(slot.u.data(), sizeof slot.u);  // 16 bytes: two words
      d.bytes(slot.r.data(), sizeof slot.r);  // 32 bytes: four words
    }
  }
  d.add(node.vertex_crease().layer);
  d.add(node.vertex_crease().def_crease);
  d.add(node.edge_crease().layer);
  d.add(node.edge_crease().def_crease);
  d.add(node.bones().size());
  for (const auto& [id, b] : node.bones()) {
    d.add(id);
    d.add(b.weight);
    d.add(b.reference);
    d.add(b.parent);
    d.bytes(b.pos.data(), sizeof b.pos);
    d.add(b.pos_label);
    d.bytes(b.rot.data(), sizeof b.rot);
    d.add(b.rot_label);
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

}  // namespace vgc::fuzz
