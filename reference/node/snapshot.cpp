// snapshot.cpp — see snapshot.h.
#include "snapshot.h"

#include <algorithm>
#include <vector>

#include "number_text.h"

namespace vgc {
namespace {

std::string u32(std::uint32_t v) { return format_uint(v, 32); }
std::string u16(std::uint16_t v) { return format_uint(v, 16); }

// The values one slot of `type` holds, space-separated (2.6.1 Table 2-1:
// "Values per Index").
std::string slot_values(LayerType type, const Slot& s) {
  std::string out;
  auto reals = [&](int n) {
    for (int i = 0; i < n; ++i) {
      out += ' ';
      out += format_f64(s.r[i]);
    }
  };
  auto uints = [&](int n, int bits) {
    for (int i = 0; i < n; ++i) {
      out += ' ';
      out += format_uint(s.u[i], bits);
    }
  };
  switch (type) {
    case LayerType::VertexXyz: reals(3); break;
    case LayerType::VertexUint32: uints(1, 32); break;
    case LayerType::VertexReal: reals(1); break;
    case LayerType::PolygonCornerUint32: uints(4, 32); break;
    case LayerType::PolygonCornerReal: reals(4); break;
    case LayerType::PolygonFaceUint8: uints(1, 8); break;
    case LayerType::PolygonFaceUint32: uints(1, 32); break;
    case LayerType::PolygonFaceReal: reals(1); break;
  }
  return out;
}

}  // namespace

UsedDefaults used_defaults(std::uint16_t layer_id, LayerType type) {
  UsedDefaults used;
  if (layer_id == Node::kVertexLayer || layer_id == Node::kPolygonLayer) return used;
  switch (type) {
    case LayerType::VertexUint32:
    case LayerType::PolygonCornerUint32:
    case LayerType::PolygonFaceUint8:
    case LayerType::PolygonFaceUint32: used.def_uint = true; break;
    case LayerType::VertexXyz:
    case LayerType::VertexReal:
    case LayerType::PolygonCornerReal:
    case LayerType::PolygonFaceReal: used.def_real = true; break;
  }
  return used;
}

std::optional<Written> line_written(const Node& node, const std::string& line) {
  std::vector<std::string> w;
  for (std::size_t i = 0; i < line.size() && w.size() < 3;) {
    const std::size_t j = std::min(line.find(' ', i), line.size());
    w.push_back(line.substr(i, j - i));
    i = j + 1;
  }
  if (w.empty()) return std::nullopt;
  if (w[0] == "crease_vertex") return node.vertex_crease().written;
  if (w[0] == "crease_edge") return node.edge_crease().written;
  std::uint32_t a = 0, b = 0;
  if (w.size() < 2 || !parse_uint(w[1], 32, &a)) return std::nullopt;
  const auto in = [](const auto& map, auto id) -> std::optional<Written> {
    const auto it = map.find(id);
    if (it == map.end()) return std::nullopt;
    return it->second.written;
  };
  if (w[0] == "layer") return a > 0xFFFF ? std::nullopt : in(node.layers(), static_cast<std::uint16_t>(a));
  if (w[0] == "vertex") return in(node.vertices(), a);
  if (w[0] == "polygon") return in(node.polygons(), a);
  if (w[0] == "bone") return a > 0xFFFF ? std::nullopt : in(node.bones(), static_cast<std::uint16_t>(a));
  if (w[0] == "slot" && w.size() >= 3 && a <= 0xFFFF && parse_uint(w[2], 32, &b)) {
    const Layer* layer = node.find_layer(static_cast<std::uint16_t>(a));
    return layer ? in(layer->slots, b) : std::nullopt;
  }
  return std::nullopt;
}

std::string print_snapshot(const Node& node) {
  return print_snapshot(SnapshotParts{node.layers(), node.vertex_crease(), node.edge_crease(), node.bones()});
}

std::string snapshot_layer_line(std::uint16_t id, const Layer& layer) {
  const UsedDefaults used = used_defaults(id, layer.type);
  return "layer " + u16(id) + " " + format_quoted(layer.name) + " " +
         std::string(layer_type_name(static_cast<std::uint8_t>(layer.type))) + " " +
         (used.def_uint ? u32(layer.def_uint) : "-") + " " + (used.def_real ? format_f64(layer.def_real) : "-") +
         " " + (!layer.subscription ? "-" : *layer.subscription == RealFormat::Real32 ? "REAL32" : "REAL64") + "\n";
}

std::string snapshot_crease_lines(const CreaseSetting& vertex, const CreaseSetting& edge) {
  return "crease_vertex " + format_quoted(vertex.layer) + " " + u32(vertex.def_crease) + "\n" + "crease_edge " +
         format_quoted(edge.layer) + " " + u32(edge.def_crease) + "\n";
}

std::string snapshot_slot_line(std::uint16_t layer_id, LayerType type, std::uint32_t element, const Slot& slot) {
  if (layer_id == Node::kVertexLayer) return "vertex " + u32(element) + slot_values(LayerType::VertexXyz, slot) + "\n";
  if (layer_id == Node::kPolygonLayer)
    return "polygon " + u32(element) + slot_values(LayerType::PolygonCornerUint32, slot) + "\n";
  return "slot " + u16(layer_id) + " " + u32(element) + slot_values(type, slot) + "\n";
}

std::string snapshot_bone_line(std::uint16_t id, const Bone& b) {
  std::string out = "bone " + u16(id) + " " + format_quoted(b.weight) + " " + format_quoted(b.reference) + " " +
                    u16(b.parent);
  for (double v : b.pos) out += " " + format_f64(v);
  out += " " + format_quoted(b.pos_label);
  for (double v : b.rot) out += " " + format_f64(v);
  out += " " + format_quoted(b.rot_label) + "\n";
  return out;
}

std::string print_snapshot(const SnapshotParts& node) {
  static const std::map<std::uint32_t, Slot> kNone;
  const auto slots_of = [&node](std::uint16_t id) -> const std::map<std::uint32_t, Slot>& {
    const auto it = node.layers.find(id);
    return it == node.layers.end() ? kNone : it->second.slots;
  };
  std::string out = kSnapshotHeader;
  out.reserve(4096);
  for (const auto& [id, layer] : node.layers) out += snapshot_layer_line(id, layer);
  out += snapshot_crease_lines(node.vertex_crease, node.edge_crease);
  for (const auto& [id, slot] : slots_of(Node::kVertexLayer))
    out += snapshot_slot_line(Node::kVertexLayer, LayerType::VertexXyz, id, slot);
  for (const auto& [id, slot] : slots_of(Node::kPolygonLayer))
    out += snapshot_slot_line(Node::kPolygonLayer, LayerType::PolygonCornerUint32, id, slot);
  for (const auto& [lid, layer] : node.layers) {
    if (lid == Node::kVertexLayer || lid == Node::kPolygonLayer) continue;
    for (const auto& [element, slot] : layer.slots) out += snapshot_slot_line(lid, layer.type, element, slot);
  }
  for (const auto& [id, b] : node.bones) out += snapshot_bone_line(id, b);
  out += "end\n";
  return out;
}

}  // namespace vgc
