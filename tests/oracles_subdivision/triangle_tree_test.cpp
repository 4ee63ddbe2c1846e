// Checks reference/geometry/triangle_tree.h, the MeshEd naming of spec 004, by its
// properties on real Loop levels:
//   "Sub-triangles are named according to their nearest vertex, with T0 in
//    the center": T0 holds no child of a parent vertex; T(i+1) holds the
//    child of parent vertex i and no other parent vertex's child.
//   "Sub-vertices are named for their opposite vertex" / "Edges are named
//    for their opposite vertex": sub-vertex k is the child of the edge
//    whose ends are the two vertices other than k.
//   "The vertex numbers of the subtriangles are the same as the nearest
//    vertex or sub-vertex of the parent triangle": slot k of every child is
//    parent vertex k's child or sub-vertex k.
//   "orientation is not implied in the vertex naming": the named vertices
//    are the oriented child face's vertices as a set.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "loop_subdivision.h"
#include "subdivision_support.h"
#include "triangle_tree.h"

namespace vgc {
namespace {

std::vector<SubdivisionLevel> sample_levels() {
  std::mt19937 rng(7);
  MeshArrays m = test::grid_with_holes(4, 3, 1.0, 2, rng);
  return subdivide_loop(m, 2);
}

TEST(TriangleTree, NamesOfChildrenAndSlots) {
  EXPECT_EQ(kCentreChild, 0);
  for (int v = 0; v < 3; ++v) {
    EXPECT_EQ(nearest_vertex_of_child(corner_child_of_vertex(v)), v);
    const auto e = edge_vertices(v);
    EXPECT_NE(e[0], v);
    EXPECT_NE(e[1], v);
    EXPECT_NE(e[0], e[1]);
  }
  EXPECT_EQ(nearest_vertex_of_child(kCentreChild), -1);
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(child_corner_names(kCentreChild)[static_cast<std::size_t>(k)].sub_vertex);
  for (int c = 1; c < 4; ++c) {
    const auto names = child_corner_names(c);
    int parent_vertices = 0;
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(names[static_cast<std::size_t>(k)].index, k);  // slot k names vertex or sub-vertex k
      parent_vertices += names[static_cast<std::size_t>(k)].sub_vertex ? 0 : 1;
    }
    EXPECT_EQ(parent_vertices, 1);
    EXPECT_FALSE(names[static_cast<std::size_t>(nearest_vertex_of_child(c))].sub_vertex);
  }
}

TEST(TriangleTree, PropertiesHoldOnLoopLevels) {
  const auto levels = sample_levels();
  ASSERT_EQ(levels.size(), 3u);
  for (std::size_t l = 1; l < levels.size(); ++l) {
    const SubdivisionLevel& p = levels[l - 1];
    const SubdivisionLevel& c = levels[l];
    std::set<int> vertex_children(c.child_of_parent_vertex.begin(), c.child_of_parent_vertex.end());
    for (int f = 0; f < p.face_count(); ++f) {
      std::array<int, 3> pv{}, pvc{}, sub{};
      for (int k = 0; k < 3; ++k) {
        pv[static_cast<std::size_t>(k)] = p.face_vertices[p.face_offsets[f] + k];
        pvc[static_cast<std::size_t>(k)] = c.child_of_parent_vertex[pv[static_cast<std::size_t>(k)]];
        sub[static_cast<std::size_t>(k)] = sub_vertex(p, c, f, k);
      }
      // Sub-vertex k is the child of the edge opposite vertex k.
      for (int k = 0; k < 3; ++k) {
        const auto ev = edge_vertices(k);
        int e = -1;
        for (int i = 0; i < p.edge_count(); ++i) {
          const int a = pv[static_cast<std::size_t>(ev[0])], b = pv[static_cast<std::size_t>(ev[1])];
          if ((p.edges[i][0] == a && p.edges[i][1] == b) || (p.edges[i][0] == b && p.edges[i][1] == a)) e = i;
        }
        ASSERT_GE(e, 0);
        EXPECT_EQ(sub[static_cast<std::size_t>(k)], c.child_of_parent_edge[e]);
      }
      for (int child = 0; child < 4; ++child) {
        const int t = child_triangle(c, f, child);
        ASSERT_GE(t, 0);
        EXPECT_EQ(c.parent_face[t], f);
        const auto named = named_child_vertices(p, c, f, child);
        // Slot k: parent vertex k's child or sub-vertex k.
        for (int k = 0; k < 3; ++k)
          EXPECT_TRUE(named[static_cast<std::size_t>(k)] == pvc[static_cast<std::size_t>(k)] ||
                      named[static_cast<std::size_t>(k)] == sub[static_cast<std::size_t>(k)]);
        int vcount = 0;
        for (int x : named) vcount += vertex_children.count(x) ? 1 : 0;
        if (child == kCentreChild) {
          EXPECT_EQ(vcount, 0) << "T0 must be the centre";
        } else {
          EXPECT_EQ(vcount, 1);
          const int near = nearest_vertex_of_child(child);
          EXPECT_EQ(named[static_cast<std::size_t>(near)], pvc[static_cast<std::size_t>(near)]);
        }
        // Same vertices as the oriented face, orientation aside.
        std::vector<int> face(c.face_vertices.begin() + c.face_offsets[t], c.face_vertices.begin() + c.face_offsets[t] + 3);
        std::vector<int> names(named.begin(), named.end());
        std::sort(face.begin(), face.end());
        std::sort(names.begin(), names.end());
        EXPECT_EQ(face, names);
      }
      // Each sub-vertex is in T0 and in the two corner children at its edge's ends.
      for (int k = 0; k < 3; ++k) {
        int in = 0;
        for (int child = 0; child < 4; ++child) {
          const auto named = named_child_vertices(p, c, f, child);
          in += std::count(named.begin(), named.end(), sub[static_cast<std::size_t>(k)]) ? 1 : 0;
        }
        EXPECT_EQ(in, 3);
        const auto own = named_child_vertices(p, c, f, corner_child_of_vertex(k));
        EXPECT_EQ(std::count(own.begin(), own.end(), sub[static_cast<std::size_t>(k)]), 0)
            << "sub-vertex k lies opposite vertex k, away from its corner child";
      }
    }
  }
}

TEST(TriangleTree, OutOfRangeGivesMinusOne) {
  const auto levels = sample_levels();
  EXPECT_EQ(child_triangle(levels[1], -1, 0), -1);
  EXPECT_EQ(child_triangle(levels[1], 0, 4), -1);
  EXPECT_EQ(sub_vertex(levels[0], levels[1], 0, 3), -1);
  EXPECT_EQ(named_child_vertices(levels[0], levels[1], levels[0].face_count(), 0)[0], -1);
  EXPECT_EQ(corner_child_of_vertex(3), -1);
}

}  // namespace
}  // namespace vgc
