// node_invariants_test.cpp — fuzz/targets/node_invariants.h has teeth: every rule
// passes on real reference states and fails on a state broken in exactly
// that one way.
#include "node_invariants.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

#include "command_text.h"
#include "node.h"

namespace vgc::fuzz {
namespace {

// The spec's cube plus a vertex layer, a polygon layer and two bones.
Node rich_node() {
  std::ifstream in(VGC_SOURCE_DIR "/corpora/examples/cube.vgc");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<Command> cs;
  TextError e;
  EXPECT_TRUE(parse_commands(text, &cs, &e)) << e.to_string();
  std::vector<Command> more;
  EXPECT_TRUE(parse_commands("layer_create 2 \"weight\" VERTEX_UINT32 0 0\n"
                             "layer_create 3 \"crease\" POLYGON_CORNER_UINT32 7 0\n"
                             "bone_create 0 \"weight\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"\n"
                             "bone_create 1 \"weight\" \"\" 0 1 0 0 \"\" 0 0 0 1 \"\"\n",
                             &more, &e))
      << e.to_string();
  cs.insert(cs.end(), more.begin(), more.end());
  Node n;
  for (const Command& c : cs) EXPECT_EQ(n.apply(c), Reason::Ok) << print_command(c);
  return n;
}

struct State {
  std::map<std::uint16_t, Layer> layers;
  std::map<std::uint16_t, Bone> bones;
};

State state_of(const Node& n) { return {n.layers(), n.bones()}; }

void expect_fails(const State& s, const std::string& keyword) {
  const std::string e = check_state(s.layers, s.bones);
  EXPECT_FALSE(e.empty()) << "expected a failure mentioning \"" << keyword << "\"";
  EXPECT_NE(e.find(keyword), std::string::npos) << e;
}

TEST(NodeInvariants, HoldOnReferenceStates) {
  EXPECT_EQ(check_node(Node{}), "");
  EXPECT_EQ(check_node(rich_node()), "");
}

TEST(NodeInvariants, BaseLayersPresentWithFixedNamesAndTypes) {
  State s = state_of(rich_node());
  s.layers.erase(0);
  expect_fails(s, "base layer 0 is missing");
  s = state_of(rich_node());
  s.layers.at(1).name = "poly";
  expect_fails(s, "base layer 1 is named");
  s = state_of(rich_node());
  s.layers.at(0).type = LayerType::VertexReal;
  expect_fails(s, "base layer 0 has the wrong type");
}

TEST(NodeInvariants, LayerIdsTypesAndNames) {
  State s = state_of(rich_node());
  s.layers.at(2).id = 9;
  expect_fails(s, "stored under id 9");
  s = state_of(rich_node());
  s.layers.at(2).type = static_cast<LayerType>(3);
  expect_fails(s, "no valid type");
  s = state_of(rich_node());
  s.layers.at(2).name = "";
  expect_fails(s, "empty name");
  s = state_of(rich_node());
  s.layers.at(2).name = std::string(16, 'n');  // 16 visible bytes: one too many
  expect_fails(s, "over 15 bytes");
  s = state_of(rich_node());
  s.layers.at(2).name = std::string("a\0b", 3);
  expect_fails(s, "with a NUL");
  s = state_of(rich_node());
  s.layers.at(3).name = "weight";
  expect_fails(s, "repeats the name");
}

TEST(NodeInvariants, EveryLayerHoldsExactlyTheLiveIdsOfItsBase) {
  State s = state_of(rich_node());
  s.layers.at(2).slots.erase(5);  // a vertex layer lacks vertex 5
  expect_fails(s, "layer 2 does not hold exactly the live ids");
  s = state_of(rich_node());
  s.layers.at(3).slots[99] = Slot{};  // a polygon layer has a dead polygon
  expect_fails(s, "layer 3 does not hold exactly the live ids");
  s = state_of(rich_node());
  s.layers.at(3).slots.erase(0);
  s.layers.at(3).slots[100] = Slot{};  // same count, other ids
  expect_fails(s, "layer 3 does not hold exactly the live ids");
}

TEST(NodeInvariants, BasePositionsFinite) {
  State s = state_of(rich_node());
  s.layers.at(0).slots.at(3).r[1] = std::numeric_limits<double>::quiet_NaN();
  expect_fails(s, "vertex 3 has a non-finite position");
}

TEST(NodeInvariants, PolygonsHaveThreeOrFourDistinctLiveCorners) {
  State s = state_of(rich_node());
  s.layers.at(1).slots.at(2).u = {3, kNone32, 5, 4};
  expect_fails(s, "polygon 2 has an unused corner 1");
  s = state_of(rich_node());
  s.layers.at(1).slots.at(2).u = {3, 2, 5, 42};
  expect_fails(s, "polygon 2 names vertex 42");
  s = state_of(rich_node());
  s.layers.at(1).slots.at(2).u = {3, 2, 3, 4};
  expect_fails(s, "polygon 2 repeats vertex 3");
  s = state_of(rich_node());
  s.layers.at(1).slots.at(2).u = {3, 2, 3, kNone32};  // a triangle with a repeat
  expect_fails(s, "polygon 2 repeats vertex 3");
}

TEST(NodeInvariants, BonesFormAForest) {
  State s = state_of(rich_node());
  s.bones.at(0).parent = 1;  // 1's parent is 0
  expect_fails(s, "in a parent cycle");
  s = state_of(rich_node());
  s.bones.at(1).parent = 1;  // its own parent
  expect_fails(s, "bone 1 is in a parent cycle");
  s = state_of(rich_node());
  s.bones.at(1).id = 7;
  expect_fails(s, "stored under id 7");
  s = state_of(rich_node());
  s.bones.at(1).weight = "";
  expect_fails(s, "empty weight");
  s = state_of(rich_node());
  s.bones.at(1).rot_label = std::string(16, 'r');
  expect_fails(s, "bone 1 has a name over 15 bytes");
}

TEST(NodeInvariants, RejectedCommandLeavesSnapshotUnchanged) {
  EXPECT_EQ(check_step(false, "a\n", "a\n"), "");
  EXPECT_EQ(check_step(true, "a\n", "b\n"), "");
  EXPECT_NE(check_step(false, "a\n", "b\n"), "");
}

TEST(NodeInvariants, SnapshotDeterministic) {
  EXPECT_EQ(check_deterministic("x", "x"), "");
  EXPECT_NE(check_deterministic("x", "y"), "");
}

}  // namespace
}  // namespace vgc::fuzz

namespace vgc::fuzz {
namespace {

// state_digest sees every part of the state print_snapshot prints.
TEST(StateDigest, ChangesWithEveryPrintedPart) {
  const Node base = rich_node();
  const std::uint64_t d0 = state_digest(base);
  EXPECT_EQ(state_digest(rich_node()), d0);  // deterministic, equal states
  auto changed = [&](const Command& c) {
    Node n = rich_node();
    EXPECT_EQ(n.apply(c), Reason::Ok) << print_command(c);
    return state_digest(n) != d0;
  };
  EXPECT_TRUE(changed(cmd::LayerCreate{2, "weight2", 1, 0, 0}));          // a layer name
  EXPECT_TRUE(changed(cmd::LayerCreate{3, "crease", 128, 7, -0.0}));      // def_real 0 -> -0
  EXPECT_TRUE(changed(cmd::LayerSubscribe{2, 1}));                         // a subscription
  EXPECT_TRUE(changed(cmd::VertexSetUint32{2, 4, 1}));                     // one slot value
  EXPECT_TRUE(changed(cmd::VertexSetXyzReal64{0, 4, -1, -1, 1.0000000000000002}));  // one bit of a position
  EXPECT_TRUE(changed(cmd::CreaseSetEdge{"crease", 0xFFFFFFFF}));          // a crease setting
  cmd::BoneCreate b{1, "weight", "", 0, {1, 0, 0}, "", {0, 0, 0, 1}, "r"};
  EXPECT_TRUE(changed(b));                                                 // a bone label
  EXPECT_EQ(check_step(false, d0, d0), "");
  EXPECT_NE(check_step(false, d0, d0 + 1), "");
  EXPECT_EQ(check_step(true, d0, d0 + 1), "");
}

}  // namespace
}  // namespace vgc::fuzz

namespace vgc::fuzz {
namespace {

std::string touched_fails(const State& s, const Command& c) { return check_touched(s.layers, s.bones, touched_by(c)); }

// check_touched (fuzz_stream's per-command check) finds each rule broken
// where the command touched it.
TEST(TouchedInvariants, FindTheRulesWhereTheCommandTouched) {
  EXPECT_EQ(check_touched(rich_node(), touched_by(cmd::VertexSetUint32{2, 4, 1})), "");
  State s = state_of(rich_node());
  s.layers.at(2).slots.erase(5);  // vertex 5 missing from layer 2: the slot count shows it anywhere
  EXPECT_NE(touched_fails(s, cmd::VertexSetUint32{2, 4, 1}).find("layer 2 does not hold"), std::string::npos);
  s = state_of(rich_node());
  s.layers.at(2).slots.erase(5);
  s.layers.at(2).slots[99] = Slot{};  // same count, other ids: seen where touched
  EXPECT_NE(touched_fails(s, cmd::VertexSetUint32{2, 5, 1}).find("layer 2 does not hold"), std::string::npos);
  EXPECT_NE(touched_fails(s, cmd::LayerSubscribe{2, 1}).find("layer 2 does not hold"), std::string::npos);
  s = state_of(rich_node());
  s.layers.at(0).slots.at(3).r[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(touched_fails(s, cmd::VertexSetXyzReal64{0, 3, 0, 0, 0}).find("non-finite"), std::string::npos);
  s = state_of(rich_node());
  s.layers.at(1).slots.at(2).u = {3, 2, 3, 4};
  EXPECT_NE(touched_fails(s, cmd::PolygonSetCornerUint32{1, 2, {3, 2, 5, 4}}).find("repeats vertex 3"),
            std::string::npos);
  // A vertex delete that left a polygon naming the vertex.
  s = state_of(rich_node());
  for (auto& [id, layer] : s.layers)
    if (is_vertex_layer_type(layer.type)) layer.slots.erase(3);
  EXPECT_NE(touched_fails(s, cmd::VertexDelete{3}).find("names vertex 3, not live"), std::string::npos);
  s = state_of(rich_node());
  s.bones.at(0).parent = 1;
  EXPECT_NE(touched_fails(s, cmd::BoneCreate{0, "weight", "", 1, {}, "", {0, 0, 0, 1}, ""}).find("parent cycle"),
            std::string::npos);
  s = state_of(rich_node());
  s.layers.at(3).name = "weight";  // names: checked for every layer, every command
  EXPECT_NE(touched_fails(s, cmd::VertexSetUint32{2, 4, 1}).find("repeats the name"), std::string::npos);
  // Picking an id: what it touches is unknown, so the whole check runs.
  s = state_of(rich_node());
  s.layers.at(1).slots.at(2).u = {3, 2, 3, 4};
  EXPECT_NE(touched_fails(s, cmd::LayerCreate{kNone16, "x", 1, 0, 0}).find("repeats vertex 3"), std::string::npos);
}

TEST(TouchedInvariants, DigestSeesWhatTheCommandNames) {
  const Node base = rich_node();
  const Touched t = touched_by(cmd::VertexSetUint32{2, 4, 1});
  const std::uint64_t d0 = touched_digest(base, t);
  EXPECT_EQ(touched_digest(rich_node(), t), d0);
  Node n = rich_node();
  ASSERT_EQ(n.apply(cmd::VertexSetXyzReal64{0, 4, 9, 9, 9}), Reason::Ok);  // the same vertex, another layer
  EXPECT_NE(touched_digest(n, t), d0);
  n = rich_node();
  ASSERT_EQ(n.apply(cmd::CreaseSetVertex{"weight", 1}), Reason::Ok);  // crease settings: always
  EXPECT_NE(touched_digest(n, t), d0);
  n = rich_node();
  ASSERT_EQ(n.apply(cmd::LayerSubscribe{3, 1}), Reason::Ok);  // every layer's header: always
  EXPECT_NE(touched_digest(n, t), d0);
  n = rich_node();
  ASSERT_EQ(n.apply(cmd::VertexSetUint32{2, 5, 7}), Reason::Ok);  // another vertex: left to the end-of-input check
  EXPECT_EQ(touched_digest(n, t), d0);
  EXPECT_NE(state_digest(n), state_digest(base));
}

}  // namespace
}  // namespace vgc::fuzz
