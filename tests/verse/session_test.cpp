// session_test.cpp — verse/verse_client against verse/verse_host over
// loopback UDP: login, node creation, subscriptions, geometry commands and
// what the host sends back to subscribers (docs/verse_wire.md sections 2, 3,
// 6, 7), and a seeded fault of the served node seen through the wire.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <set>
#include <thread>

#include "faulty_node.h"
#include "running_host.h"
#include "verse_client.h"
#include "verse_host.h"
#include "wire_login.h"
#include "wire_packet.h"

namespace vgc::verse {
namespace {

constexpr double kWait = 10.0;  // seconds; loopback answers in milliseconds

class FaultyHostedNode : public HostedNode {
 public:
  explicit FaultyHostedNode(std::vector<int> faults) : node_(std::move(faults)) {}
  bool apply(const Command& c, std::string*) override {
    node_.apply(c);
    return true;
  }
  bool snapshot(std::string* text, std::string*) override {
    *text = node_.snapshot();
    return true;
  }

 private:
  faults::FaultyNode node_;
};

template <class T>
std::vector<T> geometry_of(const std::vector<WireCommand>& cs) {
  std::vector<T> out;
  for (const WireCommand& c : cs)
    if (const auto* g = std::get_if<wire::Geometry>(&c))
      if (const auto* t = std::get_if<T>(&g->command)) out.push_back(*t);
  return out;
}

struct Client {
  ClientSession s;
  std::uint32_t node = 0;
  void connect(const RunningHost& h) {
    const Status st = s.connect("localhost", h.host.port(), {});
    ASSERT_TRUE(st.ok()) << st.to_string();
  }
  std::vector<WireCommand> barrier() {
    std::vector<WireCommand> seen;
    const Status st = s.barrier(node, kWait, &seen);
    EXPECT_TRUE(st.ok()) << st.to_string();
    return seen;
  }
};

TEST(VerseSession, CreateSubscribeSendAndSeeTheHostBroadcast) {
  RunningHost h;
  Client a;
  a.connect(h);
  Status st = a.s.create_geometry_node(&a.node, kWait);
  ASSERT_TRUE(st.ok()) << st.to_string();
  ASSERT_TRUE(a.s.subscribe_node(a.node).ok());
  ASSERT_TRUE(a.s.subscribe_layer(a.node, 0, RealFormat::Real64).ok());
  ASSERT_TRUE(a.s.subscribe_layer(a.node, 1, RealFormat::Real64).ok());
  auto seen = a.barrier();
  auto layers = geometry_of<cmd::LayerCreate>(seen);
  ASSERT_EQ(layers.size(), 2u);
  EXPECT_EQ(layers[0].name, "vertex");
  EXPECT_EQ(layers[1].name, "polygon");
  EXPECT_EQ(geometry_of<cmd::CreaseSetVertex>(seen).size(), 1u);
  EXPECT_EQ(geometry_of<cmd::CreaseSetEdge>(seen).size(), 1u);

  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::VertexSetXyzReal64{0, 0, 0, 0, 0}).ok());  // all zero: still a vertex
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::VertexSetXyzReal64{0, 1, 4, 5, 6}).ok());
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::VertexSetXyzReal64{0, 2, 7, 8, 9}).ok());
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::PolygonSetCornerUint32{1, 0, {0, 1, 2, 0xFFFFFFFFu}}).ok());
  // Dropped by the node (repeated corner): nothing may come back for it.
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::PolygonSetCornerUint32{1, 1, {0, 0, 1, 0xFFFFFFFFu}}).ok());
  seen = a.barrier();
  auto verts = geometry_of<cmd::VertexSetXyzReal64>(seen);
  ASSERT_EQ(verts.size(), 3u);
  EXPECT_EQ(verts[1].vertex_id, 1u);
  EXPECT_EQ(verts[1].x, 4.0);
  EXPECT_EQ(verts[2].z, 9.0);
  auto polys = geometry_of<cmd::PolygonSetCornerUint32>(seen);
  ASSERT_EQ(polys.size(), 1u);
  EXPECT_EQ(polys[0].polygon_id, 0u);
  EXPECT_EQ(polys[0].v, (std::array<std::uint32_t, 4>{0, 1, 2, 0xFFFFFFFFu}));

  // A second client subscribing later gets the layer's whole content, in the format it asked for.
  Client b;
  b.connect(h);
  b.node = a.node;
  ASSERT_TRUE(b.s.subscribe_node(b.node).ok());
  ASSERT_TRUE(b.s.subscribe_layer(b.node, 0, RealFormat::Real32).ok());
  seen = b.barrier();
  auto verts32 = geometry_of<cmd::VertexSetXyzReal32>(seen);
  ASSERT_EQ(verts32.size(), 3u);
  EXPECT_EQ(verts32[2].y, 8.0f);

  // A layer created by one client reaches every node subscriber; a polygon
  // delete reaches only layer 1's subscribers.
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::LayerCreate{0xFFFF, "weights", 1, 5, 0}).ok());
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::PolygonDelete{0}).ok());
  seen = a.barrier();
  EXPECT_EQ(geometry_of<cmd::PolygonDelete>(seen).size(), 1u);
  ASSERT_EQ(geometry_of<cmd::LayerCreate>(seen).size(), 1u);
  EXPECT_EQ(geometry_of<cmd::LayerCreate>(seen)[0].layer_id, 2u) << "the lowest free id";
  seen = b.barrier();
  EXPECT_EQ(geometry_of<cmd::PolygonDelete>(seen).size(), 0u);
  ASSERT_EQ(geometry_of<cmd::LayerCreate>(seen).size(), 1u);
  EXPECT_EQ(geometry_of<cmd::LayerCreate>(seen)[0].def_uint, 5u);

  // receive(…, 0) reads what has already arrived without waiting for more.
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::VertexSetXyzReal64{0, 9, 1, 1, 1}).ok());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  WireCommand got;
  do {  // b's barrier echo (node_name_set) also reached a, a node subscriber
    st = a.s.receive(&got, 0);
    ASSERT_TRUE(st.ok()) << st.to_string();
  } while (std::holds_alternative<wire::NodeNameSet>(got));
  EXPECT_EQ(describe(got).rfind("g_vertex_set_xyz_real64", 0), 0u) << describe(got);
  EXPECT_EQ(a.s.receive(&got, 0).code, Status::Code::Timeout);

  a.s.disconnect();
  b.s.disconnect();
}

// vgc's host playing the r6 behaviours the client must survive
// (HostOptions; docs/verse_wire.md sections 3 and 4).
HostOptions like_r6() {
  HostOptions o;
  o.reuse_node_ids = true;
  o.bone_form = BoneForm::R6;
  o.strict_bone_form = true;
  return o;
}

TEST(VerseSession, ANodeIdTheHostReusesAfterADestroyIsAccepted) {
  RunningHost h(like_r6());
  Client a;
  a.connect(h);
  std::uint32_t first = 0, second = 0;
  Status st = a.s.create_geometry_node(&first, kWait);
  ASSERT_TRUE(st.ok()) << st.to_string();
  ASSERT_TRUE(a.s.send(wire::NodeDestroy{first}).ok());
  st = a.s.create_geometry_node(&second, kWait);
  ASSERT_TRUE(st.ok()) << st.to_string();
  EXPECT_EQ(second, first) << "the host gave the lowest free id, the destroyed node's";
  // A node that still exists is not taken for a new one when announced again.
  std::uint32_t third = 0;
  st = a.s.create_geometry_node(&third, kWait);
  ASSERT_TRUE(st.ok()) << st.to_string();
  EXPECT_NE(third, second);
}

TEST(VerseSession, BoneCreateInR6sFormAndTheBarrierAfterOneTheHostCannotDecode) {
  RunningHost h(like_r6());
  Client a;
  a.connect(h);
  ASSERT_TRUE(a.s.create_geometry_node(&a.node, kWait).ok());
  ASSERT_TRUE(a.s.subscribe_node(a.node).ok());
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::LayerCreate{2, "w", 1, 0, 0}).ok());
  a.barrier();
  // The spec's form: this host reads it in r6's, as r6 does: the bone's
  // labels come from the rotation's bytes, and the rest of that packet does
  // not decode and is dropped. The barrier, in a packet of its own, still
  // comes back, and the host's answer (r6's form) is read in that form.
  const cmd::BoneCreate bone{0, "w", "", 0xFFFF, {1, 2, 3}, "p", {0, 0, 0, 1}, "r"};
  ASSERT_TRUE(a.s.send_geometry(a.node, bone).ok());
  auto seen = a.barrier();
  ASSERT_EQ(geometry_of<cmd::BoneCreate>(seen).size(), 1u);
  EXPECT_EQ(geometry_of<cmd::BoneCreate>(seen)[0].rot_label, "") << "not the \"r\" sent: misread";
  EXPECT_EQ(a.s.counters().other_bone_form, 1u);
  // r6's form: stored, and sent back in r6's form, which the client reads.
  a.s.set_bone_form(BoneForm::R6);
  ASSERT_TRUE(a.s.send_geometry(a.node, bone).ok());
  seen = a.barrier();
  const auto bones = geometry_of<cmd::BoneCreate>(seen);
  ASSERT_EQ(bones.size(), 1u);
  EXPECT_EQ(bones[0].pos, (std::array<double, 3>{1, 2, 3}));
  EXPECT_EQ(bones[0].pos_label, "p");
  EXPECT_EQ(bones[0].rot_label, "r");
  EXPECT_EQ(a.s.counters().other_bone_form, 1u) << "no more packets in the other form";
}

// Issue 18 / docs/verse_wire.md section 6: r6's client sends one flush in
// the hash order of the commands' addresses, e.g. the triangle before its
// vertices. vgc's host applies a packet's layer commands, then vertex
// commands, then polygon commands, so the triangle is kept.
TEST(VerseSession, ABurstInR6sOrderKeepsTheTriangle) {
  RunningHost h;
  Client a;
  a.connect(h);
  ASSERT_TRUE(a.s.create_geometry_node(&a.node, kWait).ok());
  ASSERT_TRUE(a.s.subscribe_node(a.node).ok());
  ASSERT_TRUE(a.s.subscribe_layer(a.node, 0, RealFormat::Real32).ok());
  ASSERT_TRUE(a.s.subscribe_layer(a.node, 1, RealFormat::Real32).ok());
  (void)a.barrier();
  auto g = [&](const Command& c) { return WireCommand{wire::Geometry{a.node, c}}; };
  // The order r6's client sent this burst in (tests/verse/r6_fixtures/r6_host.txt, step burst).
  ASSERT_TRUE(a.s.send_burst({g(cmd::LayerCreate{0xFFFF, "burst", 1, 0, 0}),
                              g(cmd::PolygonSetCornerUint32{1, 5, {10, 11, 12, 0xFFFFFFFFu}}),
                              g(cmd::VertexSetXyzReal32{0, 10, 5, 5, 5}),
                              g(cmd::VertexSetXyzReal32{0, 11, 6, 5, 5}),
                              g(cmd::VertexSetXyzReal32{0, 12, 5, 6, 5})})
                  .ok());
  auto seen = a.barrier();
  EXPECT_EQ(geometry_of<cmd::VertexSetXyzReal32>(seen).size(), 3u);
  EXPECT_EQ(geometry_of<cmd::LayerCreate>(seen).size(), 1u);
  auto polys = geometry_of<cmd::PolygonSetCornerUint32>(seen);
  ASSERT_EQ(polys.size(), 1u) << "the triangle sent before its vertices in one packet was dropped";
  EXPECT_EQ(polys[0].v, (std::array<std::uint32_t, 4>{10, 11, 12, 0xFFFFFFFFu}));
  // Two commands of one address keep their order: set then delete leaves no vertex.
  ASSERT_TRUE(a.s.send_burst({g(cmd::VertexSetXyzReal32{0, 20, 1, 1, 1}), g(cmd::VertexDelete{20})}).ok());
  seen = a.barrier();
  auto deletes = geometry_of<cmd::VertexDelete>(seen);
  ASSERT_EQ(deletes.size(), 1u);
  EXPECT_EQ(deletes[0].vertex_id, 20u);
}

TEST(VerseSession, ASeededFaultOfTheServedNodeShowsOnTheWire) {
  std::vector<int> faults;
  std::string error;
  ASSERT_TRUE(faults::parse_fault_list("polygon-delete-ignored", &faults, &error)) << error;
  HostOptions o;
  o.make_node = [faults](std::string*) -> std::unique_ptr<HostedNode> {
    return std::make_unique<FaultyHostedNode>(faults);
  };
  RunningHost h(o);
  Client a;
  a.connect(h);
  ASSERT_TRUE(a.s.create_geometry_node(&a.node, kWait).ok());
  ASSERT_TRUE(a.s.subscribe_node(a.node).ok());
  ASSERT_TRUE(a.s.subscribe_layer(a.node, 1, RealFormat::Real64).ok());
  for (std::uint32_t v = 0; v < 3; ++v)
    ASSERT_TRUE(a.s.send_geometry(a.node, cmd::VertexSetXyzReal64{0, v, double(v), 0, 0}).ok());
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::PolygonSetCornerUint32{1, 0, {0, 1, 2, 0xFFFFFFFFu}}).ok());
  auto seen = a.barrier();
  ASSERT_EQ(geometry_of<cmd::PolygonSetCornerUint32>(seen).size(), 1u);
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::PolygonDelete{0}).ok());
  seen = a.barrier();
  EXPECT_EQ(geometry_of<cmd::PolygonDelete>(seen).size(), 0u) << "the faulty node keeps the polygon";
}

// Every packet the served reference sends in a session touching every
// command parses; with VGC_CAPTURE_DIR set they are written there, one file
// each: that is how corpora/fuzz/fuzz_verse_packet/ was made
// (VGC_CAPTURE_DIR=corpora/fuzz/fuzz_verse_packet build/tests/verse/verse_tests
//  --gtest_filter=VerseSession.CapturedTrafficParses).
TEST(VerseSession, CapturedTrafficParses) {
  RunningHost h;
  std::vector<std::string> packets;
  ClientOptions co;
  co.on_packet = [&](const std::string& p) { packets.push_back(p); };
  Client a, b;
  ASSERT_TRUE(a.s.connect("127.0.0.1", h.host.port(), co).ok());
  ASSERT_TRUE(b.s.connect("127.0.0.1", h.host.port(), co).ok());
  ASSERT_TRUE(a.s.create_geometry_node(&a.node, kWait).ok());
  b.node = a.node;
  ASSERT_TRUE(a.s.subscribe_node(a.node).ok());
  ASSERT_TRUE(b.s.subscribe_node(b.node).ok());
  const std::uint8_t types[] = {0, 1, 2, 128, 129, 130, 131, 132};
  for (std::uint16_t i = 0; i < 8; ++i)
    ASSERT_TRUE(a.s.send_geometry(a.node, cmd::LayerCreate{std::uint16_t(2 + i), "l" + std::to_string(i), types[i], 3, 0.5}).ok());
  a.barrier();
  for (std::uint16_t l = 0; l < 10; ++l) {
    ASSERT_TRUE(a.s.subscribe_layer(a.node, l, RealFormat::Real64).ok());
    ASSERT_TRUE(b.s.subscribe_layer(b.node, l, RealFormat::Real32).ok());
  }
  const std::vector<Command> cs = {
      cmd::VertexSetXyzReal64{0, 0, 1, 2, 3}, cmd::VertexSetXyzReal32{0, 1, 4, 5, 6},
      cmd::VertexSetXyzReal64{0, 2, 7, 8, 9}, cmd::VertexSetXyzReal64{0, 3, 1, 1, 1},
      cmd::VertexSetXyzReal64{2, 1, 0.5, 0.5, 0.5}, cmd::VertexSetUint32{3, 0, 42}, cmd::VertexSetReal64{4, 1, 0.25},
      cmd::VertexSetReal32{4, 2, 0.75f}, cmd::PolygonSetCornerUint32{1, 0, {0, 1, 2, 0xFFFFFFFFu}},
      cmd::PolygonSetCornerUint32{1, 1, {0, 1, 2, 3}}, cmd::PolygonSetCornerUint32{5, 0, {9, 9, 9, 9}},
      cmd::PolygonSetCornerReal64{6, 0, {1, 2, 3, 4}}, cmd::PolygonSetCornerReal32{6, 1, {5, 6, 7, 8}},
      cmd::PolygonSetFaceUint8{7, 0, 200}, cmd::PolygonSetFaceUint32{8, 1, 77}, cmd::PolygonSetFaceReal64{9, 0, -1},
      cmd::PolygonSetFaceReal32{9, 1, 2.5f}, cmd::CreaseSetVertex{"l1", 5}, cmd::CreaseSetEdge{"", 0xFFFFFFFFu},
      cmd::BoneCreate{0, "l1", "", 0xFFFF, {1, 2, 3}, "", {0, 0, 0, 1}, ""},
      cmd::BoneCreate{1, "l2", "l1", 0, {0, 1, 0}, "p", {0, 0.6, 0, 0.8}, "r"}, cmd::PolygonDelete{1},
      cmd::VertexDelete{3}, cmd::BoneDestroy{1}, cmd::LayerDestroy{9}, cmd::LayerUnsubscribe{8}};
  for (const Command& c : cs) ASSERT_TRUE(a.s.send_geometry(a.node, c).ok());
  a.barrier();
  b.barrier();
  a.s.disconnect();
  b.s.disconnect();

  std::size_t login = 0, data = 0;
  std::set<std::uint8_t> numbers;
  for (const std::string& p : packets) {
    const auto* d = reinterpret_cast<const std::uint8_t*>(p.data());
    if (p.size() >= 4 && d[0] == 0 && d[1] == 0 && d[2] == 0 && d[3] <= 1) {
      LoginMessage m;
      EXPECT_TRUE(parse_login_packet(d, p.size(), &m).ok());
      ++login;
      continue;
    }
    Packet parsed;
    const Status st = parse_packet(d, p.size(), &parsed);
    EXPECT_TRUE(st.ok()) << st.to_string();
    for (const WireCommand& c : parsed.commands) numbers.insert(command_number(c));
    ++data;
  }
  EXPECT_EQ(login, 4u) << "two challenges and two accepts";
  EXPECT_GT(data, 4u);
  for (std::uint8_t n = 48; n <= 64; ++n)  // 49, layer_subscribe, goes only from clients to hosts
    if (n != 49) {
      EXPECT_TRUE(numbers.count(n)) << "no command " << int(n) << " was broadcast";
    }
  EXPECT_TRUE(numbers.count(kCmdNodeCreate) && numbers.count(kCmdNodeNameSet) && numbers.count(kCmdPacketAck));
  if (const char* dir = std::getenv("VGC_CAPTURE_DIR")) {
    // One packet per shape (its first byte after the id and its length
    // class), so the seeds stay few and different.
    std::set<std::string> shapes;
    std::vector<std::string> unique;
    for (const std::string& p : packets) {
      const bool login_packet = p.size() >= 6 && p[0] == 0 && p[1] == 0 && p[2] == 0 && (p[3] == 0 || p[3] == 1);
      const std::string shape = (login_packet ? p.substr(0, 6) : std::string()) + "|" +
                                (p.size() > 4 ? std::to_string(static_cast<unsigned char>(p[4])) : "") + "|" +
                                std::to_string(p.size() / 64);
      if (shapes.insert(shape).second) unique.push_back(p);
    }
    std::size_t i = 0;
    for (const std::string& p : unique) {
      char name[64];
      std::snprintf(name, sizeof name, "/seed-%03zu.bin", i++);
      std::ofstream(std::string(dir) + name, std::ios::binary) << p;
    }
  }
}

TEST(VerseSession, NoHostIsATimeoutNotAHang) {
  // A bound socket that never answers.
  Host silent;
  HostOptions o;
  o.port = 0;
  ASSERT_TRUE(silent.open(o).ok());
  ClientSession s;
  ClientOptions co;
  co.login_timeout_s = 0.5;
  const auto t0 = std::chrono::steady_clock::now();
  const Status st = s.connect("127.0.0.1", silent.port(), co);
  EXPECT_EQ(st.code, Status::Code::Timeout) << st.to_string();
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
}

TEST(VerseSession, ListenAddresses) {
  std::string addr, error;
  std::uint16_t port = 1;
  ASSERT_TRUE(parse_listen_address("0", &addr, &port, &error));
  EXPECT_EQ(addr, "127.0.0.1");
  EXPECT_EQ(port, 0);
  ASSERT_TRUE(parse_listen_address("0.0.0.0:4950", &addr, &port, &error));
  EXPECT_EQ(addr, "0.0.0.0");
  EXPECT_EQ(port, 4950);
  EXPECT_FALSE(parse_listen_address("65536", &addr, &port, &error));
  EXPECT_FALSE(parse_listen_address(":5", &addr, &port, &error));
  EXPECT_FALSE(parse_listen_address("host:x", &addr, &port, &error));
  // Read exactly (std::from_chars): no sign, no trailing text, no wrap.
  for (const char* bad : {"+80", "-1", "80x", "80 ", "", "99999999999999999999", "host:"})
    EXPECT_FALSE(parse_listen_address(bad, &addr, &port, &error)) << bad;
  ASSERT_TRUE(parse_listen_address("65535", &addr, &port, &error));
  EXPECT_EQ(port, 65535);
}

}  // namespace
}  // namespace vgc::verse
