// packet_order.cpp — see packet_order.h (docs/verse_wire.md section 6).
#include "packet_order.h"

#include <algorithm>

namespace vgc::verse {

int packet_order_group(const WireCommand& c) {
  const auto* g = std::get_if<wire::Geometry>(&c);
  if (g == nullptr) return 3;
  const vgc::Command& k = g->command;
  if (std::holds_alternative<cmd::LayerCreate>(k) || std::holds_alternative<cmd::LayerDestroy>(k)) return 0;
  if (std::holds_alternative<cmd::VertexDelete>(k)) return 1;
  if (const auto* v = std::get_if<cmd::VertexSetXyzReal32>(&k)) return v->layer_id == 0 ? 1 : 3;
  if (const auto* v = std::get_if<cmd::VertexSetXyzReal64>(&k)) return v->layer_id == 0 ? 1 : 3;
  if (std::holds_alternative<cmd::PolygonDelete>(k)) return 2;
  if (const auto* p = std::get_if<cmd::PolygonSetCornerUint32>(&k)) return p->layer_id == 1 ? 2 : 3;
  return 3;
}

void order_packet(std::vector<WireCommand>* commands) {
  std::stable_sort(commands->begin(), commands->end(), [](const WireCommand& a, const WireCommand& b) {
    return packet_order_group(a) < packet_order_group(b);
  });
}

}  // namespace vgc::verse
