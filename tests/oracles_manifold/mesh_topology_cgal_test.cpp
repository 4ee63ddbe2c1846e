// mesh_topology_cgal_test.cpp — reference/geometry/mesh_topology against CGAL
// (oracles/cgal_manifold), field by field for every question both answer,
// on manifold shapes (renumbered, faces rotated and shuffled), non-manifold
// edits (fins, bow-ties), non-orientable ones (a flipped face, a Moebius
// strip), degenerate input and random soups. Plus hand-derived answers for
// named shapes, so that a fault shared by both sides cannot pass unseen.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "cgal_manifold.h"
#include "command_text.h"
#include "manifold_shapes.h"
#include "mesh_arrays.h"
#include "mesh_topology.h"
#include "node.h"
#include "topology_comparison.h"

namespace vgc {
namespace {

using test::Faces;

std::string compare(const MeshTopology& r, const CgalManifoldReport& c) { return compare_topology_with_cgal(r, c); }

std::string compare_mesh(const MeshArrays& m) { return compare(classify_mesh(m), cgal_classify_mesh(m)); }

// ---- named shapes: CGAL agrees, and the answers derived by hand hold ----

TEST(MeshTopologyCgal, SpecCubeFromCorpus) {
  std::ifstream in(std::string(VGC_SOURCE_DIR) + "/corpora/examples/cube.vgc");
  ASSERT_TRUE(in) << "corpora/examples/cube.vgc";
  std::stringstream text;
  text << in.rdbuf();
  std::vector<Command> commands;
  TextError error;
  ASSERT_TRUE(parse_commands(text.str(), &commands, &error)) << error.to_string();
  Node node;
  for (const Command& c : commands) ASSERT_EQ(node.apply(c), Reason::Ok);
  const MeshArrays mesh = extract_mesh(node);
  const MeshTopology t = classify_mesh(mesh);
  ASSERT_EQ(t.status, MeshStatus::Ok);
  EXPECT_TRUE(t.closed);
  EXPECT_TRUE(t.is_manifold);
  EXPECT_TRUE(t.is_polygon_mesh);
  EXPECT_TRUE(t.consistently_oriented);
  EXPECT_TRUE(t.orientable);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.used_vertex_count, 8);
  EXPECT_EQ(t.edge_count, 12);
  EXPECT_EQ(t.face_count, 6);
  EXPECT_EQ(t.interior_edge_count, 12);
  EXPECT_EQ(t.boundary_edge_count, 0);
  EXPECT_EQ(t.component_count, 1);
  EXPECT_TRUE(t.boundary_loops && t.boundary_loops->empty());
  for (VertexKind k : t.vertex_kinds) EXPECT_EQ(k, VertexKind::Disc);
  const CgalManifoldReport c = cgal_classify_mesh(mesh);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.euler_characteristic, 2);
  EXPECT_EQ(c.component_count, 1);
  EXPECT_EQ(compare(t, c), "");
}

TEST(MeshTopologyCgal, GridHasOneBoundaryLoop) {
  // 2 x 1 quads, vertices 0 1 2 / 3 4 5, faces clockwise seen from +z.
  const MeshArrays m = test::grid(2, 1, false);
  const MeshTopology t = classify_mesh(m);
  EXPECT_EQ(t.boundary_edge_count, 6);
  EXPECT_EQ(t.interior_edge_count, 1);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_FALSE(t.closed);
  EXPECT_EQ(t.vertex_kinds[1], VertexKind::HalfDisc);
  // Face 0 is 0,3,4,1 and uses 0->3; the border runs the other way, 3->0,
  // so from 0 the loop continues 0->1 (face 0 uses 1->0).
  ASSERT_TRUE(t.boundary_loops);
  EXPECT_EQ(*t.boundary_loops, (std::vector<std::vector<int>>{{0, 1, 2, 5, 4, 3}}));
  EXPECT_EQ(compare_mesh(m), "");
}

TEST(MeshTopologyCgal, FinMakesANonManifoldEdge) {
  const MeshArrays m = test::add_fin(test::spec_cube(), 0, 0);  // edge 0-1 gets 3 uses
  const MeshTopology t = classify_mesh(m);
  ASSERT_EQ(t.non_manifold_edge_count, 1);
  EXPECT_FALSE(t.is_manifold);
  EXPECT_EQ(t.non_manifold_vertices, (std::vector<int>{0, 1}));
  EXPECT_EQ(t.component_count, 1);  // the fin shares edge 0-1 with the cube
  EXPECT_EQ(t.boundary_edge_count, 2);
  EXPECT_EQ(t.euler_characteristic, 9 - 14 + 7);
  EXPECT_EQ(compare_mesh(m), "");
}

TEST(MeshTopologyCgal, BowTieVertex) {
  const MeshArrays m = test::glue_at_vertex(test::tetrahedron(), test::octahedron(), 0, 0);
  const MeshTopology t = classify_mesh(m);
  EXPECT_EQ(t.non_manifold_edge_count, 0);
  EXPECT_EQ(t.non_manifold_vertices, (std::vector<int>{0}));
  EXPECT_EQ(t.vertex_fan_counts[0], 2);
  EXPECT_EQ(t.component_count, 2);
  EXPECT_FALSE(t.is_manifold);
  EXPECT_EQ(compare_mesh(m), "");
}

TEST(MeshTopologyCgal, FlippedFaceIsInconsistentButOrientable) {
  const MeshArrays m = test::flip_face(test::octahedron(), 3);
  const MeshTopology t = classify_mesh(m);
  EXPECT_FALSE(t.consistently_oriented);
  EXPECT_TRUE(t.orientable);
  EXPECT_TRUE(t.is_manifold);
  EXPECT_FALSE(t.is_polygon_mesh);
  EXPECT_EQ(compare_mesh(m), "");
}

TEST(MeshTopologyCgal, MoebiusStrip) {
  const MeshArrays m = test::moebius(5);
  const MeshTopology t = classify_mesh(m);
  EXPECT_FALSE(t.orientable);
  EXPECT_FALSE(t.consistently_oriented);
  EXPECT_TRUE(t.is_manifold);
  EXPECT_EQ(t.euler_characteristic, 0);
  ASSERT_TRUE(t.boundary_loops);
  ASSERT_EQ(t.boundary_loops->size(), 1u);
  EXPECT_EQ((*t.boundary_loops)[0].size(), 10u);
  EXPECT_EQ(compare_mesh(m), "");
}

// Closed and non-orientable: CGAL's re-orientation meets a conflict on
// an edge whose ends stay manifold, so it can answer "not orientable".
TEST(MeshTopologyCgal, KleinBottle) {
  const MeshArrays m = test::klein_bottle(4, 3);
  const MeshTopology t = classify_mesh(m);
  EXPECT_TRUE(t.closed);
  EXPECT_TRUE(t.is_manifold);
  EXPECT_FALSE(t.orientable);
  EXPECT_FALSE(t.consistently_oriented);
  EXPECT_EQ(t.euler_characteristic, 0);
  const CgalManifoldReport c = cgal_classify_mesh(m);
  EXPECT_EQ(c.orientable, std::optional<bool>(false));
  EXPECT_EQ(compare(t, c), "");
}

TEST(MeshTopologyCgal, TorusAndIsolatedVertex) {
  const MeshArrays m = test::add_isolated_vertex(test::torus(4, 3));
  const MeshTopology t = classify_mesh(m);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.isolated_vertex_count, 1);
  EXPECT_EQ(t.vertex_kinds.back(), VertexKind::Isolated);
  EXPECT_TRUE(t.closed);
  EXPECT_TRUE(t.is_manifold);
  const CgalManifoldReport c = cgal_classify_mesh(m);
  EXPECT_FALSE(c.valid_polygon_mesh);
  EXPECT_EQ(compare(t, c), "");
}

TEST(MeshTopologyCgal, InvalidInputGivesAStatus) {
  MeshArrays m = test::spec_cube();
  m.face_vertices[5] = 8;  // face 1, corner 1: out of range
  EXPECT_EQ(classify_mesh(m).status, MeshStatus::IndexOutOfRange);
  EXPECT_EQ(classify_mesh(m).bad_face, 1);
  EXPECT_EQ(compare_mesh(m), "");
  m.face_vertices[5] = -1;
  EXPECT_EQ(classify_mesh(m).status, MeshStatus::IndexOutOfRange);
  m.face_vertices[5] = 4;  // face 1 = 4,4,6,7
  EXPECT_EQ(classify_mesh(m).status, MeshStatus::RepeatedVertex);
  EXPECT_EQ(compare_mesh(m), "");
  MeshArrays two = test::make_mesh(test::spec_cube().positions, {{0, 1, 2}, {0, 1}});
  EXPECT_EQ(classify_mesh(two).status, MeshStatus::TooFewCorners);
  EXPECT_EQ(classify_mesh(two).bad_face, 1);
  EXPECT_EQ(compare_mesh(two), "");
  MeshArrays empty = test::make_mesh(test::spec_cube().positions, {{}});
  EXPECT_EQ(classify_mesh(empty).status, MeshStatus::TooFewCorners);
  MeshArrays bad = test::spec_cube();
  bad.face_offsets[5] = 22;  // 22 + 4 > 24 corners
  EXPECT_EQ(classify_mesh(bad).status, MeshStatus::BadArrays);
  EXPECT_EQ(compare_mesh(bad), "");
  bad = test::spec_cube();
  bad.face_offsets[2] = 4;  // face 2 overlaps face 1
  EXPECT_EQ(classify_mesh(bad).status, MeshStatus::BadArrays);
  EXPECT_EQ(classify_mesh(bad).bad_face, 2);
  EXPECT_EQ(compare_mesh(bad), "");
  bad = test::spec_cube();
  bad.face_vertices.push_back(0);  // a corner in no face
  EXPECT_EQ(classify_mesh(bad).status, MeshStatus::BadArrays);
  EXPECT_EQ(compare_mesh(bad), "");
  bad = test::spec_cube();
  bad.face_offsets.pop_back();
  EXPECT_EQ(classify_mesh(bad).status, MeshStatus::BadArrays);
  EXPECT_EQ(compare_mesh(bad), "");
}

// ---- random meshes ----

MeshArrays random_base(std::mt19937& rng) {
  switch (rng() % 7) {
    case 0: return test::spec_cube();
    case 1: return test::octahedron();
    case 2: return test::tetrahedron();
    case 3: return test::grid(1 + static_cast<int>(rng() % 4), 1 + static_cast<int>(rng() % 3), rng() % 2 == 0);
    case 4: return test::torus(3 + static_cast<int>(rng() % 3), 3 + static_cast<int>(rng() % 3));
    case 5: return test::moebius(3 + static_cast<int>(rng() % 4));
    default: return test::klein_bottle(3 + static_cast<int>(rng() % 3), 3 + static_cast<int>(rng() % 3));
  }
}

// A shape, then up to three random edits, then renumbering and rotation.
MeshArrays random_mesh(unsigned seed) {
  std::mt19937 rng(seed);
  MeshArrays m = random_base(rng);
  if (rng() % 8 == 0) m = test::random_soup(rng, 4 + static_cast<int>(rng() % 4), 1 + static_cast<int>(rng() % 8));
  const int edits = static_cast<int>(rng() % 4);
  for (int k = 0; k < edits; ++k) {
    const int f = static_cast<int>(rng() % static_cast<unsigned>(m.face_count()));
    switch (rng() % 7) {
      case 0: m = test::add_fin(m, f, static_cast<int>(rng() % 3)); break;
      case 1: m = test::glue_at_vertex(m, random_base(rng), static_cast<int>(rng() % static_cast<unsigned>(m.vertex_count())), 0); break;
      case 2: m = test::flip_face(m, f); break;
      case 3: m = test::add_isolated_vertex(m); break;
      case 4: m = test::disjoint_union(m, random_base(rng)); break;
      default: break;  // most meshes stay as they are
    }
  }
  m = test::renumber_vertices(m, rng);
  m = test::rotate_and_shuffle_faces(m, rng);
  return m;
}

// Breaks one face of `m` in one of the ways check_mesh reports.
MeshArrays break_mesh(MeshArrays m, unsigned seed) {
  std::mt19937 rng(seed);
  Faces f = test::faces_of(m);
  auto& face = f[rng() % f.size()];
  switch (rng() % 4) {
    case 0: face[1] = face[0]; break;                                                  // repeated vertex
    case 1: face.resize(rng() % 3); break;                                             // 0-, 1- or 2-gon
    case 2: face[rng() % face.size()] = m.vertex_count() + static_cast<int>(rng() % 3); break;  // out of range
    default: face[rng() % face.size()] = -1 - static_cast<int>(rng() % 3); break;      // negative
  }
  return test::make_mesh(m.positions, f);
}

RC_GTEST_PROP(MeshTopologyCgal, RandomMeshesAgree, (unsigned seed)) {
  const MeshArrays m = random_mesh(seed);
  const std::string why = compare_mesh(m);
  RC_ASSERT(why == "");
}

RC_GTEST_PROP(MeshTopologyCgal, RandomSoupsAgree, (unsigned seed)) {
  std::mt19937 rng(seed);
  const MeshArrays m = test::random_soup(rng, 3 + static_cast<int>(rng() % 5), 1 + static_cast<int>(rng() % 10));
  RC_ASSERT(compare_mesh(m) == "");
}

RC_GTEST_PROP(MeshTopologyCgal, BrokenMeshesGetTheSameStatus, (unsigned seed)) {
  const MeshArrays m = break_mesh(random_mesh(seed), seed);
  const MeshTopology t = classify_mesh(m);
  RC_ASSERT(t.status != MeshStatus::Ok);
  RC_ASSERT(compare(t, cgal_classify_mesh(m)) == "");
}

// Arbitrary arrays (sizes, offsets and indices anywhere near the valid
// range): no crash, and both sides give the same status and answers.
RC_GTEST_PROP(MeshTopologyCgal, ArbitraryArraysNeverCrash, ()) {
  const int vertices = *rc::gen::inRange(0, 9);
  // Sizes: mostly 3 or 4, sometimes 0..2, rarely -1.
  const auto face_count = static_cast<std::size_t>(*rc::gen::inRange(0, 12));
  const auto sizes = *rc::gen::container<std::vector<int>>(face_count, rc::gen::map(rc::gen::inRange(0, 200), [](int x) {
    return x == 0 ? -1 : x < 8 ? x % 3 : 3 + x % 2;
  }));
  MeshArrays m;
  m.positions.assign(static_cast<std::size_t>(vertices), {0, 0, 0});
  m.face_sizes = sizes;
  update_face_offsets(m);
  int total = 0;
  for (int n : sizes) total += n;
  const int lowest = *rc::gen::inRange(-1, 1);
  const int past_highest = std::max(lowest + 1, vertices + *rc::gen::inRange(0, 2));
  m.face_vertices = *rc::gen::container<std::vector<int>>(static_cast<std::size_t>(std::max(total, 0)), rc::gen::inRange(lowest, past_highest));
  if (*rc::gen::inRange(0, 8) == 0 && !m.face_offsets.empty()) m.face_offsets[0] += *rc::gen::inRange(-2, 3);
  if (*rc::gen::inRange(0, 8) == 0) m.face_vertices.push_back(0);
  const MeshTopology t = classify_mesh(m);
  RC_ASSERT(compare(t, cgal_classify_mesh(m)) == "");
  RC_TAG(to_string(t.status));
}

// Relabelling vertices, rotating and reordering faces changes no count.
RC_GTEST_PROP(MeshTopologyCgal, CountsSurviveRenumbering, (unsigned seed)) {
  std::mt19937 rng(seed);
  const MeshArrays a = random_base(rng);
  const MeshArrays b = test::rotate_and_shuffle_faces(test::renumber_vertices(a, rng), rng);
  const MeshTopology ta = classify_mesh(a), tb = classify_mesh(b);
  RC_ASSERT(ta.euler_characteristic == tb.euler_characteristic);
  RC_ASSERT(ta.boundary_edge_count == tb.boundary_edge_count);
  RC_ASSERT(ta.component_count == tb.component_count);
  RC_ASSERT(ta.orientable == tb.orientable);
  RC_ASSERT(ta.consistently_oriented == tb.consistently_oriented);
  RC_ASSERT(ta.boundary_loops->size() == tb.boundary_loops->size());
}

}  // namespace
}  // namespace vgc
