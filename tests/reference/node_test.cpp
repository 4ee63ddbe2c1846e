// node_test.cpp — the reference node (reference/node/node.cpp): every command
// kind, every rejection reason, the wire aliases, id picking, cascades,
// layer re-creation, defaults, real32/real64 equivalence, bone cycles,
// storage limits, and atomicity of rejected commands.
//
// Expected values are written from the spec (000 2.6, README) and the
// "Decision:" comments of node.cpp, never copied from program output.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "arbitrary_command.h"
#include "derived_document.h"
#include "test_util.h"

namespace vgc {
namespace {

using test::A;
using test::apply_all;
using test::C;

std::uint64_t bits(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

// ---- a fresh node ------------------------------------------------------------

TEST(Node, FreshNodeHasExactlyTheTwoBaseLayersAndConstantSmoothCreases) {
  Node n;
  ASSERT_EQ(n.layers().size(), 2u);
  EXPECT_EQ(n.find_layer(0)->name, "vertex");
  EXPECT_EQ(n.find_layer(0)->type, LayerType::VertexXyz);
  EXPECT_EQ(n.find_layer(1)->name, "polygon");
  EXPECT_EQ(n.find_layer(1)->type, LayerType::PolygonCornerUint32);
  EXPECT_TRUE(n.vertices().empty());
  EXPECT_TRUE(n.polygons().empty());
  EXPECT_EQ(n.vertex_crease().layer, "");
  EXPECT_EQ(n.vertex_crease().def_crease, 0u);
  EXPECT_EQ(n.edge_crease().layer, "");
  EXPECT_EQ(n.edge_crease().def_crease, 0u);
  EXPECT_TRUE(n.bones().empty());
}

// ---- every command kind, applied ---------------------------------------------

TEST(Node, EveryCommandKindAppliesAtLeastOnce) {
  Node n;
  std::set<std::size_t> kinds;
  const char* script[] = {
      "layer_create 2 \"u\" VERTEX_UINT32 0 0",
      "layer_create 3 \"r\" VERTEX_REAL 0 0",
      "layer_create 4 \"pc\" POLYGON_CORNER_REAL 0 0",
      "layer_create 5 \"f8\" POLYGON_FACE_UINT8 0 0",
      "layer_create 6 \"f32\" POLYGON_FACE_UINT32 0 0",
      "layer_create 7 \"fr\" POLYGON_FACE_REAL 0 0",
      "layer_create 8 \"gone\" VERTEX_REAL 0 0",
      "layer_destroy 8",
      "layer_subscribe 3 REAL32",
      "layer_unsubscribe 3",
      "vertex_set_xyz_real32 0 0 0 0 0",
      "vertex_set_xyz_real64 0 1 1 0 0",
      "vertex_set_xyz_real64 0 2 0 1 0",
      "vertex_set_xyz_real64 0 3 0 0 1",
      "vertex_set_uint32 2 0 9",
      "vertex_set_real64 3 0 0.25",
      "vertex_set_real32 3 1 0.5",
      "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF",
      "polygon_set_corner_real64 4 0 1 2 3 4",
      "polygon_set_corner_real32 4 0 1 2 3 4",
      "polygon_set_face_uint8 5 0 200",
      "polygon_set_face_uint32 6 0 70000",
      "polygon_set_face_real64 7 0 -2.5",
      "polygon_set_face_real32 7 0 -2.5",
      "crease_set_vertex \"u\" 0",
      "crease_set_edge \"\" 0xFFFFFFFF",
      "bone_create 0 \"r\" \"u\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"",
      "bone_create 1 \"r\" \"\" 0 0 0 0 \"\" 0 0 0 1 \"\"",
      "bone_destroy 1",
      "polygon_delete 0",
      "vertex_delete 3",
  };
  for (const char* line : script) {
    const Command c = C(line);
    EXPECT_EQ(reason_name(n.apply(c)), "OK") << line;
    kinds.insert(c.index());
  }
  EXPECT_EQ(kinds.size(), kCommandKinds);
}

TEST(Node, LayerCreateStoresNameTypeDefaultsAndGivesEveryLiveVertexADefaultSlot) {
  Node n;
  apply_all(n, "vertex_set_xyz_real64 0 3 1 2 3\nvertex_set_xyz_real64 0 9 4 5 6\n");
  ASSERT_EQ(A(n, "layer_create 2 \"uv\" VERTEX_REAL 7 0.5"), Reason::Ok);
  const Layer* l = n.find_layer(2);
  ASSERT_NE(l, nullptr);
  EXPECT_EQ(l->name, "uv");
  EXPECT_EQ(l->type, LayerType::VertexReal);
  EXPECT_EQ(l->def_uint, 7u);
  EXPECT_EQ(l->def_real, 0.5);
  EXPECT_FALSE(l->subscription.has_value());
  ASSERT_EQ(l->slots.size(), 2u);
  EXPECT_EQ(l->slots.at(3).r[0], 0.5);
  EXPECT_EQ(l->slots.at(9).r[0], 0.5);
  EXPECT_EQ(n.find_layer_by_name("uv"), l);
}

TEST(Node, PolygonLayerCreatedAfterPolygonsHasASlotPerLivePolygonAndNoneForVertices) {
  Node n;
  apply_all(n, test::kCubeScript);
  ASSERT_EQ(A(n, "layer_create 2 \"c\" POLYGON_CORNER_UINT32 5 0"), Reason::Ok);
  const Layer* l = n.find_layer(2);
  ASSERT_EQ(l->slots.size(), 6u);
  for (const auto& [pid, slot] : l->slots)
    for (int i = 0; i < 4; ++i) EXPECT_EQ(slot.u[i], 5u);
}

TEST(Node, LayerDestroyRemovesTheLayerAndFreesItsName) {
  Node n;
  ASSERT_EQ(A(n, "layer_create 2 \"uv\" VERTEX_REAL 0 0"), Reason::Ok);
  ASSERT_EQ(A(n, "layer_destroy 2"), Reason::Ok);
  EXPECT_EQ(n.find_layer(2), nullptr);
  EXPECT_EQ(n.layers().size(), 2u);
  EXPECT_EQ(A(n, "layer_create 3 \"uv\" VERTEX_REAL 0 0"), Reason::Ok);
}

TEST(Node, SubscribeRecordsTheRealFormatAndUnsubscribeClearsIt) {
  Node n;
  ASSERT_EQ(A(n, "layer_subscribe 0 REAL64"), Reason::Ok);
  EXPECT_EQ(n.find_layer(0)->subscription, RealFormat::Real64);
  ASSERT_EQ(A(n, "layer_subscribe 0 REAL32"), Reason::Ok);
  EXPECT_EQ(n.find_layer(0)->subscription, RealFormat::Real32);
  ASSERT_EQ(A(n, "layer_unsubscribe 0"), Reason::Ok);
  EXPECT_FALSE(n.find_layer(0)->subscription.has_value());
  // Decision: unsubscribing without a subscription is a no-op, not an error.
  EXPECT_EQ(A(n, "layer_unsubscribe 1"), Reason::Ok);
}

TEST(Node, VertexSetXyzCreatesThenMovesAVertex) {
  Node n;
  ASSERT_EQ(A(n, "vertex_set_xyz_real64 0 5 1 2 3"), Reason::Ok);
  ASSERT_EQ(n.vertices().size(), 1u);
  EXPECT_EQ(n.vertices().at(5).r[0], 1.0);
  EXPECT_EQ(n.vertices().at(5).r[1], 2.0);
  EXPECT_EQ(n.vertices().at(5).r[2], 3.0);
  ASSERT_EQ(A(n, "vertex_set_xyz_real64 0 5 -4 0.5 -0"), Reason::Ok);
  ASSERT_EQ(n.vertices().size(), 1u);
  EXPECT_EQ(n.vertices().at(5).r[0], -4.0);
  EXPECT_EQ(n.vertices().at(5).r[1], 0.5);
  EXPECT_EQ(bits(n.vertices().at(5).r[2]), bits(-0.0));
}

TEST(Node, MovingAVertexKeepsItsSlotsInOtherLayers) {
  Node n;
  apply_all(n, "layer_create 2 \"w\" VERTEX_UINT32 0 0\nvertex_set_xyz_real64 0 0 1 1 1\nvertex_set_uint32 2 0 42\n");
  ASSERT_EQ(A(n, "vertex_set_xyz_real64 0 0 2 2 2"), Reason::Ok);
  EXPECT_EQ(n.find_layer(2)->slots.at(0).u[0], 42u);
}

TEST(Node, VertexSetXyzReal32StoresTheFloatWidenedExactly) {
  Node n;
  ASSERT_EQ(n.apply(cmd::VertexSetXyzReal32{0, 0, 0.1f, -0.0f, 1e-45f}), Reason::Ok);
  EXPECT_EQ(bits(n.vertices().at(0).r[0]), bits(double(0.1f)));
  EXPECT_NE(n.vertices().at(0).r[0], 0.1);  // not re-rounded to the nearest double of "0.1"
  EXPECT_EQ(bits(n.vertices().at(0).r[1]), bits(-0.0));
  EXPECT_EQ(n.vertices().at(0).r[2], double(std::numeric_limits<float>::denorm_min()));
}

TEST(Node, NonBaseXyzLayerHoldsAnyValueIncludingNaN) {
  Node n;
  apply_all(n, "vertex_set_xyz_real64 0 0 0 0 0\nlayer_create 2 \"n\" VERTEX_XYZ 0 0\n");
  ASSERT_EQ(A(n, "vertex_set_xyz_real64 2 0 nan(0x7FF0000000000001) inf -inf"), Reason::Ok);
  const Slot& s = n.find_layer(2)->slots.at(0);
  EXPECT_EQ(bits(s.r[0]), 0x7FF0000000000001ull);
  EXPECT_EQ(s.r[1], INFINITY);
  EXPECT_EQ(s.r[2], -INFINITY);
  // ... but writing a non-base XYZ layer never creates a vertex.
  EXPECT_EQ(A(n, "vertex_set_xyz_real64 2 1 0 0 0"), Reason::NoSuchVertex);
}

TEST(Node, VertexDeleteRemovesTheVertexAndItsSlotInEveryVertexLayer) {
  Node n;
  apply_all(n, "vertex_set_xyz_real64 0 0 0 0 0\nvertex_set_xyz_real64 0 1 1 0 0\n"
               "layer_create 2 \"w\" VERTEX_UINT32 0 0\n");
  ASSERT_EQ(A(n, "vertex_delete 0"), Reason::Ok);
  EXPECT_EQ(n.vertices().count(0), 0u);
  EXPECT_EQ(n.vertices().count(1), 1u);
  EXPECT_EQ(n.find_layer(2)->slots.count(0), 0u);
  EXPECT_EQ(n.find_layer(2)->slots.size(), 1u);
  EXPECT_EQ(A(n, "vertex_delete 0"), Reason::NoSuchVertex);
}

TEST(Node, VertexSetUint32Real64Real32WriteOnlyTheAddressedSlot) {
  Node n;
  apply_all(n, "vertex_set_xyz_real64 0 0 0 0 0\nvertex_set_xyz_real64 0 1 1 0 0\n"
               "layer_create 2 \"u\" VERTEX_UINT32 3 0\nlayer_create 3 \"r\" VERTEX_REAL 0 -1\n");
  ASSERT_EQ(A(n, "vertex_set_uint32 2 1 0xFFFFFFFF"), Reason::Ok);
  ASSERT_EQ(A(n, "vertex_set_real64 3 0 0.1"), Reason::Ok);
  EXPECT_EQ(n.find_layer(2)->slots.at(0).u[0], 3u);
  EXPECT_EQ(n.find_layer(2)->slots.at(1).u[0], 0xFFFFFFFFu);
  EXPECT_EQ(n.find_layer(3)->slots.at(0).r[0], 0.1);
  EXPECT_EQ(n.find_layer(3)->slots.at(1).r[0], -1.0);
  ASSERT_EQ(A(n, "vertex_set_real32 3 1 0.1"), Reason::Ok);
  EXPECT_EQ(n.find_layer(3)->slots.at(1).r[0], double(0.1f));
}

TEST(Node, PolygonSetCornerUint32MakesTrianglesAndQuads) {
  Node n;
  apply_all(n, test::kCubeScript);
  ASSERT_EQ(A(n, "polygon_set_corner_uint32 1 9 0 1 2 0xFFFFFFFF"), Reason::Ok);
  const Slot& tri = n.polygons().at(9);
  EXPECT_EQ(tri.u[0], 0u);
  EXPECT_EQ(tri.u[1], 1u);
  EXPECT_EQ(tri.u[2], 2u);
  EXPECT_EQ(tri.u[3], kNone32);
  EXPECT_EQ(n.polygons().at(2).u[0], 3u);  // cube front: 3,2,5,4
  EXPECT_EQ(n.polygons().at(2).u[3], 4u);
  // Re-defining a live polygon replaces its corners.
  ASSERT_EQ(A(n, "polygon_set_corner_uint32 1 9 7 6 5 4"), Reason::Ok);
  EXPECT_EQ(n.polygons().at(9).u[0], 7u);
  EXPECT_EQ(n.polygons().at(9).u[3], 4u);
  EXPECT_EQ(n.polygons().size(), 7u);
}

TEST(Node, CornerUint32OnANonBaseLayerIsDataNotGeometry) {
  Node n;
  apply_all(n, test::kCubeScript);
  ASSERT_EQ(A(n, "layer_create 2 \"c\" POLYGON_CORNER_UINT32 0 0"), Reason::Ok);
  // Repeated values and v0 = 0xFFFFFFFF are fine: these are crease values.
  ASSERT_EQ(A(n, "polygon_set_corner_uint32 2 3 0xFFFFFFFF 0xFFFFFFFF 0 0"), Reason::Ok);
  EXPECT_EQ(n.find_layer(2)->slots.at(3).u[0], kNone32);
  EXPECT_EQ(n.find_layer(2)->slots.at(3).u[2], 0u);
  EXPECT_EQ(n.polygons().size(), 6u);
  EXPECT_EQ(n.polygons().at(3).u[0], 2u);
}

TEST(Node, PolygonCornerRealAndFaceLayersStoreTheirValues) {
  Node n;
  apply_all(n, test::kCubeScript);
  apply_all(n, "layer_create 2 \"pc\" POLYGON_CORNER_REAL 0 0\nlayer_create 3 \"f8\" POLYGON_FACE_UINT8 0 0\n"
               "layer_create 4 \"f32\" POLYGON_FACE_UINT32 0 0\nlayer_create 5 \"fr\" POLYGON_FACE_REAL 0 0\n");
  ASSERT_EQ(A(n, "polygon_set_corner_real64 2 1 0.1 -0 inf 4"), Reason::Ok);
  const Slot& pc = n.find_layer(2)->slots.at(1);
  EXPECT_EQ(pc.r[0], 0.1);
  EXPECT_EQ(bits(pc.r[1]), bits(-0.0));
  EXPECT_EQ(pc.r[2], INFINITY);
  EXPECT_EQ(pc.r[3], 4.0);
  ASSERT_EQ(A(n, "polygon_set_corner_real32 2 2 0.1 1 2 3"), Reason::Ok);
  EXPECT_EQ(n.find_layer(2)->slots.at(2).r[0], double(0.1f));
  ASSERT_EQ(A(n, "polygon_set_face_uint8 3 4 0xFF"), Reason::Ok);
  EXPECT_EQ(n.find_layer(3)->slots.at(4).u[0], 255u);
  ASSERT_EQ(A(n, "polygon_set_face_uint32 4 5 4000000000"), Reason::Ok);
  EXPECT_EQ(n.find_layer(4)->slots.at(5).u[0], 4000000000u);
  ASSERT_EQ(A(n, "polygon_set_face_real64 5 0 0.1"), Reason::Ok);
  EXPECT_EQ(n.find_layer(5)->slots.at(0).r[0], 0.1);
  ASSERT_EQ(A(n, "polygon_set_face_real32 5 1 0.1"), Reason::Ok);
  EXPECT_EQ(n.find_layer(5)->slots.at(1).r[0], double(0.1f));
}

TEST(Node, PolygonDeleteRemovesThePolygonFromEveryPolygonLayerButNoVertex) {
  Node n;
  apply_all(n, test::kCubeScript);
  ASSERT_EQ(A(n, "layer_create 2 \"f\" POLYGON_FACE_UINT32 0 0"), Reason::Ok);
  ASSERT_EQ(A(n, "polygon_delete 2"), Reason::Ok);
  EXPECT_EQ(n.polygons().size(), 5u);
  EXPECT_EQ(n.polygons().count(2), 0u);
  EXPECT_EQ(n.find_layer(2)->slots.count(2), 0u);
  EXPECT_EQ(n.vertices().size(), 8u);
  EXPECT_EQ(A(n, "polygon_delete 2"), Reason::NoSuchPolygon);
}

TEST(Node, CreaseSettingsAreStoredAsSent) {
  Node n;
  ASSERT_EQ(A(n, "crease_set_vertex \"not_yet\" 17"), Reason::Ok);  // layer need not exist
  EXPECT_EQ(n.vertex_crease().layer, "not_yet");
  EXPECT_EQ(n.vertex_crease().def_crease, 17u);
  ASSERT_EQ(A(n, "crease_set_edge \"\" 0xFFFFFFFF"), Reason::Ok);
  EXPECT_EQ(n.edge_crease().layer, "");
  EXPECT_EQ(n.edge_crease().def_crease, 0xFFFFFFFFu);
  EXPECT_EQ(n.vertex_crease().def_crease, 17u);  // independent settings
}

TEST(Node, BoneCreateStoresEveryFieldAndBoneDestroyRemovesIt) {
  Node n;
  apply_all(n, "layer_create 2 \"w\" VERTEX_REAL 0 0\nlayer_create 3 \"ref\" VERTEX_UINT32 0 0\n");
  ASSERT_EQ(A(n, "bone_create 4 \"w\" \"ref\" 9 1 2 3 \"pc\" 0 0 1 0 \"rc\""), Reason::Ok);
  const Bone& b = n.bones().at(4);
  EXPECT_EQ(b.id, 4u);
  EXPECT_EQ(b.weight, "w");
  EXPECT_EQ(b.reference, "ref");
  EXPECT_EQ(b.parent, 9u);  // missing parent stored as sent: a root
  EXPECT_EQ(b.pos[0], 1.0);
  EXPECT_EQ(b.pos[2], 3.0);
  EXPECT_EQ(b.pos_label, "pc");
  EXPECT_EQ(b.rot[2], 1.0);
  EXPECT_EQ(b.rot[3], 0.0);
  EXPECT_EQ(b.rot_label, "rc");
  ASSERT_EQ(A(n, "bone_destroy 4"), Reason::Ok);
  EXPECT_TRUE(n.bones().empty());
  EXPECT_EQ(A(n, "bone_destroy 4"), Reason::NoSuchBone);
}

// ---- every rejection reason ------------------------------------------------------

struct ReasonCase {
  const char* setup;    // script applied first, all OK
  const char* command;  // the command under test
  Reason expected;
};

TEST(Node, EveryReasonCodeIsProducedByACommandThatShouldProduceIt) {
  const char* base =
      "vertex_set_xyz_real64 0 0 0 0 0\nvertex_set_xyz_real64 0 1 1 0 0\nvertex_set_xyz_real64 0 2 0 1 0\n"
      "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF\n"
      "layer_create 2 \"u\" VERTEX_UINT32 0 0\nlayer_create 3 \"r\" VERTEX_REAL 0 0\n"
      "layer_create 4 \"f\" POLYGON_FACE_REAL 0 0\nbone_create 0 \"r\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"\n";
  const ReasonCase cases[] = {
      {"", "vertex_set_xyz_real64 0 0 1 2 3", Reason::Ok},
      {"", "vertex_set_uint32 9 0 1", Reason::NoSuchLayer},
      {"", "layer_destroy 9", Reason::NoSuchLayer},
      {"", "layer_subscribe 9 REAL64", Reason::NoSuchLayer},
      {"", "layer_unsubscribe 9", Reason::NoSuchLayer},
      {"", "polygon_set_face_real64 9 0 1", Reason::NoSuchLayer},
      {"", "layer_create 0 \"v\" VERTEX_XYZ 0 0", Reason::BaseLayer},
      {"", "layer_create 1 \"p\" POLYGON_CORNER_UINT32 0 0", Reason::BaseLayer},
      {"", "layer_destroy 0", Reason::BaseLayer},
      {"", "layer_destroy 1", Reason::BaseLayer},
      {"", "layer_create 1 \"\" VERTEX_XYZ 0 0", Reason::BaseLayer},  // empty name: destroy 1
      {"", "layer_create 2 \"x\" 3 0 0", Reason::BadLayerType},
      {"", "layer_create 2 \"x\" 127 0 0", Reason::BadLayerType},
      {"", "layer_create 2 \"x\" 133 0 0", Reason::BadLayerType},
      {"", "layer_create 2 \"x\" 0xFF 0 0", Reason::BadLayerType},
      {"", "vertex_set_real64 2 0 1", Reason::WrongLayerType},
      {"", "vertex_set_uint32 3 0 1", Reason::WrongLayerType},
      {"", "vertex_set_xyz_real64 2 0 1 1 1", Reason::WrongLayerType},
      {"", "polygon_set_corner_uint32 0 0 0 1 2 3", Reason::WrongLayerType},
      {"", "polygon_set_face_uint32 4 0 1", Reason::WrongLayerType},
      {"", "polygon_set_face_real64 3 0 1", Reason::WrongLayerType},  // vertex layer, face command
      {"", "layer_create 5 \"abcdefghijklmnop\" VERTEX_REAL 0 0", Reason::BadName},  // 16 bytes
      {"", "layer_create 5 \"a\\x00b\" VERTEX_REAL 0 0", Reason::BadName},
      {"", "crease_set_vertex \"abcdefghijklmnop\" 0", Reason::BadName},
      {"", "crease_set_edge \"\\x00\" 0", Reason::BadName},
      {"", "bone_create 1 \"r\" \"\" 0xFFFF 0 0 0 \"abcdefghijklmnop\" 0 0 0 1 \"\"", Reason::BadName},
      {"", "bone_create 1 \"r\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"a\\x00\"", Reason::BadName},
      {"", "layer_create 5 \"u\" VERTEX_REAL 0 0", Reason::NameInUse},
      {"", "layer_create 5 \"vertex\" VERTEX_XYZ 0 0", Reason::NameInUse},
      {"", "layer_create 0xFFFF \"r\" VERTEX_REAL 0 0", Reason::NameInUse},
      {"", "vertex_delete 7", Reason::NoSuchVertex},
      {"", "vertex_set_uint32 2 7 1", Reason::NoSuchVertex},
      {"", "polygon_set_corner_uint32 1 1 0 1 7 0xFFFFFFFF", Reason::NoSuchVertex},
      {"", "polygon_set_corner_uint32 1 1 0 1 2 7", Reason::NoSuchVertex},
      {"", "polygon_delete 5", Reason::NoSuchPolygon},
      {"", "polygon_set_face_real64 4 5 1", Reason::NoSuchPolygon},
      {"", "polygon_set_corner_uint32 1 1 0 1 1 2", Reason::BadPolygon},
      {"", "polygon_set_corner_uint32 1 1 0 1 2 0", Reason::BadPolygon},
      {"", "polygon_set_corner_uint32 1 1 0 0xFFFFFFFF 2 1", Reason::BadPolygon},
      {"", "polygon_set_corner_uint32 1 1 0 1 0xFFFFFFFF 2", Reason::BadPolygon},
      {"", "vertex_set_xyz_real64 0 5 nan 0 0", Reason::BadValue},
      {"", "vertex_set_xyz_real64 0 5 0 inf 0", Reason::BadValue},
      {"", "vertex_set_xyz_real32 0 5 0 0 -inf", Reason::BadValue},
      {"", "bone_create 1 \"r\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 0 \"\"", Reason::BadValue},
      {"", "bone_create 1 \"r\" \"\" 0xFFFF 0 nan 0 \"\" 0 0 0 1 \"\"", Reason::BadValue},
      {"", "bone_create 1 \"r\" \"\" 0xFFFF 0 0 0 \"\" 0 inf 0 1 \"\"", Reason::BadValue},
      {"", "layer_subscribe 3 2", Reason::Ok},     // the unsubscribe alias, not BAD_REAL_FORMAT
      {"", "layer_subscribe 9 0xFF", Reason::NoSuchLayer},  // unsubscribe of no layer
      {"", "bone_destroy 7", Reason::NoSuchBone},
      {"", "bone_create 7 \"\" \"\" 0 0 0 0 \"\" 0 0 0 1 \"\"", Reason::NoSuchBone},  // empty weight: destroy 7
      {"", "bone_create 1 \"r\" \"\" 1 0 0 0 \"\" 0 0 0 1 \"\"", Reason::BoneCycle},  // its own parent
      {"", "bone_create 0 \"r\" \"\" 0 0 0 0 \"\" 0 0 0 1 \"\"", Reason::BoneCycle},
      {"", "bone_create 1 \"missing\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"", Reason::BadWeightLayer},
      {"", "bone_create 1 \"f\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"", Reason::BadWeightLayer},
      {"", "bone_create 1 \"vertex\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"", Reason::BadWeightLayer},
      {"", "bone_create 1 \"u\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"", Reason::Ok},  // UINT32 weights fine
      {"", "bone_create 1 \"r\" \"r\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"", Reason::BadReferenceLayer},
      {"", "bone_create 1 \"r\" \"missing\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"", Reason::BadReferenceLayer},
      {"", "bone_create 1 \"r\" \"u\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"", Reason::Ok},
  };
  std::set<Reason> seen;
  for (const auto& rc : cases) {
    Node n;
    apply_all(n, base);
    apply_all(n, rc.setup);
    const std::string before = print_snapshot(n);
    const Reason got = A(n, rc.command);
    EXPECT_EQ(reason_name(got), reason_name(rc.expected)) << rc.command;
    if (got != Reason::Ok) {
      EXPECT_EQ(print_snapshot(n), before) << rc.command;
    }
    if (got == rc.expected) seen.insert(got);
  }
  // NO_FREE_ID and LIMIT need a full id space or small limits: see below.
  seen.insert(Reason::NoFreeId);
  seen.insert(Reason::Limit);
  // BAD_REAL_FORMAT is no longer produced: a format above REAL64 is the
  // unsubscribe alias (README "Wire aliases"); the name stays for stability.
  seen.insert(Reason::BadRealFormat);
  for (int r = static_cast<int>(Reason::Ok); r <= static_cast<int>(Reason::Limit); ++r)
    EXPECT_TRUE(seen.count(static_cast<Reason>(r))) << "no case for " << reason_name(static_cast<Reason>(r));
}

TEST(Node, NoFreeIdWhenEveryBoneIdIsTaken) {
  Node n;
  ASSERT_EQ(A(n, "layer_create 2 \"w\" VERTEX_REAL 0 0"), Reason::Ok);
  cmd::BoneCreate b;
  b.weight = "w";
  b.parent = kNone16;
  for (std::uint32_t id = 0; id <= 0xFFFE; ++id) {
    b.bone_id = static_cast<std::uint16_t>(id);
    ASSERT_EQ(n.apply(b), Reason::Ok) << id;
  }
  b.bone_id = kNone16;
  EXPECT_EQ(n.apply(b), Reason::NoFreeId);
  EXPECT_EQ(n.bones().size(), 0xFFFFu);
  ASSERT_EQ(A(n, "bone_destroy 300"), Reason::Ok);
  EXPECT_EQ(n.apply(b), Reason::Ok);
  EXPECT_EQ(n.bones().count(300), 1u);
}

TEST(Node, LimitRejectsNewVerticesPolygonsAndLayersPastTheCellBudget) {
  Node n(NodeLimits{4});
  for (int i = 0; i < 4; ++i) ASSERT_EQ(n.apply(cmd::VertexSetXyzReal64{0, std::uint32_t(i), 0, 0, double(i)}), Reason::Ok);
  std::string before = print_snapshot(n);
  EXPECT_EQ(A(n, "vertex_set_xyz_real64 0 4 0 0 0"), Reason::Limit);
  EXPECT_EQ(print_snapshot(n), before);
  EXPECT_EQ(A(n, "vertex_set_xyz_real64 0 3 9 9 9"), Reason::Ok);  // moving costs nothing
  // A second vertex layer would need 2 x 4 cells.
  before = print_snapshot(n);
  EXPECT_EQ(A(n, "layer_create 2 \"w\" VERTEX_UINT32 0 0"), Reason::Limit);
  EXPECT_EQ(print_snapshot(n), before);
  // The polygon stack has its own budget: 4 polygons in 1 layer, or 2 in 2.
  EXPECT_EQ(A(n, "layer_create 2 \"f\" POLYGON_FACE_UINT8 0 0"), Reason::Ok);
  EXPECT_EQ(A(n, "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF"), Reason::Ok);
  EXPECT_EQ(A(n, "polygon_set_corner_uint32 1 1 0 1 3 0xFFFFFFFF"), Reason::Ok);
  EXPECT_EQ(A(n, "polygon_set_corner_uint32 1 2 1 2 3 0xFFFFFFFF"), Reason::Limit);
  EXPECT_EQ(n.polygons().size(), 2u);
  // Re-typing layer 2 into the vertex stack would need 2 x 4 vertex cells.
  EXPECT_EQ(A(n, "layer_create 2 \"f\" VERTEX_UINT32 0 0"), Reason::Limit);
  EXPECT_EQ(n.find_layer(2)->type, LayerType::PolygonFaceUint8);
}

TEST(Node, AnIdOfFourBillionCostsOneSlotNotFourBillion) {
  Node n;
  ASSERT_EQ(A(n, "layer_create 2 \"w\" VERTEX_UINT32 0 0"), Reason::Ok);
  ASSERT_EQ(A(n, "vertex_set_xyz_real64 0 4000000000 1 2 3"), Reason::Ok);
  EXPECT_EQ(n.vertices().size(), 1u);
  EXPECT_EQ(n.vertices().begin()->first, 4000000000u);
  EXPECT_EQ(n.find_layer(2)->slots.size(), 1u);
  ASSERT_EQ(A(n, "vertex_set_xyz_real64 0 0xFFFFFFFE 1 2 3"), Reason::Ok);
  EXPECT_EQ(n.vertices().size(), 2u);
}

// ---- wire aliases ------------------------------------------------------------------

TEST(Node, LayerCreateWithEmptyNameDestroysTheLayer) {
  Node n;
  ASSERT_EQ(A(n, "layer_create 2 \"uv\" VERTEX_REAL 0 0"), Reason::Ok);
  ASSERT_EQ(A(n, "layer_create 2 \"\" POLYGON_FACE_REAL 5 5"), Reason::Ok);
  EXPECT_EQ(n.find_layer(2), nullptr);
  EXPECT_EQ(A(n, "layer_create 2 \"\" VERTEX_REAL 0 0"), Reason::NoSuchLayer);
  EXPECT_EQ(A(n, "layer_create 0 \"\" 99 0 0"), Reason::BaseLayer);  // type not judged: it is a destroy
}

TEST(Node, FltMaxInAnyReal32CoordinateDeletesTheVertex) {
  for (int axis = 0; axis < 3; ++axis) {
    Node n;
    apply_all(n, "vertex_set_xyz_real64 0 3 1 1 1\nvertex_set_xyz_real64 0 4 1 1 1\n");
    cmd::VertexSetXyzReal32 c{0, 3, 0, 0, 0};
    (axis == 0 ? c.x : axis == 1 ? c.y : c.z) = FLT_MAX;
    EXPECT_EQ(n.apply(c), Reason::Ok) << axis;
    EXPECT_EQ(n.vertices().count(3), 0u) << axis;
    EXPECT_EQ(n.vertices().count(4), 1u) << axis;
    EXPECT_EQ(n.apply(c), Reason::NoSuchVertex) << axis;
  }
  Node n;  // -FLT_MAX is an ordinary (finite) coordinate
  ASSERT_EQ(n.apply(cmd::VertexSetXyzReal32{0, 3, -FLT_MAX, 0, 0}), Reason::Ok);
  EXPECT_EQ(n.vertices().at(3).r[0], double(-FLT_MAX));
}

TEST(Node, DblMaxInAnyReal64CoordinateDeletesTheVertexWhateverTheLayer) {
  for (int axis = 0; axis < 3; ++axis) {
    Node n;
    apply_all(n, "vertex_set_xyz_real64 0 3 1 1 1\n");
    cmd::VertexSetXyzReal64 c{7, 3, 0, 0, 0};  // the layer id plays no part in the alias
    (axis == 0 ? c.x : axis == 1 ? c.y : c.z) = DBL_MAX;
    EXPECT_EQ(n.apply(c), Reason::Ok) << axis;
    EXPECT_TRUE(n.vertices().empty()) << axis;
  }
  Node n;  // FLT_MAX widened is not DBL_MAX: a real64 write of it is a position
  ASSERT_EQ(n.apply(cmd::VertexSetXyzReal64{0, 3, double(FLT_MAX), 0, 0}), Reason::Ok);
  EXPECT_EQ(n.vertices().at(3).r[0], double(FLT_MAX));
}

TEST(Node, CornerV0NoneOnLayerOneDeletesThePolygon) {
  Node n;
  apply_all(n, test::kCubeScript);
  ASSERT_EQ(A(n, "polygon_set_corner_uint32 1 4 0xFFFFFFFF 1 2 3"), Reason::Ok);
  EXPECT_EQ(n.polygons().count(4), 0u);
  EXPECT_EQ(n.polygons().size(), 5u);
  EXPECT_EQ(A(n, "polygon_set_corner_uint32 1 4 0xFFFFFFFF 0 0 0"), Reason::NoSuchPolygon);
}

TEST(Node, BoneCreateWithEmptyWeightDestroysTheBone) {
  Node n;
  apply_all(n, "layer_create 2 \"w\" VERTEX_REAL 0 0\nbone_create 3 \"w\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"\n");
  ASSERT_EQ(A(n, "bone_create 3 \"\" \"junk\" 0 nan 0 0 \"\" 0 0 0 0 \"\""), Reason::Ok);
  EXPECT_TRUE(n.bones().empty());
}

TEST(Node, LayerSubscribeWithAFormatAboveReal64UnsubscribesTheLayer) {
  // README: "a real_format above REAL64 (any value > 1) means g_layer_unsubscribe(layer_id)".
  for (const char* format : {"2", "7", "0xFF"}) {
    Node n;
    ASSERT_EQ(A(n, "layer_subscribe 0 REAL64"), Reason::Ok);
    EXPECT_EQ(A(n, std::string("layer_subscribe 0 ") + format), Reason::Ok) << format;
    EXPECT_FALSE(n.find_layer(0)->subscription.has_value()) << format;
    EXPECT_EQ(A(n, std::string("layer_subscribe 0 ") + format), Reason::Ok) << format;  // as unsubscribe: no-op
    EXPECT_EQ(A(n, std::string("layer_subscribe 9 ") + format), Reason::NoSuchLayer) << format;
  }
}

// README "Wire aliases": "A host reached over the wire cannot tell the two
// forms apart, so a suite must not expect different answers for them." Each
// aliased form gives exactly the verdict and the state of the command it
// aliases, on a node with layers of every stack, a subscription and a bone,
// whatever the other fields hold.
TEST(Node, EveryAliasedFormAnswersAndActsExactlyAsTheCommandItAliases) {
  const std::string setup = std::string(test::kCubeScript) +
                            "layer_create 2 \"u\" VERTEX_UINT32 7 0\n"
                            "layer_create 3 \"r\" VERTEX_REAL 0 0.5\n"
                            "layer_subscribe 3 REAL64\n"
                            "layer_create 4 \"xyz\" VERTEX_XYZ 0 2\n"
                            "layer_create 5 \"f\" POLYGON_FACE_REAL 0 1\n"
                            "layer_create 6 \"c\" POLYGON_CORNER_UINT32 3 0\n"
                            "bone_create 3 \"r\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"\n";
  struct Pair {
    const char* alias;
    const char* plain;
  };
  const Pair pairs[] = {
      // layer_subscribe with a format > REAL64 = layer_unsubscribe
      {"layer_subscribe 3 2", "layer_unsubscribe 3"},
      {"layer_subscribe 3 0xFF", "layer_unsubscribe 3"},
      {"layer_subscribe 2 9", "layer_unsubscribe 2"},
      {"layer_subscribe 0 2", "layer_unsubscribe 0"},
      {"layer_subscribe 9 2", "layer_unsubscribe 9"},
      {"layer_subscribe 0xFFFF 0xFF", "layer_unsubscribe 0xFFFF"},
      // layer_create with an empty name = layer_destroy (type and defaults ignored)
      {"layer_create 3 \"\" POLYGON_FACE_REAL 1 2", "layer_destroy 3"},
      {"layer_create 6 \"\" 99 0 nan", "layer_destroy 6"},
      {"layer_create 0 \"\" VERTEX_XYZ 0 0", "layer_destroy 0"},
      {"layer_create 1 \"\" 200 0 0", "layer_destroy 1"},
      {"layer_create 9 \"\" VERTEX_REAL 0 0", "layer_destroy 9"},
      {"layer_create 0xFFFF \"\" VERTEX_REAL 0 0", "layer_destroy 0xFFFF"},
      // vertex_set_xyz_real32/64 with a coordinate FLT_MAX / DBL_MAX = vertex_delete, whatever the layer
      {"vertex_set_xyz_real32 0 2 3.4028235e+38 0 0", "vertex_delete 2"},
      {"vertex_set_xyz_real32 0 2 0 3.4028235e+38 nan", "vertex_delete 2"},
      {"vertex_set_xyz_real32 4 2 0 0 3.4028235e+38", "vertex_delete 2"},   // a non-base XYZ layer
      {"vertex_set_xyz_real32 2 2 3.4028235e+38 0 0", "vertex_delete 2"},   // a VERTEX_UINT32 layer
      {"vertex_set_xyz_real32 9 2 3.4028235e+38 0 0", "vertex_delete 2"},   // no such layer
      {"vertex_set_xyz_real32 0 99 3.4028235e+38 0 0", "vertex_delete 99"}, // no such vertex
      {"vertex_set_xyz_real32 0 0xFFFFFFFF 3.4028235e+38 0 0", "vertex_delete 0xFFFFFFFF"},
      {"vertex_set_xyz_real64 0 5 1.7976931348623157e+308 0 0", "vertex_delete 5"},
      {"vertex_set_xyz_real64 0 5 inf 1.7976931348623157e+308 0", "vertex_delete 5"},
      {"vertex_set_xyz_real64 4 5 0 0 1.7976931348623157e+308", "vertex_delete 5"},
      {"vertex_set_xyz_real64 5 5 0 0 1.7976931348623157e+308", "vertex_delete 5"},  // a polygon layer
      {"vertex_set_xyz_real64 0xFFFF 5 1.7976931348623157e+308 0 0", "vertex_delete 5"},
      {"vertex_set_xyz_real64 0 77 1.7976931348623157e+308 0 0", "vertex_delete 77"},
      // polygon_set_corner_uint32 on layer 1 with v0 = 0xFFFFFFFF = polygon_delete
      {"polygon_set_corner_uint32 1 3 0xFFFFFFFF 1 2 3", "polygon_delete 3"},
      {"polygon_set_corner_uint32 1 3 0xFFFFFFFF 0xFFFFFFFF 0xFFFFFFFF 0xFFFFFFFF", "polygon_delete 3"},
      {"polygon_set_corner_uint32 1 3 0xFFFFFFFF 9 9 9", "polygon_delete 3"},
      {"polygon_set_corner_uint32 1 99 0xFFFFFFFF 0 1 2", "polygon_delete 99"},
      {"polygon_set_corner_uint32 1 0xFFFFFFFF 0xFFFFFFFF 0 1 2", "polygon_delete 0xFFFFFFFF"},
      // bone_create with an empty weight name = bone_destroy (all other fields ignored)
      {"bone_create 3 \"\" \"junk\" 0 nan 0 0 \"\" 0 0 0 0 \"\"", "bone_destroy 3"},
      {"bone_create 3 \"\" \"abcdefghijklmnopq\" 3 0 0 0 \"\" 0 0 0 1 \"\"", "bone_destroy 3"},
      {"bone_create 9 \"\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"", "bone_destroy 9"},
      {"bone_create 0xFFFF \"\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"", "bone_destroy 0xFFFF"},
  };
  for (const Pair& p : pairs) {
    Node a, b;
    apply_all(a, setup);
    apply_all(b, setup);
    const Reason ra = A(a, p.alias), rb = A(b, p.plain);
    EXPECT_EQ(reason_name(ra), reason_name(rb)) << p.alias << " vs " << p.plain;
    EXPECT_EQ(print_snapshot(a), print_snapshot(b)) << p.alias << " vs " << p.plain;
    EXPECT_EQ(print_derived(a), print_derived(b)) << p.alias << " vs " << p.plain;
  }
  // Not aliases: the same conditions elsewhere are ordinary data.
  Node n;
  apply_all(n, setup);
  EXPECT_EQ(A(n, "polygon_set_corner_uint32 6 3 0xFFFFFFFF 1 2 3"), Reason::Ok);  // corner layer other than 1
  EXPECT_EQ(n.polygons().count(3), 1u);
  EXPECT_EQ(A(n, "vertex_set_xyz_real32 0 2 -3.4028235e+38 0 0"), Reason::Ok);   // -FLT_MAX
  EXPECT_EQ(A(n, "vertex_set_xyz_real64 0 2 3.4028234663852886e+38 0 0"), Reason::Ok);  // FLT_MAX widened
  EXPECT_EQ(n.vertices().count(2), 1u);
  EXPECT_EQ(A(n, "layer_subscribe 3 REAL32"), Reason::Ok);
  EXPECT_EQ(n.find_layer(3)->subscription, RealFormat::Real32);
}

// ---- picking ids -------------------------------------------------------------------

TEST(Node, AllOnesVertexIdPicksTheLowestFreeId) {
  Node n;
  apply_all(n, "vertex_set_xyz_real64 0 0 0 0 0\nvertex_set_xyz_real64 0 1 0 0 0\nvertex_set_xyz_real64 0 3 0 0 0\n");
  ASSERT_EQ(A(n, "vertex_set_xyz_real64 0 0xFFFFFFFF 5 5 5"), Reason::Ok);
  EXPECT_EQ(n.vertices().at(2).r[0], 5.0);
  ASSERT_EQ(A(n, "vertex_set_xyz_real64 0 0xFFFFFFFF 6 6 6"), Reason::Ok);
  EXPECT_EQ(n.vertices().at(4).r[0], 6.0);
  EXPECT_EQ(n.vertices().size(), 5u);
}

TEST(Node, AllOnesPolygonIdPicksTheLowestFreeId) {
  Node n;
  apply_all(n, test::kCubeScript);
  ASSERT_EQ(A(n, "polygon_delete 1"), Reason::Ok);
  ASSERT_EQ(A(n, "polygon_set_corner_uint32 1 0xFFFFFFFF 4 5 6 7"), Reason::Ok);
  EXPECT_EQ(n.polygons().at(1).u[0], 4u);
  ASSERT_EQ(A(n, "polygon_set_corner_uint32 1 0xFFFFFFFF 0 1 2 0xFFFFFFFF"), Reason::Ok);
  EXPECT_EQ(n.polygons().at(6).u[3], kNone32);
}

TEST(Node, AllOnesLayerIdPicksTheLowestFreeIdFromTwo) {
  Node n;
  apply_all(n, "layer_create 3 \"a\" VERTEX_REAL 0 0\n");
  ASSERT_EQ(A(n, "layer_create 0xFFFF \"b\" VERTEX_REAL 0 0"), Reason::Ok);
  EXPECT_EQ(n.find_layer(2)->name, "b");
  ASSERT_EQ(A(n, "layer_create 0xFFFF \"c\" POLYGON_FACE_UINT8 0 0"), Reason::Ok);
  EXPECT_EQ(n.find_layer(4)->name, "c");
}

TEST(Node, AllOnesBoneIdPicksTheLowestFreeIdFromZero) {
  Node n;
  apply_all(n, "layer_create 2 \"w\" VERTEX_REAL 0 0\nbone_create 0 \"w\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"\n"
               "bone_create 2 \"w\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"\n");
  ASSERT_EQ(A(n, "bone_create 0xFFFF \"w\" \"\" 0 7 0 0 \"\" 0 0 0 1 \"\""), Reason::Ok);
  EXPECT_EQ(n.bones().at(1).pos[0], 7.0);
  EXPECT_EQ(n.bones().at(1).parent, 0u);
}

// ---- cascades, re-creation, defaults ---------------------------------------------

TEST(Node, VertexDeleteDeletesEveryPolygonUsingIt) {
  Node n;
  apply_all(n, test::kCubeScript);
  ASSERT_EQ(A(n, "layer_create 2 \"f\" POLYGON_FACE_UINT32 0 0"), Reason::Ok);
  ASSERT_EQ(A(n, "vertex_delete 0"), Reason::Ok);
  // Vertex 0 is in top (0), back (4) and left (5).
  std::set<std::uint32_t> left;
  for (const auto& [pid, s] : n.polygons()) left.insert(pid);
  EXPECT_EQ(left, (std::set<std::uint32_t>{1, 2, 3}));
  EXPECT_EQ(n.find_layer(2)->slots.size(), 3u);
  EXPECT_EQ(n.find_layer(2)->slots.count(4), 0u);
  EXPECT_EQ(n.vertices().size(), 7u);
}

TEST(Node, VertexDeleteCascadeReachesTrianglesByAnyCorner) {
  Node n;
  apply_all(n, "vertex_set_xyz_real64 0 0 0 0 0\nvertex_set_xyz_real64 0 1 1 0 0\nvertex_set_xyz_real64 0 2 0 1 0\n"
               "vertex_set_xyz_real64 0 3 1 1 0\npolygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF\n"
               "polygon_set_corner_uint32 1 1 1 3 2 0xFFFFFFFF\n");
  ASSERT_EQ(A(n, "vertex_delete 2"), Reason::Ok);  // the third corner of both
  EXPECT_TRUE(n.polygons().empty());
}

TEST(Node, RecreatingALayerWithItsOwnTypeKeepsDataAndSubscription) {
  Node n;
  apply_all(n, "vertex_set_xyz_real64 0 0 0 0 0\nlayer_create 2 \"a\" VERTEX_UINT32 1 0\nvertex_set_uint32 2 0 42\n"
               "layer_subscribe 2 REAL64\n");
  ASSERT_EQ(A(n, "layer_create 2 \"b\" VERTEX_UINT32 9 0.5"), Reason::Ok);
  const Layer* l = n.find_layer(2);
  EXPECT_EQ(l->name, "b");
  EXPECT_EQ(l->def_uint, 9u);
  EXPECT_EQ(l->def_real, 0.5);
  EXPECT_EQ(l->slots.at(0).u[0], 42u);
  EXPECT_EQ(l->subscription, RealFormat::Real64);
  EXPECT_EQ(n.find_layer_by_name("a"), nullptr);
  // New elements take the new default.
  ASSERT_EQ(A(n, "vertex_set_xyz_real64 0 1 0 0 0"), Reason::Ok);
  EXPECT_EQ(l->slots.at(1).u[0], 9u);
}

TEST(Node, RecreatingALayerWithAnotherTypeResetsItsData) {
  Node n;
  apply_all(n, test::kCubeScript);
  apply_all(n, "layer_create 2 \"a\" VERTEX_UINT32 1 0\nvertex_set_uint32 2 0 42\nlayer_subscribe 2 REAL32\n");
  // Same stack, other type.
  ASSERT_EQ(A(n, "layer_create 2 \"a\" VERTEX_REAL 0 2.5"), Reason::Ok);
  EXPECT_EQ(n.find_layer(2)->type, LayerType::VertexReal);
  EXPECT_EQ(n.find_layer(2)->slots.size(), 8u);
  EXPECT_EQ(n.find_layer(2)->slots.at(0).r[0], 2.5);
  EXPECT_FALSE(n.find_layer(2)->subscription.has_value());
  // Other stack: one slot per polygon now.
  ASSERT_EQ(A(n, "layer_create 2 \"a\" POLYGON_FACE_UINT8 0x1FF 0"), Reason::Ok);
  EXPECT_EQ(n.find_layer(2)->slots.size(), 6u);
  EXPECT_EQ(n.find_layer(2)->slots.at(5).u[0], 0xFFu);
}

TEST(Node, NewSlotsTakeTheLayerDefaultAndFaceUint8KeepsTheLow8Bits) {
  Node n;
  apply_all(n, "layer_create 2 \"u\" VERTEX_UINT32 0x12345678 0.5\nlayer_create 3 \"r\" VERTEX_REAL 7 -0.25\n"
               "layer_create 4 \"x\" VERTEX_XYZ 0 3\nlayer_create 5 \"f8\" POLYGON_FACE_UINT8 0x1234 0\n"
               "layer_create 6 \"c\" POLYGON_CORNER_UINT32 0xFFFFFFFF 0\nlayer_create 7 \"cr\" POLYGON_CORNER_REAL 0 1.5\n"
               "layer_create 8 \"fu\" POLYGON_FACE_UINT32 77 0\nlayer_create 9 \"fr\" POLYGON_FACE_REAL 0 nan\n");
  apply_all(n, "vertex_set_xyz_real64 0 0 0 0 0\nvertex_set_xyz_real64 0 1 1 0 0\nvertex_set_xyz_real64 0 2 0 1 0\n"
               "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF\n");
  EXPECT_EQ(n.find_layer(2)->slots.at(1).u[0], 0x12345678u);
  EXPECT_EQ(n.find_layer(3)->slots.at(2).r[0], -0.25);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(n.find_layer(4)->slots.at(0).r[i], 3.0);
  EXPECT_EQ(n.find_layer(5)->slots.at(0).u[0], 0x34u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(n.find_layer(6)->slots.at(0).u[i], 0xFFFFFFFFu);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(n.find_layer(7)->slots.at(0).r[i], 1.5);
  EXPECT_EQ(n.find_layer(8)->slots.at(0).u[0], 77u);
  EXPECT_EQ(bits(n.find_layer(9)->slots.at(0).r[0]), 0x7FF8000000000000ull);
  // The default is per layer: a vertex deleted and re-created gets it again.
  ASSERT_EQ(A(n, "vertex_set_uint32 2 1 5"), Reason::Ok);
  ASSERT_EQ(A(n, "vertex_delete 1"), Reason::Ok);
  ASSERT_EQ(A(n, "vertex_set_xyz_real64 0 1 1 0 0"), Reason::Ok);
  EXPECT_EQ(n.find_layer(2)->slots.at(1).u[0], 0x12345678u);
}

// ---- real32 writes are real64 writes of the widened value ------------------------

RC_GTEST_PROP(NodeProperty, Real32WritesEqualReal64WritesOfTheSameValue, ()) {
  const float f = *gen::gen_f32_any();
  const float g = *gen::gen_f32_any();
  const float h = *gen::gen_f32_any();
  RC_PRE(f != FLT_MAX && g != FLT_MAX && h != FLT_MAX);  // the real32 delete alias
  const char* setup =
      "vertex_set_xyz_real64 0 0 0 0 0\nvertex_set_xyz_real64 0 1 1 0 0\nvertex_set_xyz_real64 0 2 0 1 0\n"
      "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF\nlayer_create 2 \"r\" VERTEX_REAL 0 0\n"
      "layer_create 3 \"cr\" POLYGON_CORNER_REAL 0 0\nlayer_create 4 \"fr\" POLYGON_FACE_REAL 0 0\n"
      "layer_create 5 \"x\" VERTEX_XYZ 0 0\n";
  Node a, b;
  std::vector<Command> cs;
  TextError e;
  RC_ASSERT(parse_commands(setup, &cs, &e));
  for (const auto& c : cs) {
    RC_ASSERT(a.apply(c) == Reason::Ok);
    RC_ASSERT(b.apply(c) == Reason::Ok);
  }
  const double F = f, G = g, H = h;
  const std::pair<Command, Command> pairs[] = {
      {cmd::VertexSetXyzReal32{0, 1, f, g, h}, cmd::VertexSetXyzReal64{0, 1, F, G, H}},
      {cmd::VertexSetXyzReal32{0, 7, f, g, h}, cmd::VertexSetXyzReal64{0, 7, F, G, H}},
      {cmd::VertexSetXyzReal32{5, 0, f, g, h}, cmd::VertexSetXyzReal64{5, 0, F, G, H}},
      {cmd::VertexSetReal32{2, 0, f}, cmd::VertexSetReal64{2, 0, F}},
      {cmd::PolygonSetCornerReal32{3, 0, {f, g, h, f}}, cmd::PolygonSetCornerReal64{3, 0, {F, G, H, F}}},
      {cmd::PolygonSetFaceReal32{4, 0, g}, cmd::PolygonSetFaceReal64{4, 0, G}},
  };
  for (const auto& [c32, c64] : pairs) {
    RC_ASSERT(a.apply(c32) == b.apply(c64));
    RC_ASSERT(print_snapshot(a) == print_snapshot(b));
  }
}

// ---- bones ---------------------------------------------------------------------------

constexpr const char* kBoneLayer = "layer_create 2 \"w\" VERTEX_REAL 0 0\n";

std::string bone(int id, int parent) {
  return "bone_create " + std::to_string(id) + " \"w\" \"\" " + std::to_string(parent) +
         " 0 0 0 \"\" 0 0 0 1 \"\"";
}

TEST(Node, BoneThatWouldBeItsOwnAncestorIsRejected) {
  Node n;
  apply_all(n, kBoneLayer);
  EXPECT_EQ(A(n, bone(0, 0)), Reason::BoneCycle);
  ASSERT_EQ(A(n, bone(0, 1000)), Reason::Ok);
  ASSERT_EQ(A(n, bone(1, 0)), Reason::Ok);
  ASSERT_EQ(A(n, bone(2, 1)), Reason::Ok);
  const std::string before = print_snapshot(n);
  EXPECT_EQ(A(n, bone(0, 2)), Reason::BoneCycle);  // 0 -> 2 -> 1 -> 0
  EXPECT_EQ(A(n, bone(1, 2)), Reason::BoneCycle);  // 1 -> 2 -> 1
  EXPECT_EQ(print_snapshot(n), before);
  EXPECT_EQ(n.bones().at(0).parent, 1000u);
  EXPECT_EQ(A(n, bone(2, 0)), Reason::Ok);  // re-parenting without a cycle is fine
}

TEST(Node, ParentMissingAtCreationThatIsCreatedLaterStillCannotCloseACycle) {
  Node n;
  apply_all(n, kBoneLayer);
  ASSERT_EQ(A(n, bone(1, 2)), Reason::Ok);   // parent 2 missing: 1 is a root for now
  EXPECT_EQ(A(n, bone(2, 1)), Reason::BoneCycle);  // 2 -> 1 -> 2
  EXPECT_EQ(n.bones().count(2), 0u);
  ASSERT_EQ(A(n, bone(2, 5)), Reason::Ok);   // 2 appears: 1 is now its child
  ASSERT_EQ(A(n, bone(3, 1)), Reason::Ok);
  EXPECT_EQ(A(n, bone(2, 3)), Reason::BoneCycle);  // 2 -> 3 -> 1 -> 2
  EXPECT_EQ(n.bones().at(2).parent, 5u);
}

TEST(Node, DestroyedBoneLeavesChildLinksAndReattachesWhenRecreated) {
  Node n;
  apply_all(n, kBoneLayer);
  apply_all(n, bone(0, 0xFFFF) + "\n" + bone(1, 0) + "\n");
  ASSERT_EQ(A(n, "bone_destroy 0"), Reason::Ok);
  EXPECT_EQ(n.bones().size(), 1u);
  EXPECT_EQ(n.bones().at(1).parent, 0u);  // the link is kept
  EXPECT_EQ(A(n, bone(0, 1)), Reason::BoneCycle);  // 0 -> 1 -> 0 via the kept link
  ASSERT_EQ(A(n, bone(0, 0xFFFF)), Reason::Ok);
  EXPECT_EQ(n.bones().at(1).parent, 0u);
}

TEST(Node, BoneWeightLayerIsCheckedOnlyAtCreation) {
  Node n;
  apply_all(n, kBoneLayer);
  ASSERT_EQ(A(n, bone(0, 0xFFFF)), Reason::Ok);
  ASSERT_EQ(A(n, "layer_destroy 2"), Reason::Ok);
  EXPECT_EQ(n.bones().at(0).weight, "w");
  EXPECT_EQ(A(n, bone(1, 0)), Reason::BadWeightLayer);
}

// ---- check order (docs/commands.md lists it) --------------------------------------

TEST(Node, ChecksAreMadeInTheDocumentedOrder) {
  Node n;
  apply_all(n, "layer_create 2 \"u\" VERTEX_UINT32 0 0\n");
  // layer_create: base layer before type before name before name clash.
  EXPECT_EQ(A(n, "layer_create 0 \"abcdefghijklmnopq\" 7 0 0"), Reason::BaseLayer);
  EXPECT_EQ(A(n, "layer_create 3 \"abcdefghijklmnopq\" 7 0 0"), Reason::BadLayerType);
  EXPECT_EQ(A(n, "layer_create 3 \"abcdefghijklmnopq\" VERTEX_REAL 0 0"), Reason::BadName);
  // subscribe: layer before format.
  EXPECT_EQ(A(n, "layer_subscribe 9 7"), Reason::NoSuchLayer);
  // slot writes: layer, then type, then element.
  EXPECT_EQ(A(n, "vertex_set_real64 2 99 0"), Reason::WrongLayerType);
  // base positions: layer, type, finiteness, then (for id picking) free ids.
  EXPECT_EQ(A(n, "vertex_set_xyz_real64 2 0 nan 0 0"), Reason::WrongLayerType);
  // polygons: shape before vertex existence.
  EXPECT_EQ(A(n, "polygon_set_corner_uint32 1 0 5 5 6 0xFFFFFFFF"), Reason::BadPolygon);
  // bones: names, values, weight layer, reference layer, cycle.
  EXPECT_EQ(A(n, "bone_create 0 \"missing\" \"abcdefghijklmnopq\" 0 nan 0 0 \"\" 0 0 0 0 \"\""), Reason::BadName);
  EXPECT_EQ(A(n, "bone_create 0 \"missing\" \"missing\" 0 nan 0 0 \"\" 0 0 0 1 \"\""), Reason::BadValue);
  EXPECT_EQ(A(n, "bone_create 0 \"missing\" \"missing\" 0 0 0 0 \"\" 0 0 0 1 \"\""), Reason::BadWeightLayer);
  EXPECT_EQ(A(n, "bone_create 0 \"u\" \"missing\" 0 0 0 0 \"\" 0 0 0 1 \"\""), Reason::BadReferenceLayer);
}

// ---- atomicity -------------------------------------------------------------------------

// For any command sequence, a rejected command leaves the snapshot exactly as
// it was, and apply never throws (RapidCheck fails a property that throws).
RC_GTEST_PROP(NodeProperty, RejectedCommandsChangeNothingAndApplyNeverThrows, ()) {
  const std::size_t limit = *rc::gen::element<std::size_t>(8, 40, std::size_t{1} << 22);
  Node node(NodeLimits{limit});
  const int steps = *rc::gen::inRange(1, 60);
  for (int i = 0; i < steps; ++i) {
    const Command c = *gen::gen_command_for(node);
    const std::string before = print_snapshot(node);
    const Reason r = node.apply(c);
    if (r != Reason::Ok) {
      RC_ASSERT(print_snapshot(node) == before);
    }
  }
  (void)print_derived(node);  // every reachable state can be interpreted
}

RC_GTEST_PROP(NodeProperty, ArbitraryCommandsNeverThrowAndRejectionsAreAtomic, (std::vector<Command> cs)) {
  Node node(NodeLimits{64});
  for (const auto& c : cs) {
    const std::string before = print_snapshot(node);
    if (node.apply(c) != Reason::Ok) RC_ASSERT(print_snapshot(node) == before);
  }
  (void)print_derived(node);
}

}  // namespace
}  // namespace vgc
