// node_rules_test.cpp — the reference node names its decisions
// (reference/node/rule.h): Node::apply records the rules a command applied,
// every snapshot line knows the rule and step that last wrote it
// (line_written), and every refusal records the guard that refused it.
//
// Expected rules are written from docs/commands.md section 4 (the step each
// rule's text names), not copied from program output.
#include <gtest/gtest.h>

#include <vector>

#include "snapshot.h"
#include "test_util.h"

namespace vgc {
namespace {

using test::C;

std::vector<Rule> rules_of(Node& n, const std::string& line, Reason* verdict = nullptr) {
  RuleTrace t;
  const Reason r = n.apply(C(line), &t);
  if (verdict) *verdict = r;
  return std::vector<Rule>(t.begin(), t.end());
}

TEST(NodeRules, ARefusalRecordsItsGuardAndThatNothingChanged) {
  Node n;
  Reason r = Reason::Ok;
  EXPECT_EQ(rules_of(n, "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF", &r),
            (std::vector<Rule>{Rule::PolygonCornerNoVertex, Rule::RejectedChangesNothing}));
  EXPECT_EQ(r, Reason::NoSuchVertex);
  // An alias is read first, then its guard refuses.
  EXPECT_EQ(rules_of(n, "vertex_set_xyz_real64 7 3 1.7976931348623157e308 0 0", &r),
            (std::vector<Rule>{Rule::VertexMaxCoordinateDeletes, Rule::VertexDeleteMissing,
                               Rule::RejectedChangesNothing}));
  EXPECT_EQ(rules_of(n, "layer_create 1 \"x\" VERTEX_UINT32 0 0"),
            (std::vector<Rule>{Rule::LayerCreateBaseId, Rule::RejectedChangesNothing}));
  // Every guard that refuses it is named, the deciding one first: a 16-byte
  // name with a type that is no layer type (the r6 case of issue 17).
  EXPECT_EQ(rules_of(n, "layer_create 3 \"abcdefghijklmnop\" 77 0 0", &r),
            (std::vector<Rule>{Rule::LayerTypeUnknown, Rule::LayerNameInvalid, Rule::RejectedChangesNothing}));
  EXPECT_EQ(r, Reason::BadLayerType);
}

TEST(NodeRules, EachLineKnowsTheRuleThatLastWroteIt) {
  Node n;
  EXPECT_EQ(rules_of(n, "vertex_set_xyz_real64 0 4 1 2 3"), (std::vector<Rule>{Rule::VertexCreate}));
  EXPECT_EQ(line_written(n, "vertex 4 1 2 3")->rule, Rule::VertexCreate);
  EXPECT_EQ(line_written(n, "vertex 4 1 2 3")->step, 1u);
  EXPECT_EQ(line_written(n, "layer 0 \"vertex\" VERTEX_XYZ - - -")->rule, Rule::BaseLayers);
  EXPECT_EQ(line_written(n, "crease_vertex \"\" 0")->rule, Rule::InitialCreases);
  // A new layer over a live vertex: placed by the stack rule, valued by the default.
  EXPECT_EQ(rules_of(n, "layer_create 2 \"u\" VERTEX_UINT32 5 0"),
            (std::vector<Rule>{Rule::LayerCreate, Rule::LayerSlotsForStack, Rule::LayerNewSlotDefault}));
  EXPECT_EQ(line_written(n, "slot 2 4 5")->rule, Rule::LayerNewSlotDefault);
  EXPECT_EQ(line_written(n, "layer 2")->rule, Rule::LayerCreate);
  // A write, then a move that keeps it.
  EXPECT_EQ(rules_of(n, "vertex_set_uint32 2 4 9"), (std::vector<Rule>{Rule::SlotWriteUint}));
  EXPECT_EQ(rules_of(n, "vertex_set_xyz_real64 0 4 0 0 0"),
            (std::vector<Rule>{Rule::VertexMove, Rule::VertexMoveKeepsSlots}));
  EXPECT_EQ(line_written(n, "slot 2 4 9")->rule, Rule::SlotWriteUint);
  EXPECT_EQ(line_written(n, "slot 2 4 9")->step, 3u);
  EXPECT_EQ(line_written(n, "vertex 4 0 0 0")->rule, Rule::VertexMove);
  // A new vertex grows the other layer with its default.
  EXPECT_EQ(rules_of(n, "vertex_set_xyz_real64 0 0xFFFFFFFF 1 1 1"),
            (std::vector<Rule>{Rule::VertexIdPick, Rule::VertexCreate, Rule::ElementGrowsLayers,
                               Rule::ElementNewSlotDefault}));
  EXPECT_EQ(line_written(n, "slot 2 0 5")->rule, Rule::ElementNewSlotDefault);
  // Re-typed into the polygon stack: it leaves the vertex stack.
  EXPECT_EQ(rules_of(n, "layer_create 2 \"u\" POLYGON_FACE_UINT32 0 0"),
            (std::vector<Rule>{Rule::LayerRetype, Rule::LayerRetypeLeavesStack}));
  EXPECT_FALSE(line_written(n, "slot 2 4 9").has_value());
  EXPECT_FALSE(line_written(n, "bone 0").has_value());
}

TEST(NodeRules, DeletingAUsedVertexRecordsTheCascadeAfterTheDelete) {
  Node n;
  for (const char* l : {"vertex_set_xyz_real64 0 0 0 0 0", "vertex_set_xyz_real64 0 1 1 0 0",
                        "vertex_set_xyz_real64 0 2 0 1 0", "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF"})
    ASSERT_EQ(n.apply(C(l)), Reason::Ok);
  EXPECT_EQ(rules_of(n, "vertex_delete 1"), (std::vector<Rule>{Rule::VertexDelete, Rule::PolygonCascadeDelete}));
}

TEST(NodeRules, ApplyingWithoutATraceDecidesTheSame) {
  Node a, b;
  for (const char* l : {"vertex_set_xyz_real64 0 0 0 0 0", "layer_create 0xFFFF \"w\" VERTEX_REAL 0 2",
                        "bone_create 0xFFFF \"w\" \"\" 9 0 0 0 \"\" 0 0 0 1 \"\"", "vertex_delete 5"}) {
    RuleTrace t;
    EXPECT_EQ(a.apply(C(l), &t), b.apply(C(l))) << l;
  }
  EXPECT_EQ(print_snapshot(a), print_snapshot(b));
  EXPECT_EQ(a.step(), 4u);
}

}  // namespace
}  // namespace vgc
