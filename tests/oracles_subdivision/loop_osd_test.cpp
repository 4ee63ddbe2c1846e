// Checks reference/geometry/loop_subdivision.h against OpenSubdiv's SCHEME_LOOP
// (oracles/osd_subdivision.h): all-triangle meshes (triangle grids with
// holes, closed shapes of valence 3..7, random renumbering) with random
// creases; every vertex of levels 1..4 agrees within 1e-9 * scale, matched
// by parent component, and each reference child triangle is one of
// OpenSubdiv's child faces of the same parent (same vertices, same
// orientation). Each seeded fault of LoopFaults makes the comparison fail.
#include <gtest/gtest.h>

#include "loop_subdivision.h"
#include "osd_subdivision.h"
#include "subdivision_support.h"

namespace vgc {
namespace {

constexpr int kLevels = 4;

// Splits every quad along its 0-2 diagonal.
MeshArrays triangulated(const MeshArrays& m) {
  std::vector<std::vector<int>> faces;
  for (const auto& f : test::faces_of(m)) {
    if (f.size() == 3) {
      faces.push_back(f);
    } else {
      faces.push_back({f[0], f[1], f[2]});
      faces.push_back({f[0], f[2], f[3]});
    }
  }
  MeshArrays t = test::make_mesh(m.positions, faces);
  t.vertex_creases = m.vertex_creases;
  return t;
}

std::vector<MeshArrays> corpus() {
  std::vector<MeshArrays> out;
  for (unsigned seed = 1; seed <= 10; ++seed) {
    std::mt19937 rng(seed + 100);
    MeshArrays m;
    switch (seed % 5) {
      case 0: m = test::grid_with_holes(5, 4, 1.0, 3, rng); break;
      case 1: m = test::torus(6, 5, 1.0, rng); break;
      case 2: m = test::octahedron(rng); break;
      case 3: m = triangulated(test::cube_with_triangles(rng)); break;  // valences 3..6
      default: m = triangulated(test::grid_with_holes(4, 3, 0.5, 2, rng)); break;
    }
    test::add_random_creases(m, 0.3, 0.3, rng);
    out.push_back(std::move(m));
  }
  return out;
}

std::string compare(const MeshArrays& m, const LoopFaults& faults = {}) {
  const auto ref = subdivide_loop(m, kLevels, faults);
  if (ref.empty()) return "reference refused the mesh";
  const OsdResult osd = osd_refine_uniform(test::to_osd_input(m, OsdScheme::Loop, kLevels));
  return test::compare_by_parent(ref, osd, 1e-9 * test::mesh_scale(m), false);
}

TEST(LoopOsd, RandomTriangleMeshesAgreeAtEveryLevel) {
  int i = 0;
  for (const MeshArrays& m : corpus()) EXPECT_EQ(compare(m), "") << "mesh " << i++;
}

TEST(LoopOsd, EverySeededFaultIsCaught) {
  const auto meshes = corpus();
  auto caught = [&](const LoopFaults& f) {
    int n = 0;
    for (const MeshArrays& m : meshes) n += compare(m, f).empty() ? 0 : 1;
    return n;
  };
  LoopFaults warren;
  warren.warren_weights = true;
  EXPECT_GT(caught(warren), 0) << "Warren's weights went unnoticed";
  LoopFaults blend;
  blend.no_fractional_blend = true;
  EXPECT_GT(caught(blend), 0) << "dropping the fractional blend went unnoticed";
}

TEST(LoopOsd, OracleRefusesQuadsForLoop) {
  std::mt19937 rng(1);
  const MeshArrays quads = test::grid_with_holes(2, 2, 0.0, 0, rng);
  EXPECT_FALSE(osd_refine_uniform(test::to_osd_input(quads, OsdScheme::Loop, 1)).ok);
  EXPECT_TRUE(subdivide_loop(quads, 1).empty());
}

}  // namespace
}  // namespace vgc
