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
// Appends a slot's values, each after a space: the fields `type` gives it.
void append_slot_values(std::string* out, LayerType type, const Slot& s) {
  auto reals = [&](int n) {
    for (int i = 0; i < n; ++i) {
      *out += ' ';
      *out += format_f64(s.r[i]);
    }
  };
  auto uints = [&](int n, int bits) {
    for (int i = 0; i < n; ++i) {
      *out += ' ';
      *out += format_uint(s.u[i], bits);
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
}

// Appends snapshot_slot_line's line. print_snapshot appends every slot
// line to the one document string this way rather than concatenating a
// string per line: slot lines are most of a snapshot, and the fuzz targets
// print one or two snapshots per input.
void append_slot_line(std::string* out, std::uint16_t layer_id, LayerType type, std::uint32_t element,
                      const Slot& slot) {
  if (layer_id == Node::kVertexLayer) {
    *out += "vertex ";
    type = LayerType::VertexXyz;
  } else if (layer_id == Node::kPolygonLayer) {
    *out += "polygon ";
    type = LayerType::PolygonCornerUint32;
  } else {
    *out += "slot ";
    *out += u16(layer_id);
    *out += ' ';
  }
  *out += u32(element);
  append_slot_values(out, type, slot);
  *out += '\n';
}

// Appends snapshot_layer_line's line (as append_slot_line, for the same reason).
void append_layer_line(std::string* out, std::uint16_t id, const Layer& layer) {
  const UsedDefaults used = used_defaults(id, layer.type);
  *out += "layer ";
  *out += u16(id);
  *out += ' ';
  *out += format_quoted(layer.name);
  *out += ' ';
  *out += layer_type_name(static_cast<std::uint8_t>(layer.type));
  *out += ' ';
  *out += used.def_uint ? u32(layer.def_uint) : "-";
  *out += ' ';
  *out += used.def_real ? format_f64(layer.def_real) : "-";
  *out += ' ';
  *out += !layer.subscription ? "-" : *layer.subscription == RealFormat::Real32 ? "REAL32" : "REAL64";
  *out += '\n';
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
  std::string line;
  append_layer_line(&line, id, layer);
  return line;
}

std::string snapshot_crease_lines(const CreaseSetting& vertex, const CreaseSetting& edge) {
  return "crease_vertex " + format_quoted(vertex.layer) + " " + u32(vertex.def_crease) + "\n" + "crease_edge " +
         format_quoted(edge.layer) + " " + u32(edge.def_crease) + "\n";
}

std::string snapshot_slot_line(std::uint16_t layer_id, LayerType type, std::uint32_t element, const Slot& slot) {
  std::string line;
  append_slot_line(&line, layer_id, type, element, slot);
  return line;
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
  for (const auto& [id, layer] : node.layers) append_layer_line(&out, id, layer);
  out += snapshot_crease_lines(node.vertex_crease, node.edge_crease);
  for (const auto& [id, slot] : slots_of(Node::kVertexLayer))
    append_slot_line(&out, Node::kVertexLayer, LayerType::VertexXyz, id, slot);
  for (const auto& [id, slot] : slots_of(Node::kPolygonLayer))
    append_slot_line(&out, Node::kPolygonLayer, LayerType::PolygonCornerUint32, id, slot);
  for (const auto& [lid, layer] : node.layers) {
    if (lid == Node::kVertexLayer || lid == Node::kPolygonLayer) continue;
    for (const auto& [element, slot] : layer.slots) append_slot_line(&out, lid, layer.type, element, slot);
  }
  for (const auto& [id, b] : node.bones) out += snapshot_bone_line(id, b);
  out += "end\n";
  return out;
}

}  // namespace vgc
