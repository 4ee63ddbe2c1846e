// build_level_edges_test.cpp — the edges of a subdivision level
// (reference/geometry/catmull_clark.h build_level_edges): numbered by first
// appearance walking the faces corner by corner, each in the direction its
// first face uses it, with the count of faces using it. Expected values are
// written out by hand from the faces, not computed by the code under test.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "catmull_clark.h"

namespace vgc {
namespace {

SubdivisionLevel level_of(const std::vector<std::vector<int>>& faces) {
  SubdivisionLevel l;
  for (const auto& f : faces) {
    l.face_offsets.push_back(static_cast<int>(l.face_vertices.size()));
    l.face_sizes.push_back(static_cast<int>(f.size()));
    l.face_vertices.insert(l.face_vertices.end(), f.begin(), f.end());
  }
  build_level_edges(&l);
  return l;
}

using Edges = std::vector<std::array<int, 2>>;

TEST(BuildLevelEdges, OneTriangleHasThreeEdgesInCornerOrder) {
  const SubdivisionLevel l = level_of({{5, 3, 9}});
  EXPECT_EQ(l.edges, (Edges{{5, 3}, {3, 9}, {9, 5}}));
  EXPECT_EQ(l.face_edges, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(l.edge_face_count, (std::vector<int>{1, 1, 1}));
}

TEST(BuildLevelEdges, ASharedEdgeKeepsItsFirstFacesDirectionAndNumber) {
  // Quad 0 1 2 3 and triangle 2 1 4: edge 1-2 is the quad's second edge.
  const SubdivisionLevel l = level_of({{0, 1, 2, 3}, {2, 1, 4}});
  EXPECT_EQ(l.edges, (Edges{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {1, 4}, {4, 2}}));
  EXPECT_EQ(l.face_edges, (std::vector<int>{0, 1, 2, 3, 1, 4, 5}));
  EXPECT_EQ(l.edge_face_count, (std::vector<int>{1, 2, 1, 1, 1, 1}));
}

TEST(BuildLevelEdges, AFinCountsThreeFacesOnOneEdge) {
  const SubdivisionLevel l = level_of({{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  ASSERT_EQ(l.edge_count(), 7);
  EXPECT_EQ(l.edges[0], (std::array<int, 2>{0, 1}));
  EXPECT_EQ(l.face_edges[3], 0);  // 1 -> 0 of the second face
  EXPECT_EQ(l.face_edges[6], 0);  // 0 -> 1 of the third
  EXPECT_EQ(l.edge_face_count[0], 3);
}

TEST(BuildLevelEdges, AClosedFanOfAThousandTrianglesHasASpokeAndARimEdgeEach) {
  // Triangles 0, i, i + 1 around hub 0 (rim vertices 1..1000, closed).
  const int n = 1000;
  std::vector<std::vector<int>> faces;
  for (int i = 1; i <= n; ++i) faces.push_back({0, i, i % n + 1});
  const SubdivisionLevel l = level_of(faces);
  ASSERT_EQ(l.edge_count(), 2 * n);
  // Face 1 (the first) gives spoke 0-1, rim 1-2, spoke 2-0; every later face
  // i gives its rim edge i - (i+1), then a new spoke, except the last, whose
  // closing spoke 1-0 is edge 0.
  EXPECT_EQ(l.edges[0], (std::array<int, 2>{0, 1}));
  EXPECT_EQ(l.edges[1], (std::array<int, 2>{1, 2}));
  EXPECT_EQ(l.edges[2], (std::array<int, 2>{2, 0}));
  EXPECT_EQ(l.edges[3], (std::array<int, 2>{2, 3}));
  EXPECT_EQ(l.edges[4], (std::array<int, 2>{3, 0}));
  EXPECT_EQ(l.face_edges[3 * (n - 1) + 2], 0);
  for (int e = 0; e < l.edge_count(); ++e) {
    const bool spoke = l.edges[static_cast<std::size_t>(e)][0] == 0 || l.edges[static_cast<std::size_t>(e)][1] == 0;
    EXPECT_EQ(l.edge_face_count[static_cast<std::size_t>(e)], spoke ? 2 : 1) << "edge " << e;
  }
}

}  // namespace
}  // namespace vgc
