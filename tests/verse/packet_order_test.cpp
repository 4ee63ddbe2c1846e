// packet_order_test.cpp — verse/packet_order (docs/verse_wire.md section
// 6): the groups of one packet's commands, and that the sort is stable.
#include <gtest/gtest.h>

#include "packet_order.h"

namespace vgc::verse {
namespace {

WireCommand g(const Command& c) { return wire::Geometry{7, c}; }

TEST(PacketOrder, GroupsAndStability) {
  std::vector<WireCommand> p = {
      g(cmd::VertexSetUint32{2, 10, 4}),                                  // 3: a slot
      wire::NodeNameSet{7, "n"},                                          // 3
      g(cmd::PolygonSetCornerUint32{1, 5, {10, 11, 12, 0xFFFFFFFFu}}),   // 2
      g(cmd::VertexSetXyzReal32{0, 11, 1, 2, 3}),                         // 1
      g(cmd::VertexSetXyzReal64{4, 11, 1, 2, 3}),                         // 3: not the base layer
      g(cmd::VertexDelete{11}),                                           // 1, after the set
      g(cmd::LayerCreate{0xFFFF, "l", 1, 0, 0}),                          // 0
      g(cmd::PolygonDelete{5}),                                           // 2, after the set
      g(cmd::PolygonSetCornerUint32{5, 5, {1, 2, 3, 4}}),                 // 3: not the base layer
      g(cmd::LayerDestroy{3}),                                            // 0, after the create
  };
  std::vector<int> groups;
  for (const WireCommand& c : p) groups.push_back(packet_order_group(c));
  EXPECT_EQ(groups, (std::vector<int>{3, 3, 2, 1, 3, 1, 0, 2, 3, 0}));
  order_packet(&p);
  std::vector<std::string> order;
  for (const WireCommand& c : p) order.push_back(describe(c));
  EXPECT_EQ(order, (std::vector<std::string>{
                       describe(g(cmd::LayerCreate{0xFFFF, "l", 1, 0, 0})), describe(g(cmd::LayerDestroy{3})),
                       describe(g(cmd::VertexSetXyzReal32{0, 11, 1, 2, 3})), describe(g(cmd::VertexDelete{11})),
                       describe(g(cmd::PolygonSetCornerUint32{1, 5, {10, 11, 12, 0xFFFFFFFFu}})),
                       describe(g(cmd::PolygonDelete{5})), describe(g(cmd::VertexSetUint32{2, 10, 4})),
                       describe(wire::NodeNameSet{7, "n"}), describe(g(cmd::VertexSetXyzReal64{4, 11, 1, 2, 3})),
                       describe(g(cmd::PolygonSetCornerUint32{5, 5, {1, 2, 3, 4}}))}));
  EXPECT_TRUE(std::holds_alternative<wire::NodeNameSet>(p[7]));
}

}  // namespace
}  // namespace vgc::verse
