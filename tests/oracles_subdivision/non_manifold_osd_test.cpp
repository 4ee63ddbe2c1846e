// Checks the reference's non-manifold rules (reference/geometry/catmull_clark.h
// build_base_level, non_manifold_tags) and Loop's child edges from the
// parent topology (reference/geometry/loop_subdivision.h) against OpenSubdiv
// (oracles/osd_subdivision.h) at levels 1..3, on shapes a geometry node can
// hold (triangles and quads, distinct corners) that are not polygon meshes:
// a fin (three faces on one edge), a fin along two edges (the interior
// non-manifold crease OpenSubdiv does not sharpen), bow-ties (two fans
// sharing one vertex), a closed pillow (two triangles on the same three
// vertices), a same-direction pair (two faces using their shared edge the
// same way), a pillow of quads, and a cube for contrast; each with and
// without creases. OpenSubdiv's own regression shapes are not in Debian's
// libosd-dev: these are built here.
// The two seeded faults (LoopFaults / CatmullClarkFaults
// no_non_manifold_rule, LoopFaults edges_by_vertex_pair) each make the
// comparison fail on some of these shapes.
#include <gtest/gtest.h>

#include "catmull_clark.h"
#include "loop_subdivision.h"
#include "osd_subdivision.h"
#include "subdivision_support.h"

namespace vgc {
namespace {

constexpr int kLevels = 3;

struct Shape {
  const char* name;
  MeshArrays mesh;
};

MeshArrays mesh(std::vector<std::array<double, 3>> p, std::vector<std::vector<int>> f) {
  return test::make_mesh(std::move(p), std::move(f));
}

// Triangle shapes (Loop and Catmull-Clark).
std::vector<Shape> triangle_shapes() {
  std::vector<Shape> s;
  // Fin: three triangles on edge 0-1, each with its own apex.
  s.push_back({"tri-fin", mesh({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0.2}, {0.5, 0, 1}},
                               {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}})});
  // Fin along two edges (0-1, 1-2): three sheets of two triangles each;
  // vertex 1 has two non-manifold edges, no boundary, 6 faces on 5 edges.
  s.push_back({"tri-fin-spine",
               mesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, -1, 0.3}, {1, 0.2, 1}},
                    {{0, 1, 3}, {1, 2, 3}, {1, 0, 4}, {2, 1, 4}, {0, 1, 5}, {1, 2, 5}})});
  // Bow-tie: two fans of two triangles touching at vertex 0.
  s.push_back({"tri-bowtie", mesh({{0, 0, 0}, {1, 1, 0}, {1.5, 0, 0.1}, {1, -1, 0}, {-1, 1, 0}, {-1.5, 0, 0.2}, {-1, -1, 0}},
                                  {{0, 1, 2}, {0, 2, 3}, {0, 4, 5}, {0, 5, 6}})});
  // Pillow: two triangles on the same three vertices, opposite orientation
  // (closed; a valid polygon mesh, yet Loop's T0 children share vertices).
  s.push_back({"tri-pillow", mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0.5}}, {{0, 1, 2}, {0, 2, 1}})});
  // Pillow of the same orientation: every edge used twice the same way.
  s.push_back({"tri-pillow-same-direction", mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0.5}}, {{0, 1, 2}, {1, 2, 0}})});
  // Same-direction pair: two triangles using edge 0->1 the same way.
  s.push_back({"tri-same-direction", mesh({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0.3}}, {{0, 1, 2}, {0, 1, 3}})});
  // A closed octahedron with one face doubled the other way round (a fin
  // on each of its three edges).
  s.push_back({"tri-octahedron-doubled-face",
               mesh({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
                    {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}, {0, 4, 2}})});
  return s;
}

// Shapes with quads (Catmull-Clark only).
std::vector<Shape> quad_shapes() {
  std::vector<Shape> s;
  s.push_back({"quad-fin", mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, -1, 0.2}, {0, -1, 0.2}, {1, 0, 1}, {0, 0, 1}},
                                {{0, 1, 2, 3}, {1, 0, 5, 4}, {0, 1, 6, 7}})});
  s.push_back({"quad-bowtie", mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0, 0.3}, {-1, -1, 0.3}, {0, -1, 0.3}},
                                   {{0, 1, 2, 3}, {0, 4, 5, 6}})});
  s.push_back({"quad-same-direction",
               mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, -1, 0.2}, {0, -1, 0.2}}, {{0, 1, 2, 3}, {0, 1, 4, 5}})});
  s.push_back({"quad-pillow", mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0.3}, {0, 1, 0}}, {{0, 1, 2, 3}, {0, 3, 2, 1}})});
  // A triangle and a quad sharing two edges' worth of vertices, mixed.
  s.push_back({"mixed-fin", mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}},
                                 {{0, 1, 2, 3}, {1, 0, 4}, {0, 1, 5}})});
  std::mt19937 rng(7);
  s.push_back({"cube", test::cube_with_triangles(rng)});
  return s;
}

// The shape with creases on every other edge and vertex (a fractional, a
// semi-sharp and an infinite value in turn).
MeshArrays creased(MeshArrays m) {
  const std::uint32_t values[] = {0x20000000u, 0x80000000u, 0xFFFFFFFFu};
  for (std::size_t v = 0; v < m.vertex_creases.size(); v += 2) m.vertex_creases[v] = values[v % 3];
  for (std::size_t c = 1; c < m.corner_edge_creases.size(); c += 3) m.corner_edge_creases[c] = values[c % 3];
  return m;
}

std::string compare_cc(const MeshArrays& m, int levels, const CatmullClarkFaults& faults = {}) {
  const auto ref = subdivide_catmull_clark(m, levels, faults);
  if (ref.empty()) return "reference refused the mesh";
  const OsdResult osd = osd_refine_uniform(test::to_osd_input(m, OsdScheme::CatmullClark, levels));
  return test::compare_by_parent(ref, osd, 1e-9 * test::mesh_scale(m), true);
}

std::string compare_loop(const MeshArrays& m, int levels, const LoopFaults& faults = {}) {
  const auto ref = subdivide_loop(m, levels, faults);
  if (ref.empty()) return "reference refused the mesh";
  const OsdResult osd = osd_refine_uniform(test::to_osd_input(m, OsdScheme::Loop, levels));
  return test::compare_by_parent(ref, osd, 1e-9 * test::mesh_scale(m), false);
}

TEST(NonManifoldOsd, CatmullClarkAgreesOnEveryShapeAtLevelsOneToThree) {
  std::vector<Shape> shapes = triangle_shapes();
  for (auto& s : quad_shapes()) shapes.push_back(std::move(s));
  for (const Shape& s : shapes)
    for (int levels = 1; levels <= kLevels; ++levels) {
      EXPECT_EQ(compare_cc(s.mesh, levels), "") << s.name << " to level " << levels;
      EXPECT_EQ(compare_cc(creased(s.mesh), levels), "") << s.name << " (creased) to level " << levels;
    }
}

TEST(NonManifoldOsd, LoopAgreesOnEveryTriangleShapeAtLevelsOneToThree) {
  std::mt19937 rng(3);
  std::vector<Shape> shapes = triangle_shapes();
  shapes.push_back({"octahedron", test::octahedron(rng)});
  for (const Shape& s : shapes)
    for (int levels = 1; levels <= kLevels; ++levels) {
      EXPECT_EQ(compare_loop(s.mesh, levels), "") << s.name << " to level " << levels;
      EXPECT_EQ(compare_loop(creased(s.mesh), levels), "") << s.name << " (creased) to level " << levels;
    }
}

// The numbers: Loop on the closed pillow keeps all its vertices:
// 3 + 3 edge points = 6 at level 1, 6 + 12 = 18 at level 2 (15 when level
// 1's edges were merged by vertex pair), 18 + 48 = 66 at level 3.
TEST(NonManifoldOsd, LoopPillowKeepsEveryVertex) {
  const MeshArrays pillow = triangle_shapes()[3].mesh;
  const auto ref = subdivide_loop(pillow, 3);
  ASSERT_EQ(ref.size(), 4u);
  EXPECT_EQ(ref[1].vertex_count(), 6);
  EXPECT_EQ(ref[1].edge_count(), 12);
  EXPECT_EQ(ref[2].vertex_count(), 18);
  EXPECT_EQ(ref[3].vertex_count(), 66);
  const OsdResult osd = osd_refine_uniform(test::to_osd_input(pillow, OsdScheme::Loop, 3));
  ASSERT_TRUE(osd.ok) << osd.failure;
  EXPECT_EQ(osd.levels[2].positions.size(), 18u);
  EXPECT_EQ(osd.levels[3].positions.size(), 66u);
}

// The tags on the shapes, stated independently of OpenSubdiv.
TEST(NonManifoldOsd, TagsNameTheNonManifoldParts) {
  auto tags_of = [](const MeshArrays& m) {
    SubdivisionLevel base;
    EXPECT_TRUE(build_base_level(m, &base));
    return std::make_pair(non_manifold_tags(m, base), base);
  };
  {  // fin: edge 0-1 and its ends; all three of its vertices... only 0 and 1
    const auto [t, base] = tags_of(triangle_shapes()[0].mesh);
    int nm_edges = 0;
    for (auto e : t.edge) nm_edges += e;
    EXPECT_EQ(nm_edges, 1);
    EXPECT_EQ(std::vector<unsigned char>(t.vertex.begin(), t.vertex.end()), (std::vector<unsigned char>{1, 1, 0, 0, 0}));
    EXPECT_EQ(base.vertex_sharpness[0], kSharpnessInfinite);
    EXPECT_EQ(base.vertex_sharpness[2], kSharpnessSmooth);
  }
  {  // fin spine: vertex 1 is non-manifold but on an interior crease, not sharpened
    const auto [t, base] = tags_of(triangle_shapes()[1].mesh);
    EXPECT_EQ(t.vertex[1], 1);
    EXPECT_EQ(t.vertex_sharpened[1], 0);
    EXPECT_EQ(t.vertex_sharpened[0], 1);
  }
  {  // bow-tie: only the shared vertex, no edge
    const auto [t, base] = tags_of(triangle_shapes()[2].mesh);
    for (auto e : t.edge) EXPECT_EQ(e, 0);
    EXPECT_EQ(t.vertex[0], 1);
    for (std::size_t v = 1; v < t.vertex.size(); ++v) EXPECT_EQ(t.vertex[v], 0) << v;
  }
  {  // pillow: manifold (each edge used once each way)
    const auto [t, base] = tags_of(triangle_shapes()[3].mesh);
    for (auto e : t.edge) EXPECT_EQ(e, 0);
    for (auto v : t.vertex) EXPECT_EQ(v, 0);
  }
  {  // same direction: the shared edge and its ends
    const auto [t, base] = tags_of(triangle_shapes()[5].mesh);
    EXPECT_EQ(t.edge[0], 1);
    EXPECT_EQ(t.vertex[0] + t.vertex[1], 2);
    EXPECT_EQ(base.edge_sharpness[0], kSharpnessInfinite);
  }
}

// Each seeded fault makes the comparison fail on some shape.
TEST(NonManifoldOsd, EverySeededFaultIsCaught) {
  std::vector<Shape> shapes = triangle_shapes();
  for (auto& s : quad_shapes()) shapes.push_back(std::move(s));
  CatmullClarkFaults cc;
  cc.no_non_manifold_rule = true;
  int cc_caught = 0;
  for (const Shape& s : shapes) cc_caught += compare_cc(s.mesh, 2, cc).empty() ? 0 : 1;
  EXPECT_GE(cc_caught, 5) << "Catmull-Clark without the non-manifold rule went unnoticed";

  LoopFaults nm;
  nm.no_non_manifold_rule = true;
  LoopFaults pairs;
  pairs.edges_by_vertex_pair = true;
  int nm_caught = 0, pairs_caught = 0;
  for (const Shape& s : triangle_shapes()) {
    nm_caught += compare_loop(s.mesh, 2, nm).empty() ? 0 : 1;
    pairs_caught += compare_loop(s.mesh, 2, pairs).empty() ? 0 : 1;
  }
  EXPECT_GE(nm_caught, 3) << "Loop without the non-manifold rule went unnoticed";
  EXPECT_GE(pairs_caught, 1) << "Loop edges by vertex pair went unnoticed";
  EXPECT_NE(compare_loop(triangle_shapes()[3].mesh, 2, pairs), "") << "the pillow with edges by vertex pair";
}

}  // namespace
}  // namespace vgc
