// document_digest.cpp — see document_digest.h.
#include "document_digest.h"

#include <cstdio>

#include "derived_document.h"
#include "snapshot.h"

namespace vgc {
namespace {

// Identities: kind in the top byte, then a 16-bit and a 32-bit id, so that
// the slots of one layer are one range of keys.
enum Kind : std::uint64_t { kLayer = 1, kCreases = 2, kSlot = 3, kBone = 4, kVertexCrease = 5, kEdgeCrease = 6,
                            kBonePose = 7 };
std::uint64_t key(Kind k, std::uint16_t a, std::uint32_t b = 0) {
  return (static_cast<std::uint64_t>(k) << 56) | (static_cast<std::uint64_t>(a) << 32) | b;
}

// The hash of one or more lines, each ending in "\n".
std::uint64_t lines_hash(std::string_view text) { return document_digest(text); }

std::string hex16(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

bool parse_hex16(std::string_view s, std::uint64_t* out) {
  if (s.size() != 16) return false;
  std::uint64_t v = 0;
  for (char c : s) {
    int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (d < 0) return false;
    v = (v << 4) | static_cast<std::uint64_t>(d);
  }
  *out = v;
  return true;
}

}  // namespace

std::uint64_t line_hash(std::string_view line) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : line) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::uint64_t document_digest(std::string_view text) {
  std::uint64_t sum = 0;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t j = text.find('\n', i);
    if (j == std::string_view::npos) j = text.size();
    sum += line_hash(text.substr(i, j - i));
    i = j + 1;
  }
  return sum;
}

DocumentDigests digests_of(std::string_view snapshot, std::string_view derived) {
  return {document_digest(snapshot), document_digest(derived)};
}

std::string format_digest_line(const DocumentDigests& d) {
  return "digest " + hex16(d.snapshot) + " " + hex16(d.derived) + "\n";
}

bool parse_digest_line(std::string_view line, DocumentDigests* out) {
  if (!line.empty() && line.back() == '\n') line.remove_suffix(1);
  if (line.size() != 7 + 16 + 1 + 16 || line.substr(0, 7) != "digest " || line[23] != ' ') return false;
  return parse_hex16(line.substr(7, 16), &out->snapshot) && parse_hex16(line.substr(24, 16), &out->derived);
}

bool NodeDigest::Sum::set(std::uint64_t k, const std::string& text) {
  const std::uint64_t h = text.empty() ? 0 : lines_hash(text);
  auto it = lines.find(k);
  if (it == lines.end()) {
    if (text.empty()) return false;
    lines.emplace(k, h);
    sum += h;
    return true;
  }
  const std::uint64_t old = it->second;
  sum -= old;
  if (text.empty()) {
    lines.erase(it);
    return true;
  }
  it->second = h;
  sum += h;
  return old != h;
}

void NodeDigest::Sum::erase_range(std::uint64_t from, std::uint64_t to) {
  auto first = lines.lower_bound(from), last = lines.lower_bound(to);
  for (auto it = first; it != last; ++it) sum -= it->second;
  lines.erase(first, last);
}

NodeDigest::NodeDigest() : NodeDigest(Node{}) {}

NodeDigest::NodeDigest(const Node& node) {
  for (const auto& [id, layer] : node.layers()) set_layer(node, id, true);
  snapshot_.set(key(kCreases, 0), snapshot_crease_lines(node.vertex_crease(), node.edge_crease()));
  for (const auto& [id, bone] : node.bones()) snapshot_.set(key(kBone, id), snapshot_bone_line(id, bone));
  derived_all_creases(node, nullptr);
  derived_bones(node, nullptr);
}

DocumentDigests NodeDigest::digests() const {
  static const std::uint64_t snapshot_frame = line_hash("vgc-snapshot 1") + line_hash("end");
  static const std::uint64_t derived_frame = line_hash("vgc-derived 1") + line_hash("end");
  return {snapshot_.sum + snapshot_frame, derived_.sum + derived_frame};
}

void NodeDigest::set_layer(const Node& node, std::uint16_t id, bool with_slots) {
  const Layer* layer = node.find_layer(id);
  snapshot_.set(key(kLayer, id), layer ? snapshot_layer_line(id, *layer) : std::string());
  if (!with_slots) return;
  snapshot_.erase_range(key(kSlot, id), key(kSlot, id) + (std::uint64_t{1} << 32));
  if (!layer) return;
  for (const auto& [element, slot] : layer->slots)
    snapshot_.set(key(kSlot, id, element), snapshot_slot_line(id, layer->type, element, slot));
}

void NodeDigest::set_slot(const Node& node, std::uint16_t layer_id, std::uint32_t element) {
  const Layer* layer = node.find_layer(layer_id);
  std::string text;
  if (layer) {
    const auto it = layer->slots.find(element);
    if (it != layer->slots.end()) text = snapshot_slot_line(layer_id, layer->type, element, it->second);
  }
  snapshot_.set(key(kSlot, layer_id, element), text);
}

void NodeDigest::derived_element(const Node& node, bool vertex, std::uint32_t id,
                                 std::vector<DerivedChange>* changed) {
  std::string text;
  if (vertex) {
    if (node.vertices().count(id)) text = derived_vertex_line(node, id);
  } else if (const auto it = node.polygons().find(id); it != node.polygons().end()) {
    text = derived_polygon_lines(node, id, it->second);
  }
  const char* kind = vertex ? "vertex_crease" : "edge_crease";
  if (derived_.set(key(vertex ? kVertexCrease : kEdgeCrease, 0, id), text) && changed)
    changed->push_back({kind, text.empty() ? std::string(kind) + " " + std::to_string(id) : text});
}

void NodeDigest::derived_all_creases(const Node& node, std::vector<DerivedChange>* changed) {
  // Elements gone since: their entries go (a command that changes every
  // effective crease does not delete elements, but nothing depends on that).
  std::vector<std::pair<bool, std::uint32_t>> gone;
  for (auto it = derived_.lines.lower_bound(key(kVertexCrease, 0)); it != derived_.lines.end(); ++it) {
    const auto kind = static_cast<Kind>(it->first >> 56);
    if (kind != kVertexCrease && kind != kEdgeCrease) break;
    const auto id = static_cast<std::uint32_t>(it->first);
    if (kind == kVertexCrease ? !node.vertices().count(id) : !node.polygons().count(id))
      gone.emplace_back(kind == kVertexCrease, id);
  }
  for (const auto& [vertex, id] : gone) derived_element(node, vertex, id, changed);
  for (const auto& [id, slot] : node.vertices()) derived_element(node, true, id, changed);
  for (const auto& [id, slot] : node.polygons()) derived_element(node, false, id, changed);
}

void NodeDigest::derived_bones(const Node& node, std::vector<DerivedChange>* changed) {
  const auto lines = derived_bone_lines(node);
  std::vector<std::uint16_t> gone;
  for (auto it = derived_.lines.lower_bound(key(kBonePose, 0)); it != derived_.lines.end(); ++it) {
    const auto id = static_cast<std::uint16_t>(it->first >> 32);
    if (!lines.count(id)) gone.push_back(id);
  }
  for (std::uint16_t id : gone)
    if (derived_.set(key(kBonePose, id), std::string()) && changed)
      changed->push_back({"bone_pose", "bone_pose " + std::to_string(id)});
  for (const auto& [id, line] : lines)
    if (derived_.set(key(kBonePose, id), line) && changed) changed->push_back({"bone_pose", line});
}

void NodeDigest::update(const Node& node, const ChangeLog& changes, std::vector<DerivedChange>* derived_changed) {
  for (std::uint16_t id : changes.whole_layers) set_layer(node, id, true);
  for (std::uint16_t id : changes.layer_lines) set_layer(node, id, false);
  for (const auto& [layer_id, element] : changes.slots) set_slot(node, layer_id, element);
  if (changes.creases)
    snapshot_.set(key(kCreases, 0), snapshot_crease_lines(node.vertex_crease(), node.edge_crease()));
  for (std::uint16_t id : changes.bones) {
    const auto it = node.bones().find(id);
    snapshot_.set(key(kBone, id), it == node.bones().end() ? std::string() : snapshot_bone_line(id, it->second));
  }
  // The derived document: an element's effective creases depend on the
  // element, the crease settings and the layers they name (by name: a layer
  // created, re-created or destroyed may be one of them); bone poses on the
  // bones only.
  if (changes.creases || !changes.whole_layers.empty()) {
    derived_all_creases(node, derived_changed);
  } else {
    for (const auto& [layer_id, element] : changes.slots) {
      const Layer* layer = node.find_layer(layer_id);
      if (layer) derived_element(node, is_vertex_layer_type(layer->type), element, derived_changed);
    }
  }
  if (!changes.bones.empty()) derived_bones(node, derived_changed);
}

}  // namespace vgc
