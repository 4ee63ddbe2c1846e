// face_normals_test.cpp — the front normal convention on the spec's cube
// (expected directions derived by hand from its geometry) and Newell's
// normal on awkward polygons.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <random>

#include "face_normals.h"
#include "manifold_shapes.h"

namespace vgc {
namespace {

void expect_near(const Vec3& got, const Vec3& want, double tol = 1e-12) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[static_cast<std::size_t>(i)], want[static_cast<std::size_t>(i)], tol) << "component " << i;
}

// 000 section 2.6.4: polygons top, bottom, front, right, back, left; the
// cube "viewed along the negative Z-axis, with positive Y being upwards", so
// front is +z and right is +x. Read off the vertex table: face 0 has y = 1
// everywhere, face 1 y = -1, face 2 z = 1, face 3 x = 1, face 4 z = -1,
// face 5 x = -1. Outward normals, one per face:
TEST(FaceNormals, SpecCubeNormalsPointOutwards) {
  const MeshArrays cube = test::spec_cube();
  const Vec3 outward[6] = {{0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {1, 0, 0}, {0, 0, -1}, {-1, 0, 0}};
  for (int f = 0; f < 6; ++f) {
    SCOPED_TRACE(f);
    expect_near(face_normal(cube, f), outward[f]);
    // Each face of a 2 x 2 x 2 cube has area 4.
    expect_near(face_area_vector(cube, f), scale(outward[f], 4.0));
  }
}

// 002's n = (C-B) x (A-B) is the anti-clockwise normal; the Verse front is
// its opposite. Top face corners A=(-1,1,-1), B=(1,1,-1), C=(1,1,1):
// (C-B) x (A-B) = (0,0,2) x (-2,0,0) = (0,-4,0).
TEST(FaceNormals, FormulaOf002IsTheBackSide) {
  expect_near(triangle_normal_anticlockwise({-1, 1, -1}, {1, 1, -1}, {1, 1, 1}), {0, -4, 0});
  expect_near(polygon_area_vector({{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}}), {0, 2, 0});
}

// Three collinear corners first: a corner-triple cross product would be 0,
// Newell's sum is not. (0,0,0) (1,0,0) (2,0,0) (1,1,0) runs anti-clockwise
// seen from +z, so its front faces -z; it is a triangle of area 1.
TEST(FaceNormals, NewellSurvivesCollinearCorners) {
  expect_near(polygon_area_vector({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}}), {0, 0, -1});
}

// A non-planar quad (a "bow" of height h over the unit square, clockwise
// seen from +z): its projection on z = 0 is the unit square, so the area
// vector's z is exactly 1 whatever h is; the x and y parts cancel by symmetry.
TEST(FaceNormals, NonPlanarQuad) {
  const double h = 0.3;
  const Vec3 n = polygon_area_vector({{0, 0, 0}, {0, 1, h}, {1, 1, 0}, {1, 0, h}});
  expect_near(n, {0, 0, 1});
}

TEST(FaceNormals, DegenerateFaceGivesZero) {
  const MeshArrays m = test::make_mesh({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {{0, 1, 2}});
  expect_near(face_normal(m, 0), {0, 0, 0});
}

// Rotating a polygon's corner list or rigidly rotating its points changes
// its normal accordingly.
RC_GTEST_PROP(FaceNormals, FollowsRotationsAndIgnoresFirstCorner, (unsigned seed)) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, 1);
  std::vector<Vec3> p;
  const int n = 3 + static_cast<int>(rng() % 4);
  for (int i = 0; i < n; ++i) p.push_back({g(rng), g(rng), g(rng)});
  const Vec3 a = polygon_area_vector(p);
  std::vector<Vec3> q(p.begin() + 1, p.end());
  q.push_back(p[0]);
  const Vec3 b = polygon_area_vector(q);
  for (int i = 0; i < 3; ++i) RC_ASSERT(std::abs(a[static_cast<std::size_t>(i)] - b[static_cast<std::size_t>(i)]) < 1e-12);
  // Rotation about a random unit axis u by angle t (Rodrigues).
  const Vec3 u = normalized({g(rng), g(rng), g(rng)});
  const double t = g(rng);
  auto rot = [&](const Vec3& v) {
    return add(add(scale(v, std::cos(t)), scale(cross(u, v), std::sin(t))), scale(u, dot(u, v) * (1 - std::cos(t))));
  };
  std::vector<Vec3> r;
  for (const auto& v : p) r.push_back(add(rot(v), Vec3{3, -2, 1}));
  const Vec3 c = polygon_area_vector(r), want = rot(a);
  for (int i = 0; i < 3; ++i) RC_ASSERT(std::abs(c[static_cast<std::size_t>(i)] - want[static_cast<std::size_t>(i)]) < 1e-9);
}

}  // namespace
}  // namespace vgc
