// crease.cpp — see crease.h.
#include "crease.h"

namespace vgc {
namespace {

const Layer* crease_layer(const Node& node, const CreaseSetting& s, LayerType required) {
  if (s.layer.empty()) return nullptr;
  const Layer* layer = node.find_layer_by_name(s.layer);
  return layer && layer->type == required ? layer : nullptr;
}

}  // namespace

int corner_count(const Slot& polygon) { return polygon.u[3] == kNone32 ? 3 : 4; }

std::uint32_t vertex_crease(const Node& node, std::uint32_t vertex_id) {
  const CreaseSetting& s = node.vertex_crease();
  if (const Layer* layer = crease_layer(node, s, LayerType::VertexUint32))
    return layer->slots.at(vertex_id).u[0];
  return s.def_crease;
}

std::uint32_t edge_crease(const Node& node, std::uint32_t polygon_id, int corner) {
  const CreaseSetting& s = node.edge_crease();
  if (const Layer* layer = crease_layer(node, s, LayerType::PolygonCornerUint32))
    return layer->slots.at(polygon_id).u[static_cast<std::size_t>(corner)];
  return s.def_crease;
}

}  // namespace vgc
