// snapshot_test.cpp — the snapshot and derived documents (reference/node/snapshot.cpp,
// reference/geometry/derived_document.cpp).
// The expected documents are written by hand from the format in
// docs/commands.md ("Snapshot", "Derived document").
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "derived_document.h"
#include "test_util.h"

namespace vgc {
namespace {

using test::apply_all;

TEST(Snapshot, FreshNodePrintsTheBaseLayersAndConstantCreases) {
  Node n;
  EXPECT_EQ(print_snapshot(n),
            "vgc-snapshot 1\n"
            "layer 0 \"vertex\" VERTEX_XYZ - - -\n"
            "layer 1 \"polygon\" POLYGON_CORNER_UINT32 - - -\n"
            "crease_vertex \"\" 0\n"
            "crease_edge \"\" 0\n"
            "end\n");
  EXPECT_EQ(print_derived(n), "vgc-derived 1\nend\n");
}

// Created out of id order on purpose: the documents are ordered by id.
constexpr const char* kScene = R"(
layer_create 5 "fr" POLYGON_FACE_REAL 0 -0.5
layer_create 3 "w" VERTEX_UINT32 0xFFFFFFFF 0
layer_create 2 "uv" VERTEX_REAL 0 0.25
layer_subscribe 2 REAL32
layer_subscribe 0 REAL64
vertex_set_xyz_real64 0 7 1 2 3
vertex_set_xyz_real64 0 2 0.5 -0 1e-300
vertex_set_xyz_real64 0 4 -1 -1 -1
polygon_set_corner_uint32 1 9 2 4 7 0xFFFFFFFF
polygon_set_corner_uint32 1 1 7 4 2 0xFFFFFFFF
vertex_set_real64 2 4 nan
vertex_set_uint32 3 7 12
polygon_set_face_real64 5 9 inf
crease_set_vertex "w" 3
crease_set_edge "" 0xFFFFFFFF
bone_create 1 "w" "" 0xFFFF 1 2 3 "pos" 0 0 0 1 "r\"ot"
bone_create 0 "uv" "w" 1 0 0 0 "" 0 0 1 0 ""
)";

TEST(Snapshot, ListsLayersCreasesVerticesPolygonsSlotsAndBonesInIdOrder) {
  Node n;
  apply_all(n, kScene);
  EXPECT_EQ(print_snapshot(n),
            "vgc-snapshot 1\n"
            "layer 0 \"vertex\" VERTEX_XYZ - - REAL64\n"
            "layer 1 \"polygon\" POLYGON_CORNER_UINT32 - - -\n"
            "layer 2 \"uv\" VERTEX_REAL - 0.25 REAL32\n"
            "layer 3 \"w\" VERTEX_UINT32 0xFFFFFFFF - -\n"
            "layer 5 \"fr\" POLYGON_FACE_REAL - -0.5 -\n"
            "crease_vertex \"w\" 3\n"
            "crease_edge \"\" 0xFFFFFFFF\n"
            "vertex 2 0.5 -0 1e-300\n"
            "vertex 4 -1 -1 -1\n"
            "vertex 7 1 2 3\n"
            "polygon 1 7 4 2 0xFFFFFFFF\n"
            "polygon 9 2 4 7 0xFFFFFFFF\n"
            "slot 2 2 0.25\n"
            "slot 2 4 nan\n"
            "slot 2 7 0.25\n"
            "slot 3 2 0xFFFFFFFF\n"
            "slot 3 4 0xFFFFFFFF\n"
            "slot 3 7 12\n"
            "slot 5 1 -0.5\n"
            "slot 5 9 inf\n"
            "bone 0 \"uv\" \"w\" 1 0 0 0 \"\" 0 0 1 0 \"\"\n"
            "bone 1 \"w\" \"\" 0xFFFF 1 2 3 \"pos\" 0 0 0 1 \"r\\\"ot\"\n"
            "end\n");
}

TEST(Snapshot, DerivedListsEffectiveCreasesPerVertexAndEdgeThenBonePoses) {
  Node n;
  apply_all(n, kScene);
  // Vertex creases come from layer "w" (default 0xFFFFFFFF, vertex 7 set to 12);
  // edges use the constant; bone 0 hangs under bone 1 at its origin and
  // composes its 180-degree Z rotation with bone 1's identity.
  EXPECT_EQ(print_derived(n),
            "vgc-derived 1\n"
            "vertex_crease 2 0xFFFFFFFF\n"
            "vertex_crease 4 0xFFFFFFFF\n"
            "vertex_crease 7 12\n"
            "edge_crease 1 0 0xFFFFFFFF\n"
            "edge_crease 1 1 0xFFFFFFFF\n"
            "edge_crease 1 2 0xFFFFFFFF\n"
            "edge_crease 9 0 0xFFFFFFFF\n"
            "edge_crease 9 1 0xFFFFFFFF\n"
            "edge_crease 9 2 0xFFFFFFFF\n"
            "bone_pose 0 1 2 3 0 0 1 0\n"
            "bone_pose 1 1 2 3 0 0 0 1\n"
            "end\n");
}

TEST(Snapshot, PrintsEverySlotOfEveryNonBaseLayerWithItsTypesValueCount) {
  Node n;
  apply_all(n, test::kCubeScript);
  apply_all(n, "layer_create 2 \"x\" VERTEX_XYZ 0 1.5\nlayer_create 3 \"cr\" POLYGON_CORNER_REAL 0 2\n"
               "layer_create 4 \"c\" POLYGON_CORNER_UINT32 4 0\nlayer_create 5 \"f8\" POLYGON_FACE_UINT8 0xFF 0\n"
               "layer_create 6 \"fu\" POLYGON_FACE_UINT32 6 0\n");
  const std::string s = print_snapshot(n);
  std::istringstream in(s);
  std::string line;
  std::map<std::string, int> slot_lines;  // "slot <layer>" -> count
  while (std::getline(in, line)) {
    if (line.rfind("slot ", 0) != 0) continue;
    const std::string layer = line.substr(0, line.find(' ', 5));
    ++slot_lines[layer];
  }
  EXPECT_EQ(slot_lines["slot 2"], 8);  // 8 vertices
  EXPECT_EQ(slot_lines["slot 3"], 6);  // 6 polygons
  EXPECT_EQ(slot_lines["slot 4"], 6);
  EXPECT_EQ(slot_lines["slot 5"], 6);
  EXPECT_EQ(slot_lines["slot 6"], 6);
  EXPECT_NE(s.find("slot 2 7 1.5 1.5 1.5\n"), std::string::npos);
  EXPECT_NE(s.find("slot 3 5 2 2 2 2\n"), std::string::npos);
  EXPECT_NE(s.find("slot 4 0 4 4 4 4\n"), std::string::npos);
  EXPECT_NE(s.find("slot 5 3 0xFF\n"), std::string::npos);
  EXPECT_NE(s.find("slot 6 1 6\n"), std::string::npos);
  // The base layers never print as slots.
  EXPECT_EQ(s.find("slot 0 "), std::string::npos);
  EXPECT_EQ(s.find("slot 1 "), std::string::npos);
}

TEST(Snapshot, SubscriptionColumnShowsDashReal32OrReal64) {
  Node n;
  apply_all(n, "layer_create 2 \"a\" VERTEX_REAL 0 0\nlayer_subscribe 2 REAL32\n");
  EXPECT_NE(print_snapshot(n).find("layer 2 \"a\" VERTEX_REAL - 0 REAL32\n"), std::string::npos);
  apply_all(n, "layer_subscribe 2 REAL64\n");
  EXPECT_NE(print_snapshot(n).find("layer 2 \"a\" VERTEX_REAL - 0 REAL64\n"), std::string::npos);
  apply_all(n, "layer_unsubscribe 2\n");
  EXPECT_NE(print_snapshot(n).find("layer 2 \"a\" VERTEX_REAL - 0 -\n"), std::string::npos);
}

// 000 2.6.1: a new slot "is typically initialized with a default value" of
// its layer's value type (Table 2-1), so only that default is state: the
// other prints "-", and the base layers, whose slots hold written data,
// print both as "-".
TEST(Snapshot, OnlyTheDefaultALayersTypeUsesIsPrinted) {
  Node n;
  apply_all(n,
            "layer_create 2 \"xyz\" VERTEX_XYZ 7 1.5\n"
            "layer_create 3 \"u\" VERTEX_UINT32 7 1.5\n"
            "layer_create 4 \"r\" VERTEX_REAL 7 1.5\n"
            "layer_create 5 \"cu\" POLYGON_CORNER_UINT32 7 1.5\n"
            "layer_create 6 \"cr\" POLYGON_CORNER_REAL 7 1.5\n"
            "layer_create 7 \"f8\" POLYGON_FACE_UINT8 0x1234 1.5\n"
            "layer_create 8 \"f32\" POLYGON_FACE_UINT32 7 1.5\n"
            "layer_create 9 \"fr\" POLYGON_FACE_REAL 7 1.5\n");
  const std::string s = print_snapshot(n);
  for (const char* line : {"layer 0 \"vertex\" VERTEX_XYZ - - -\n", "layer 1 \"polygon\" POLYGON_CORNER_UINT32 - - -\n",
                           "layer 2 \"xyz\" VERTEX_XYZ - 1.5 -\n", "layer 3 \"u\" VERTEX_UINT32 7 - -\n",
                           "layer 4 \"r\" VERTEX_REAL - 1.5 -\n", "layer 5 \"cu\" POLYGON_CORNER_UINT32 7 - -\n",
                           "layer 6 \"cr\" POLYGON_CORNER_REAL - 1.5 -\n", "layer 7 \"f8\" POLYGON_FACE_UINT8 4660 - -\n",
                           "layer 8 \"f32\" POLYGON_FACE_UINT32 7 - -\n", "layer 9 \"fr\" POLYGON_FACE_REAL - 1.5 -\n"})
    EXPECT_NE(s.find(line), std::string::npos) << line << " in\n" << s;
}

TEST(Snapshot, NamesAreQuotedWithEscapes) {
  Node n;
  apply_all(n, "layer_create 2 \"a b\\\\\\x01\" VERTEX_REAL 0 0\n");
  EXPECT_NE(print_snapshot(n).find("layer 2 \"a b\\\\\\x01\" VERTEX_REAL - 0 -\n"), std::string::npos);
}

}  // namespace
}  // namespace vgc
