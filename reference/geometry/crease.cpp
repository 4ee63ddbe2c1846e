// crease.cpp — see crease.h.
#include "crease.h"

namespace vgc {
namespace {

// Where a setting's effective creases come from: the layer to read (null
// for the constant) and the rule that decided it. The one place the
// decision is made: values and rules both come from here.
struct CreaseSource {
  const Layer* layer = nullptr;
  DerivedRule rule = DerivedRule::None;
};

struct CreaseRules {
  DerivedRule constant, layer, missing, initial;
};

constexpr CreaseRules kVertexRules{DerivedRule::VertexCreaseConstant, DerivedRule::VertexCreaseLayer,
                                   DerivedRule::VertexCreaseLayerMissing, DerivedRule::VertexCreaseInitial};
constexpr CreaseRules kEdgeRules{DerivedRule::EdgeCreaseConstant, DerivedRule::EdgeCreaseLayer,
                                 DerivedRule::EdgeCreaseLayerMissing, DerivedRule::EdgeCreaseInitial};

CreaseSource crease_source(const Node& node, const CreaseSetting& s, LayerType required, const CreaseRules& rules) {
  if (s.layer.empty())
    return {nullptr, s.written.rule == Rule::InitialCreases ? rules.initial : rules.constant};
  const Layer* layer = node.find_layer_by_name(s.layer);
  if (layer && layer->type == required) return {layer, rules.layer};
  return {nullptr, rules.missing};
}

CreaseSource vertex_source(const Node& node) {
  return crease_source(node, node.vertex_crease(), LayerType::VertexUint32, kVertexRules);
}

CreaseSource edge_source(const Node& node) {
  return crease_source(node, node.edge_crease(), LayerType::PolygonCornerUint32, kEdgeRules);
}

}  // namespace

int corner_count(const Slot& polygon) { return polygon.u[3] == kNone32 ? 3 : 4; }

std::uint32_t vertex_crease(const Node& node, std::uint32_t vertex_id) {
  if (const Layer* layer = vertex_source(node).layer) return layer->slots.at(vertex_id).u[0];
  return node.vertex_crease().def_crease;
}

std::uint32_t edge_crease(const Node& node, std::uint32_t polygon_id, int corner) {
  if (const Layer* layer = edge_source(node).layer)
    return layer->slots.at(polygon_id).u[static_cast<std::size_t>(corner)];
  return node.edge_crease().def_crease;
}

DerivedRule vertex_crease_rule(const Node& node) { return vertex_source(node).rule; }
DerivedRule edge_crease_rule(const Node& node) { return edge_source(node).rule; }

}  // namespace vgc
