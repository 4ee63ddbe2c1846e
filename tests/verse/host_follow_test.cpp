// host_follow_test.cpp — the host follows its node at the cost of each
// command (verse/followed_node.h, issue 28) and still shows subscribers
// exactly the stored state (docs/verse_wire.md section 7): what a client
// receives is the same whether the host reads the whole snapshot after
// every command or follows the node by its digest; a node whose digest
// differs from the host's prediction (a fault) is read whole; a node that
// lies with the predicted digest is caught by the periodic whole read.
#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "arbitrary_command.h"
#include "document_digest.h"
#include "faulty_node.h"
#include "snapshot.h"
#include "running_host.h"
#include "verse_client.h"
#include "verse_host.h"
#include "wire_pack.h"

namespace vgc::verse {
namespace {

constexpr double kWait = 10.0;  // seconds; loopback answers in milliseconds

// The reference without a digest: the host reads it whole after every command.
class WholeReadNode : public HostedNode {
 public:
  bool apply(const Command& c, std::string*) override {
    node_.apply(c);
    return true;
  }
  bool snapshot(std::string* text, std::string*) override {
    *text = print_snapshot(node_);
    return true;
  }

 private:
  Node node_;
};

// A faulty node. honest: its digest is its own snapshot's; otherwise it
// answers the digest the reference would have (it lies).
class FaultyDigestNode : public HostedNode {
 public:
  FaultyDigestNode(std::vector<int> faults, bool honest) : node_(std::move(faults)), honest_(honest) {}
  bool apply(const Command& c, std::string*) override {
    node_.apply(c);
    reference_.apply(c);
    return true;
  }
  bool snapshot(std::string* text, std::string*) override {
    *text = node_.snapshot();
    return true;
  }
  bool offers_digest() override { return true; }
  bool snapshot_digest(std::uint64_t* digest, std::string*) override {
    *digest = honest_ ? node_.digests().snapshot : document_digest(print_snapshot(reference_));
    return true;
  }

 private:
  faults::FaultyNode node_;
  Node reference_;
  bool honest_;
};

std::vector<int> faults_of(const std::string& list) {
  std::vector<int> faults;
  std::string error;
  EXPECT_TRUE(faults::parse_fault_list(list, &faults, &error)) << error;
  return faults;
}

// A session subscribed to its node and to every layer it hears of (REAL64;
// again after each layer_create it hears, since a re-created layer loses
// its subscribers), recording what the host sends it as text.
struct Watcher {
  ClientSession s;
  std::uint32_t node = 0;
  std::vector<std::string> seen;
  void start(const RunningHost& h) {
    ASSERT_TRUE(s.connect("127.0.0.1", h.host.port(), {}).ok());
    ASSERT_TRUE(s.create_geometry_node(&node, kWait).ok());
    ASSERT_TRUE(s.subscribe_node(node).ok());
    sync();
  }
  void sync() {
    std::vector<WireCommand> got;
    const Status st = s.barrier(node, kWait, &got);
    ASSERT_TRUE(st.ok()) << st.to_string();
    std::vector<std::uint16_t> fresh;
    for (const WireCommand& w : got) {
      const auto* geometry = std::get_if<wire::Geometry>(&w);
      seen.push_back(geometry ? print_command(geometry->command) : describe(w));
      if (const auto* g = std::get_if<wire::Geometry>(&w))
        if (const auto* l = std::get_if<cmd::LayerCreate>(&g->command))
          fresh.push_back(l->layer_id);
    }
    if (fresh.empty()) return;
    for (std::uint16_t l : fresh) ASSERT_TRUE(s.subscribe_layer(node, l, RealFormat::Real64).ok());
    sync();
  }
};

// A mesh with a layer of every type, then commands the generator makes
// for the state so far, as the wire carries them (a name with a NUL is
// not sent).
std::vector<Command> program(std::uint64_t seed, std::size_t n) {
  Node model;
  std::vector<Command> out;
  for (std::uint32_t v = 0; v < 8; ++v) out.push_back(cmd::VertexSetXyzReal64{0, v, double(v), double(v % 3), 0.5});
  for (std::uint32_t p = 0; p < 4; ++p) out.push_back(cmd::PolygonSetCornerUint32{1, p, {p, p + 1, p + 2, p + 3}});
  const std::uint8_t types[] = {0, 1, 2, 128, 129, 130, 131, 132};
  for (std::uint16_t i = 0; i < 8; ++i)
    out.push_back(cmd::LayerCreate{std::uint16_t(2 + i), "l" + std::to_string(i), types[i], 3, 0.5});
  for (const Command& c : out) model.apply(c);
  n += out.size();
  for (std::size_t i = 0; out.size() < n && i < 4 * n; ++i) {
    const Command c = gen::gen_command_for(model)(rc::Random(seed * 100003 + i), 30).value();
    std::string bytes;
    if (!encode_command(wire::Geometry{0, c}, &bytes, BoneForm::Spec).ok()) continue;
    model.apply(c);
    out.push_back(c);
  }
  return out;
}

TEST(VerseHostFollow, ClientsSeeTheSameWhetherTheNodeIsFollowedOrReadWhole) {
  HostOptions whole;
  whole.make_node = [](std::string*) -> std::unique_ptr<HostedNode> { return std::make_unique<WholeReadNode>(); };
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const std::vector<Command> cs = program(seed, 300);
    RunningHost followed, read_whole(whole);
    Watcher a, b;
    a.start(followed);
    b.start(read_whole);
    ASSERT_EQ(a.node, b.node);
    for (std::size_t i = 0; i < cs.size(); ++i) {
      ASSERT_TRUE(a.s.send_geometry(a.node, cs[i]).ok());
      ASSERT_TRUE(b.s.send_geometry(b.node, cs[i]).ok());
      if (i % 3 == 2 || i + 1 == cs.size()) {
        a.sync();
        b.sync();
        ASSERT_EQ(a.seen, b.seen) << "seed " << seed << ", after `" << print_command(cs[i]) << "` (command " << i + 1
                                  << ")";
      }
    }
    EXPECT_GT(a.seen.size(), 60u);
    const Host::Counters fc = followed.host.counters(), wc = read_whole.host.counters();
    EXPECT_EQ(fc.whole_snapshots, 1u) << "only the new node's: the reference is followed by its digest";
    EXPECT_GE(fc.followed_by_digest, cs.size());
    EXPECT_EQ(wc.whole_snapshots, fc.followed_by_digest + 1) << "every geometry command, layer subscriptions included";
    EXPECT_EQ(wc.followed_by_digest, 0u);
  }
}

TEST(VerseHostFollow, ANodeWhoseDigestIsNotTheReferencesIsReadWhole) {
  HostOptions o;
  const std::vector<int> faults = faults_of("polygon-delete-ignored");
  o.make_node = [faults](std::string*) -> std::unique_ptr<HostedNode> {
    return std::make_unique<FaultyDigestNode>(faults, true);
  };
  RunningHost h(o);
  Watcher a;
  a.start(h);
  ASSERT_TRUE(a.s.subscribe_layer(a.node, 1, RealFormat::Real64).ok());
  for (std::uint32_t v = 0; v < 3; ++v)
    ASSERT_TRUE(a.s.send_geometry(a.node, cmd::VertexSetXyzReal64{0, v, double(v), 0, 0}).ok());
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::PolygonSetCornerUint32{1, 0, {0, 1, 2, 0xFFFFFFFFu}}).ok());
  a.sync();
  a.seen.clear();
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::PolygonDelete{0}).ok());
  a.sync();
  for (const std::string& line : a.seen) EXPECT_NE(line.rfind("polygon_delete", 0), 0u) << line;
  EXPECT_EQ(h.host.counters().whole_snapshots, 2u) << "the new node's and the delete's";
  EXPECT_GE(h.host.counters().followed_by_digest, 4u);
}

TEST(VerseHostFollow, ANodeThatLiesWithTheReferencesDigestIsCaughtByTheWholeRead) {
  HostOptions o;
  o.verify_min_commands = 16;
  const std::vector<int> faults = faults_of("polygon-delete-ignored");
  o.make_node = [faults](std::string*) -> std::unique_ptr<HostedNode> {
    return std::make_unique<FaultyDigestNode>(faults, false);
  };
  RunningHost h(o);
  Watcher a;
  a.start(h);
  ASSERT_TRUE(a.s.subscribe_layer(a.node, 1, RealFormat::Real64).ok());
  for (std::uint32_t v = 0; v < 3; ++v)
    ASSERT_TRUE(a.s.send_geometry(a.node, cmd::VertexSetXyzReal64{0, v, double(v), 0, 0}).ok());
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::PolygonSetCornerUint32{1, 0, {0, 1, 2, 0xFFFFFFFFu}}).ok());
  ASSERT_TRUE(a.s.send_geometry(a.node, cmd::PolygonDelete{0}).ok());  // the lie: the polygon stays
  a.sync();
  a.seen.clear();
  for (int i = 0; i < 16; ++i)
    ASSERT_TRUE(a.s.send_geometry(a.node, cmd::VertexSetXyzReal64{0, 2, 2, double(i), 0}).ok());
  a.sync();
  bool polygon_back = false;
  for (const std::string& line : a.seen) polygon_back |= line.rfind("polygon_set_corner_uint32 1 0 ", 0) == 0;
  EXPECT_TRUE(polygon_back) << "within 16 commands the whole read shows the polygon the node kept";
  EXPECT_GE(h.host.counters().whole_snapshots, 2u);
}

}  // namespace
}  // namespace vgc::verse
