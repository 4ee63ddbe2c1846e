// session_drop_test.cpp — a session that falls far behind is caught up or
// clearly told it was dropped, never left stuck (issue 28; docs/verse_wire.md
// section 5): 2,000 packets lost in a row are naked and the session goes on;
// past kMaxPacketGap the host ends the session with connect_terminate (as r6
// ends one, v_connect.c) and vgc's client reports Status::Code::Dropped with
// the host's words, at once rather than at a time-out.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "running_host.h"
#include "verse_client.h"
#include "verse_host.h"
#include "wire_endpoint.h"

namespace vgc::verse {
namespace {

constexpr double kWait = 10.0;  // seconds; loopback answers in milliseconds

// A session with a node, subscribed to it and to its vertices.
struct Client {
  ClientSession s;
  std::uint32_t node = 0;
  void start(const RunningHost& h) {
    ASSERT_TRUE(s.connect("127.0.0.1", h.host.port(), {}).ok());
    ASSERT_TRUE(s.create_geometry_node(&node, kWait).ok());
    ASSERT_TRUE(s.subscribe_node(node).ok());
    ASSERT_TRUE(s.subscribe_layer(node, 0, RealFormat::Real64).ok());
    std::vector<WireCommand> seen;
    ASSERT_TRUE(s.barrier(node, kWait, &seen).ok());
  }
  // `n` packet ids taken and never sent: the host sees them all lost.
  void lose(std::uint32_t n) {
    for (std::uint32_t i = 0; i < n; ++i) (void)s.take_packet_id();
  }
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(VerseSessionDrop, TwoThousandPacketsLostInARowAreCaughtUp) {
  RunningHost h;
  Client a;
  a.start(h);
  a.lose(2000);
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::VertexSetXyzReal64{0, 5, 1, 2, 3}).ok());
  std::vector<WireCommand> seen;
  const Status st = a.s.barrier(a.node, kWait, &seen);
  ASSERT_TRUE(st.ok()) << st.to_string();
  bool vertex = false;
  for (const WireCommand& w : seen)
    if (const auto* g = std::get_if<wire::Geometry>(&w)) vertex |= std::holds_alternative<cmd::VertexSetXyzReal64>(g->command);
  EXPECT_TRUE(vertex) << "the command after the gap was applied and broadcast";
  EXPECT_EQ(h.host.counters().terminates_sent, 0u);
}

TEST(VerseSessionDrop, ASessionPastTheGapIsDroppedAndItsClientIsToldSo) {
  RunningHost h;
  Client a;
  a.start(h);
  a.lose(kMaxPacketGap + 10);
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::VertexSetXyzReal64{0, 5, 1, 2, 3}).ok());
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<WireCommand> seen;
  Status st = a.s.barrier(a.node, kWait, &seen);
  EXPECT_EQ(st.code, Status::Code::Dropped) << st.to_string();
  EXPECT_LT(seconds_since(t0), 5.0) << "told at once, not at a time-out";
  EXPECT_NE(st.detail.find("the host dropped this session"), std::string::npos) << st.detail;
  EXPECT_NE(st.detail.find("more than 65536 packets lost in a row"), std::string::npos) << st.detail;
  EXPECT_FALSE(a.s.connected());
  st = a.s.send_geometry(a.node, cmd::VertexSetXyzReal64{0, 6, 1, 2, 3});
  EXPECT_EQ(st.code, Status::Code::Dropped) << "every later call says why: " << st.to_string();
  EXPECT_GE(h.host.counters().terminates_sent, 1u);

  // The host serves on: a new session sees the node as it was.
  Client b;
  ASSERT_TRUE(b.s.connect("127.0.0.1", h.host.port(), {}).ok());
  b.node = a.node;
  ASSERT_TRUE(b.s.subscribe_node(b.node).ok());
  st = b.s.barrier(b.node, kWait, &seen);
  EXPECT_TRUE(st.ok()) << st.to_string();
}

}  // namespace
}  // namespace vgc::verse
