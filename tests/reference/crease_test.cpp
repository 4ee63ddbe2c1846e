// crease_test.cpp — effective creases (reference/geometry/crease.cpp): constant vs
// layer, fallback for a missing or wrong-typed layer, late resolution, and
// the corner-to-edge rule including a triangle's wrap from corner 2 to 0.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "crease.h"
#include "derived_document.h"
#include "test_util.h"

namespace vgc {
namespace {

using test::A;
using test::apply_all;

// Four vertices, a quad (polygon 0: 0 1 2 3) and a triangle (polygon 1: 3 2 1).
constexpr const char* kMesh =
    "vertex_set_xyz_real64 0 0 0 0 0\nvertex_set_xyz_real64 0 1 1 0 0\n"
    "vertex_set_xyz_real64 0 2 1 1 0\nvertex_set_xyz_real64 0 3 0 1 0\n"
    "polygon_set_corner_uint32 1 0 0 1 2 3\npolygon_set_corner_uint32 1 1 3 2 1 0xFFFFFFFF\n";

TEST(Crease, ConstantAppliesToEveryVertexAndEdgeWhenNoLayerIsNamed) {
  Node n;
  apply_all(n, kMesh);
  for (std::uint32_t v = 0; v < 4; ++v) EXPECT_EQ(vertex_crease(n, v), kCreaseSmooth);
  ASSERT_EQ(A(n, "crease_set_vertex \"\" 1234"), Reason::Ok);
  ASSERT_EQ(A(n, "crease_set_edge \"\" 0xFFFFFFFF"), Reason::Ok);
  for (std::uint32_t v = 0; v < 4; ++v) EXPECT_EQ(vertex_crease(n, v), 1234u);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(edge_crease(n, 0, c), kCreaseMax);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(edge_crease(n, 1, c), kCreaseMax);
}

TEST(Crease, VertexCreaseLayerOfTypeVertexUint32GivesPerVertexValues) {
  Node n;
  apply_all(n, kMesh);
  apply_all(n, "layer_create 2 \"vc\" VERTEX_UINT32 7 0\nvertex_set_uint32 2 1 100\nvertex_set_uint32 2 3 0xFFFFFFFF\n"
               "crease_set_vertex \"vc\" 55\n");
  EXPECT_EQ(vertex_crease(n, 0), 7u);  // the layer's default, not the setting's constant
  EXPECT_EQ(vertex_crease(n, 1), 100u);
  EXPECT_EQ(vertex_crease(n, 2), 7u);
  EXPECT_EQ(vertex_crease(n, 3), kCreaseMax);
}

TEST(Crease, MissingLayerFallsBackToTheConstant) {
  Node n;
  apply_all(n, kMesh);
  apply_all(n, "crease_set_vertex \"nope\" 55\ncrease_set_edge \"nope\" 66\n");
  EXPECT_EQ(vertex_crease(n, 2), 55u);
  EXPECT_EQ(edge_crease(n, 0, 1), 66u);
}

TEST(Crease, WrongTypedLayerFallsBackToTheConstant) {
  Node n;
  apply_all(n, kMesh);
  // A per-vertex uint32 layer is right for vertices, wrong for edges; a
  // VERTEX_REAL or POLYGON_FACE_UINT32 layer is wrong for both.
  apply_all(n, "layer_create 2 \"vu\" VERTEX_UINT32 9 0\nlayer_create 3 \"vr\" VERTEX_REAL 0 9\n"
               "layer_create 4 \"fu\" POLYGON_FACE_UINT32 9 0\nlayer_create 5 \"cu\" POLYGON_CORNER_UINT32 9 0\n");
  apply_all(n, "crease_set_vertex \"vr\" 1\ncrease_set_edge \"vu\" 2\n");
  EXPECT_EQ(vertex_crease(n, 0), 1u);
  EXPECT_EQ(edge_crease(n, 0, 0), 2u);
  apply_all(n, "crease_set_vertex \"cu\" 3\ncrease_set_edge \"fu\" 4\n");
  EXPECT_EQ(vertex_crease(n, 0), 3u);
  EXPECT_EQ(edge_crease(n, 0, 0), 4u);
  apply_all(n, "crease_set_vertex \"vu\" 3\ncrease_set_edge \"cu\" 4\n");
  EXPECT_EQ(vertex_crease(n, 0), 9u);
  EXPECT_EQ(edge_crease(n, 0, 0), 9u);
}

TEST(Crease, LayerNamesAreResolvedWhenReadNotWhenSet) {
  Node n;
  apply_all(n, kMesh);
  ASSERT_EQ(A(n, "crease_set_vertex \"late\" 5"), Reason::Ok);
  EXPECT_EQ(vertex_crease(n, 0), 5u);
  ASSERT_EQ(A(n, "layer_create 2 \"late\" VERTEX_UINT32 77 0"), Reason::Ok);
  EXPECT_EQ(vertex_crease(n, 0), 77u);
  ASSERT_EQ(A(n, "layer_create 2 \"late\" VERTEX_REAL 0 0"), Reason::Ok);  // re-typed: wrong type now
  EXPECT_EQ(vertex_crease(n, 0), 5u);
  ASSERT_EQ(A(n, "layer_create 2 \"late\" VERTEX_UINT32 78 0"), Reason::Ok);
  EXPECT_EQ(vertex_crease(n, 0), 78u);
  ASSERT_EQ(A(n, "layer_destroy 2"), Reason::Ok);
  EXPECT_EQ(vertex_crease(n, 0), 5u);
}

// The crease of each directed edge (from vertex, to vertex) of a polygon.
std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edges_of(const Node& n, std::uint32_t pid) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> out;
  const Slot& s = n.polygons().at(pid);
  const int k = corner_count(s);
  for (int c = 0; c < k; ++c) out[{s.u[c], s.u[(c + 1) % k]}] = edge_crease(n, pid, c);
  return out;
}

TEST(Crease, EachCornerHoldsTheCreaseOfTheEdgeStartingThereAndTrianglesWrapAtCornerTwo) {
  Node n;
  apply_all(n, kMesh);
  apply_all(n, "layer_create 2 \"ec\" POLYGON_CORNER_UINT32 0 0\ncrease_set_edge \"ec\" 5\n"
               "polygon_set_corner_uint32 2 0 10 11 12 13\npolygon_set_corner_uint32 2 1 20 21 22 23\n");
  using E = std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t>;
  // Quad 0 1 2 3: edges 0->1, 1->2, 2->3, 3->0.
  EXPECT_EQ(edges_of(n, 0), (E{{{0, 1}, 10}, {{1, 2}, 11}, {{2, 3}, 12}, {{3, 0}, 13}}));
  // Triangle 3 2 1: edges 3->2, 2->1, and 1->3 from corner 2; corner 3's 23 is unused.
  EXPECT_EQ(edges_of(n, 1), (E{{{3, 2}, 20}, {{2, 1}, 21}, {{1, 3}, 22}}));
  EXPECT_EQ(corner_count(n.polygons().at(0)), 4);
  EXPECT_EQ(corner_count(n.polygons().at(1)), 3);
  // The derived document lists exactly these edges.
  const std::string derived = print_derived(n);
  EXPECT_NE(derived.find("edge_crease 1 2 22\n"), std::string::npos);
  EXPECT_EQ(derived.find("edge_crease 1 3 "), std::string::npos);
  EXPECT_NE(derived.find("edge_crease 0 3 13\n"), std::string::npos);
}

}  // namespace
}  // namespace vgc
