// Checks reference/geometry/hierarchical_edit.h (spec 001). OpenSubdiv 3 dropped
// hierarchical edits, so only holes at level 0 are checked against it
// (TopologyDescriptor numHoles/holeIndices); the rest by properties:
// paths name what spec 001 says, "add" 0 changes nothing, "set" then read
// gives the value, an edit at level k leaves levels below k untouched, a
// hole flags every descendant and nothing else, a sharpness edit at level 0
// equals the same crease given in the mesh.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "crease_sharpness.h"
#include "hierarchical_edit.h"
#include "osd_subdivision.h"
#include "subdivision_support.h"

namespace vgc {
namespace {

// A 26 x 26 quad grid (676 faces, so face 655 exists) and a mixed mesh with
// a pentagon and triangles (extraordinary faces).
MeshArrays big_grid() {
  std::mt19937 rng(3);
  return test::grid_with_holes(26, 26, 0.0, 0, rng);
}

MeshArrays mixed_with_pentagon() {
  // A pentagon fan: centre pentagon 0..4 ringed by quads and triangles.
  std::vector<std::array<double, 3>> p;
  for (int i = 0; i < 5; ++i) p.push_back({std::cos(2 * M_PI * i / 5), std::sin(2 * M_PI * i / 5), 0.1 * i});
  for (int i = 0; i < 5; ++i) p.push_back({2 * std::cos(2 * M_PI * i / 5), 2 * std::sin(2 * M_PI * i / 5), 0.0});
  std::vector<std::vector<int>> f{{0, 1, 2, 3, 4}, {0, 5, 6, 1}, {1, 6, 7}, {1, 7, 2}, {2, 7, 8, 3}, {3, 8, 9, 4}, {4, 9, 5, 0}};
  return test::make_mesh(p, f);
}

std::vector<SubdivisionLevel> plain(const MeshArrays& m, int levels) {
  std::vector<SubdivisionLevel> out;
  EXPECT_EQ(subdivide_with_edits(m, levels, {}, &out), EditStatus::Ok);
  return out;
}

TEST(HierarchicalEdit, RegularChildKeepsTheVertexIndex) {
  const MeshArrays m = big_grid();
  const auto L = plain(m, 1);
  for (int f = 0; f < L[0].face_count(); f += 37)
    for (int i = 0; i < 4; ++i) {
      const int parent_vertex = resolve_vertex(L, {f, {}}, i);
      // "the sub-face labeled n has one incident vertex that is the result of
      // the subdivision of the parent vertex also labeled n" and, regular:
      // "assigns the same index to the child vertex".
      EXPECT_EQ(resolve_vertex(L, {f, {i}}, i), L[1].child_of_parent_vertex[parent_vertex]);
    }
}

TEST(HierarchicalEdit, ExtraordinaryChildPutsTheVertexAtZero) {
  const MeshArrays m = mixed_with_pentagon();
  const auto L = plain(m, 1);
  for (int f = 0; f < L[0].face_count(); ++f) {
    const int n = L[0].face_sizes[f];
    if (n == 4) continue;
    for (int i = 0; i < n; ++i)
      EXPECT_EQ(resolve_vertex(L, {f, {i}}, 0), L[1].child_of_parent_vertex[resolve_vertex(L, {f, {}}, i)]) << f;
    EXPECT_EQ(resolve_face(L, {f, {n}}), -1);  // n children only
  }
}

TEST(HierarchicalEdit, TheSpecExamplePath) {
  // "(655 2 3 0) specifies the 1st. vertex of the 3 rd. child face of the 2 nd. child face of the 655 th. face"
  const auto L = plain(big_grid(), 2);
  const int f1 = resolve_face(L, {655, {2}});
  const int f2 = resolve_face(L, {655, {2, 3}});
  ASSERT_GE(f1, 0);
  ASSERT_GE(f2, 0);
  EXPECT_EQ(L[1].parent_face[f1], 655);
  EXPECT_EQ(L[2].parent_face[f2], f1);
  const int v = resolve_vertex(L, {655, {2, 3}}, 0);
  EXPECT_EQ(v, L[2].face_vertices[L[2].face_offsets[f2]]);
  // Regular child 3 of a quad is [e3 F e2 v3']: its vertex 0 is the edge point of the parent's edge 3.
  EXPECT_EQ(v, L[2].child_of_parent_edge[resolve_edge(L, {655, {2}}, 3)]);
}

TEST(HierarchicalEdit, EdgesAreLabelledByTheirOrigin) {
  const MeshArrays m = mixed_with_pentagon();
  const auto L = plain(m, 2);
  for (int f = 0; f < L[0].face_count(); ++f)
    for (int c = 0; c < L[0].face_sizes[f]; ++c) {
      const FacePath path{f, {c, 1}};
      for (int i = 0; i < 4; ++i) {
        const int e = resolve_edge(L, path, i);
        ASSERT_GE(e, 0);
        const int a = resolve_vertex(L, path, i), b = resolve_vertex(L, path, (i + 1) % 4);
        EXPECT_TRUE((L[2].edges[e][0] == a && L[2].edges[e][1] == b) || (L[2].edges[e][0] == b && L[2].edges[e][1] == a));
      }
    }
}

// A random path to level `level` of `m` (all child faces are quads after level 0).
FacePath random_path(const MeshArrays& m, int level) {
  FacePath p;
  p.base_face = *rc::gen::inRange(0, m.face_count());
  for (int d = 0; d < level; ++d) p.children.push_back(*rc::gen::inRange(0, d == 0 ? m.face_sizes[p.base_face] : 4));
  return p;
}

RC_GTEST_PROP(HierarchicalEdit, AddZeroChangesNothing, ()) {
  const MeshArrays m = mixed_with_pentagon();
  const int level = *rc::gen::inRange(0, 3);
  HierarchicalEdit e;
  e.kind = *rc::gen::element(EditKind::VertexValue, EditKind::VertexSharpness, EditKind::EdgeSharpness);
  e.op = EditOp::Add;
  e.face = random_path(m, level);
  e.index = *rc::gen::inRange(0, 3);
  std::vector<SubdivisionLevel> edited;
  RC_ASSERT(subdivide_with_edits(m, 3, {e}, &edited) == EditStatus::Ok);
  const auto base = plain(m, 3);
  for (std::size_t l = 0; l < base.size(); ++l) {
    RC_ASSERT(edited[l].positions == base[l].positions);
    RC_ASSERT(edited[l].edge_sharpness == base[l].edge_sharpness);
    RC_ASSERT(edited[l].vertex_sharpness == base[l].vertex_sharpness);
  }
}

RC_GTEST_PROP(HierarchicalEdit, SetThenReadAndCoarserLevelsUntouched, ()) {
  const MeshArrays m = mixed_with_pentagon();
  const int level = *rc::gen::inRange(0, 3);
  HierarchicalEdit e;
  e.op = EditOp::Set;
  e.face = random_path(m, level);
  e.index = *rc::gen::inRange(0, 3);
  e.value = {*rc::gen::inRange(-100, 100) * 0.5 + 0.25, 7.0, -3.0};
  std::vector<SubdivisionLevel> edited;
  RC_ASSERT(subdivide_with_edits(m, 3, {e}, &edited) == EditStatus::Ok);
  const int v = resolve_vertex(edited, e.face, e.index);
  RC_ASSERT(v >= 0);
  RC_ASSERT(edited[static_cast<std::size_t>(level)].positions[static_cast<std::size_t>(v)] == e.value);
  const auto base = plain(m, 3);
  for (int l = 0; l < level; ++l) RC_ASSERT(edited[static_cast<std::size_t>(l)].positions == base[static_cast<std::size_t>(l)].positions);
  // At its own level only the edited vertex moved; the next level moved too.
  auto expected = base[static_cast<std::size_t>(level)].positions;
  expected[static_cast<std::size_t>(v)] = e.value;
  RC_ASSERT(edited[static_cast<std::size_t>(level)].positions == expected);
  if (level < 3) RC_ASSERT(edited[static_cast<std::size_t>(level + 1)].positions != base[static_cast<std::size_t>(level + 1)].positions);
}

RC_GTEST_PROP(HierarchicalEdit, HoleFlagsEveryDescendantAndNothingElse, ()) {
  const MeshArrays m = mixed_with_pentagon();
  const int level = *rc::gen::inRange(0, 3);
  HierarchicalEdit e;
  e.kind = EditKind::FaceHole;
  e.face = random_path(m, level);
  std::vector<SubdivisionLevel> L;
  RC_ASSERT(subdivide_with_edits(m, 3, {e}, &L) == EditStatus::Ok);
  const int hole = resolve_face(L, e.face);
  for (int l = 0; l <= 3; ++l)
    for (int f = 0; f < L[static_cast<std::size_t>(l)].face_count(); ++f) {
      int a = f;  // the ancestor of f at the hole's level, if f is at or below it
      for (int k = l; k > level; --k) a = L[static_cast<std::size_t>(k)].parent_face[static_cast<std::size_t>(a)];
      const bool descendant = l >= level && a == hole;
      RC_ASSERT((L[static_cast<std::size_t>(l)].face_hole[static_cast<std::size_t>(f)] != 0) == descendant);
    }
  const auto base = plain(m, 3);
  for (int l = 0; l <= 3; ++l) RC_ASSERT(L[static_cast<std::size_t>(l)].positions == base[static_cast<std::size_t>(l)].positions);
}

RC_GTEST_PROP(HierarchicalEdit, SharpnessSetThenRead, ()) {
  const MeshArrays m = mixed_with_pentagon();
  const int level = *rc::gen::inRange(0, 3);
  HierarchicalEdit e;
  e.kind = *rc::gen::element(EditKind::VertexSharpness, EditKind::EdgeSharpness);
  e.face = random_path(m, level);
  e.index = *rc::gen::inRange(0, 3);
  e.sharpness = static_cast<float>(*rc::gen::inRange(1, 40)) * 0.25f;
  std::vector<SubdivisionLevel> L;
  RC_ASSERT(subdivide_with_edits(m, 3, {e}, &L) == EditStatus::Ok);
  const SubdivisionLevel& l = L[static_cast<std::size_t>(level)];
  if (e.kind == EditKind::VertexSharpness) {
    RC_ASSERT(l.vertex_sharpness[static_cast<std::size_t>(resolve_vertex(L, e.face, e.index))] == e.sharpness);
  } else {
    const auto edge = static_cast<std::size_t>(resolve_edge(L, e.face, e.index));
    // Boundary edges stay infinitely sharp (the documented decision).
    RC_ASSERT(l.edge_sharpness[edge] == (l.edge_face_count[edge] == 2 ? e.sharpness : kSharpnessInfinite));
  }
  const auto base = plain(m, 3);
  for (int k = 0; k < level; ++k) RC_ASSERT(L[static_cast<std::size_t>(k)].positions == base[static_cast<std::size_t>(k)].positions);
}

TEST(HierarchicalEdit, BaseHolesAgreeWithOpenSubdiv) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    std::mt19937 rng(seed);
    MeshArrays m = seed % 2 ? test::torus(6, 4, 0.3, rng) : test::grid_with_holes(5, 4, 0.3, 1, rng);
    test::add_random_creases(m, 0.3, 0.3, rng);
    std::vector<HierarchicalEdit> edits;
    OsdInput in = test::to_osd_input(m, OsdScheme::CatmullClark, 3);
    for (int f = static_cast<int>(seed); f < m.face_count(); f += 5) {
      HierarchicalEdit e;
      e.kind = EditKind::FaceHole;
      e.face = {f, {}};
      edits.push_back(e);
      in.hole_faces.push_back(f);
    }
    std::vector<SubdivisionLevel> L;
    ASSERT_EQ(subdivide_with_edits(m, 3, edits, &L), EditStatus::Ok);
    const OsdResult osd = osd_refine_uniform(in);
    EXPECT_EQ(test::compare_by_parent(L, osd, 1e-9 * test::mesh_scale(m), true), "") << seed;
    // And the comparison sees holes: without them it disagrees.
    EXPECT_NE(test::compare_by_parent(plain(m, 3), osd, 1e-9 * test::mesh_scale(m), true), "") << seed;
  }
}

TEST(HierarchicalEdit, BaseSharpnessEditsEqualTheSameCreasesInTheMesh) {
  MeshArrays m = mixed_with_pentagon();
  // Edge 0 of face 0 (vertices 0-1, shared with face 1) and vertex 2 of face 0.
  HierarchicalEdit edge;
  edge.kind = EditKind::EdgeSharpness;
  edge.face = {0, {}};
  edge.index = 0;
  edge.sharpness = 2.5f;
  HierarchicalEdit vertex;
  vertex.kind = EditKind::VertexSharpness;
  vertex.face = {0, {}};
  vertex.index = 2;
  vertex.sharpness = 10.0f;
  std::vector<SubdivisionLevel> L;
  ASSERT_EQ(subdivide_with_edits(m, 3, {edge, vertex}, &L), EditStatus::Ok);
  // The same creases given in the mesh, compared through OpenSubdiv.
  OsdInput in = test::to_osd_input(m, OsdScheme::CatmullClark, 3);
  in.crease_edges.push_back({0, 1});
  in.crease_sharpness.push_back(2.5f);
  in.corner_vertices.push_back(2);
  in.corner_sharpness.push_back(10.0f);
  EXPECT_EQ(test::compare_by_parent(L, osd_refine_uniform(in), 1e-9 * test::mesh_scale(m), true), "");
}

TEST(HierarchicalEdit, BadPathsAreRefused) {
  const MeshArrays m = mixed_with_pentagon();
  std::vector<SubdivisionLevel> L;
  HierarchicalEdit e;
  e.face = {99, {}};
  EXPECT_EQ(subdivide_with_edits(m, 2, {e}, &L), EditStatus::BadPath);
  EXPECT_TRUE(L.empty());
  e.face = {2, {3}};  // a triangle has children 0..2
  EXPECT_EQ(subdivide_with_edits(m, 2, {e}, &L), EditStatus::BadPath);
  e.face = {0, {0, 0, 0}};  // deeper than the levels asked for
  EXPECT_EQ(subdivide_with_edits(m, 2, {e}, &L), EditStatus::BadPath);
  e.face = {0, {4}};
  e.index = 4;  // child faces are quads
  EXPECT_EQ(subdivide_with_edits(m, 2, {e}, &L), EditStatus::BadIndex);
  e.index = 3;
  EXPECT_EQ(subdivide_with_edits(m, 2, {e}, &L), EditStatus::Ok);
}

}  // namespace
}  // namespace vgc
