// Checks reference/geometry/catmull_clark.h against OpenSubdiv (oracles/osd_subdivision.h):
// random quad/triangle meshes (grids with holes as boundaries, closed
// shapes, random vertex renumbering) with random vertex and edge creases
// (smooth, fractional, semi-sharp, infinite); every refined vertex of levels
// 1..4 agrees within 1e-9 * scale, matched by parent component. The spec's
// cube (000 2.6.4, "maximum sharpness everywhere") stays a cube in both. Each
// seeded fault of CatmullClarkFaults makes the comparison fail.
#include <gtest/gtest.h>

#include "catmull_clark.h"
#include "osd_subdivision.h"
#include "subdivision_support.h"

namespace vgc {
namespace {

constexpr int kLevels = 4;

struct Case {
  std::string name;
  MeshArrays mesh;
};

// The corpus: the same meshes for every test, from fixed seeds.
std::vector<Case> corpus() {
  std::vector<Case> cases;
  for (unsigned seed = 1; seed <= 12; ++seed) {
    std::mt19937 rng(seed);
    Case c;
    switch (seed % 4) {
      case 0: c.mesh = test::grid_with_holes(5, 4, 0.0, 3, rng); c.name = "quad grid with holes"; break;
      case 1: c.mesh = test::grid_with_holes(4, 4, 0.4, 2, rng); c.name = "mixed grid with holes"; break;
      case 2: c.mesh = test::torus(6, 4, 0.3, rng); c.name = "mixed torus"; break;
      default: c.mesh = seed == 3 ? test::cube_with_triangles(rng) : test::octahedron(rng); c.name = "closed"; break;
    }
    test::add_random_creases(c.mesh, 0.3, 0.3, rng);
    c.name += " seed " + std::to_string(seed);
    cases.push_back(std::move(c));
  }
  return cases;
}

std::string compare(const MeshArrays& m, const CatmullClarkFaults& faults = {}) {
  const auto ref = subdivide_catmull_clark(m, kLevels, faults);
  if (ref.empty()) return "reference refused the mesh";
  const OsdResult osd = osd_refine_uniform(test::to_osd_input(m, OsdScheme::CatmullClark, kLevels));
  return test::compare_by_parent(ref, osd, 1e-9 * test::mesh_scale(m), true);
}

TEST(CatmullClarkOsd, RandomMeshesAgreeAtEveryLevel) {
  for (const Case& c : corpus()) EXPECT_EQ(compare(c.mesh), "") << c.name;
}

TEST(CatmullClarkOsd, SmoothMeshesAgree) {  // no creases at all: only the boundary rule
  std::mt19937 rng(1);
  for (Case c : corpus()) {
    test::add_random_creases(c.mesh, 0.0, 0.0, rng);
    EXPECT_EQ(compare(c.mesh), "") << c.name;
  }
}

TEST(CatmullClarkOsd, EverySeededFaultIsCaught) {
  const auto cases = corpus();
  auto caught = [&](const CatmullClarkFaults& f) {
    int failures = 0;
    for (const Case& c : cases) failures += compare(c.mesh, f).empty() ? 0 : 1;
    return failures;
  };
  CatmullClarkFaults boundary;
  boundary.pin_boundary_vertices = true;
  EXPECT_GT(caught(boundary), 0) << "pinning boundary vertices (corner rule) went unnoticed";
  CatmullClarkFaults blend;
  blend.no_fractional_blend = true;
  EXPECT_GT(caught(blend), 0) << "dropping the fractional blend went unnoticed";
  CatmullClarkFaults weights;
  weights.wrong_crease_weights = true;
  EXPECT_GT(caught(weights), 0) << "wrong crease weights went unnoticed";
}

// The cube: every refined vertex on the cube's surface, the 8 corners fixed.
void expect_cube(const std::vector<std::array<double, 3>>& positions, const std::vector<std::array<double, 3>>& corners,
                 const std::vector<int>& corner_index, const char* who) {
  for (const auto& p : positions) {
    const double m = std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
    EXPECT_NEAR(m, 1.0, 1e-12) << who << ": a vertex off the cube's surface";
  }
  for (std::size_t k = 0; k < corners.size(); ++k)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(positions[static_cast<std::size_t>(corner_index[k])][a], corners[k][a]) << who;
}

TEST(CatmullClarkOsd, SharpCubeStaysACubeInBoth) {
  const MeshArrays cube = test::cube_from_corpus();
  ASSERT_EQ(cube.vertex_count(), 8);
  const auto ref = subdivide_catmull_clark(cube, kLevels);
  ASSERT_EQ(ref.size(), static_cast<std::size_t>(kLevels + 1));
  const OsdResult osd = osd_refine_uniform(test::to_osd_input(cube, OsdScheme::CatmullClark, kLevels));
  ASSERT_TRUE(osd.ok) << osd.failure;
  for (int l = 1; l <= kLevels; ++l) {
    std::vector<int> rc(8), oc(8);
    for (int v = 0; v < 8; ++v) {
      int r = v, o = v;
      for (int k = 1; k <= l; ++k) {
        r = ref[static_cast<std::size_t>(k)].child_of_parent_vertex[static_cast<std::size_t>(r)];
        o = osd.levels[static_cast<std::size_t>(k)].child_of_parent_vertex[static_cast<std::size_t>(o)];
      }
      rc[static_cast<std::size_t>(v)] = r;
      oc[static_cast<std::size_t>(v)] = o;
    }
    expect_cube(ref[static_cast<std::size_t>(l)].positions, cube.positions, rc, "reference");
    expect_cube(osd.levels[static_cast<std::size_t>(l)].positions, cube.positions, oc, "OpenSubdiv");
  }
  EXPECT_EQ(test::compare_by_parent(ref, osd, 1e-12, true), "");
  // Level 4 of a cube: 6 * 4^4 faces.
  EXPECT_EQ(ref.back().face_count(), 6 * 256);
}

TEST(CatmullClarkOsd, SmoothCubeIsNotACube) {  // the cube check can fail: without creases it rounds
  MeshArrays cube = test::cube_from_corpus();
  std::fill(cube.vertex_creases.begin(), cube.vertex_creases.end(), 0u);
  std::fill(cube.corner_edge_creases.begin(), cube.corner_edge_creases.end(), 0u);
  const auto ref = subdivide_catmull_clark(cube, 2);
  double worst = 0;
  for (const auto& p : ref.back().positions) worst = std::max(worst, 1.0 - std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}));
  EXPECT_GT(worst, 0.1);
}

TEST(CatmullClarkOsd, OracleRejectsBadIndicesWithoutCrashing) {
  OsdInput in;
  in.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  in.face_sizes = {3};
  in.face_vertices = {0, 1, -1};
  EXPECT_FALSE(osd_refine_uniform(in).ok);
  in.face_vertices = {0, 1, 3};
  EXPECT_FALSE(osd_refine_uniform(in).ok);
  in.face_vertices = {0, 1, 2};
  EXPECT_TRUE(osd_refine_uniform(in).ok);
}

}  // namespace
}  // namespace vgc
