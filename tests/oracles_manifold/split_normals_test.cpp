// split_normals_test.cpp — sharp edges, smooth fans, per-corner normals and
// custom normals in fan normal spaces (spec 003), on the spec's cube with
// hand-derived answers and as properties of random meshes.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>

#include "command_text.h"
#include "crease.h"
#include "manifold_shapes.h"
#include "mesh_topology.h"
#include "node.h"
#include "split_normals.h"

namespace vgc {
namespace {

bool near(const Vec3& a, const Vec3& b, double tol) {
  return std::abs(a[0] - b[0]) <= tol && std::abs(a[1] - b[1]) <= tol && std::abs(a[2] - b[2]) <= tol;
}

std::string show(const Vec3& v) {
  std::ostringstream o;
  o << '(' << v[0] << ", " << v[1] << ", " << v[2] << ')';
  return o.str();
}

// Corner of face f holding vertex v.
int corner_of(const MeshArrays& m, int f, int v) {
  for (int i = 0; i < m.face_sizes[static_cast<std::size_t>(f)]; ++i)
    if (m.face_vertices[static_cast<std::size_t>(m.face_offsets[static_cast<std::size_t>(f)] + i)] == v)
      return m.face_offsets[static_cast<std::size_t>(f)] + i;
  return -1;
}

MeshArrays cube_from_corpus() {
  std::ifstream in(std::string(VGC_SOURCE_DIR) + "/corpora/examples/cube.vgc");
  std::stringstream text;
  text << in.rdbuf();
  std::vector<Command> commands;
  TextError error;
  EXPECT_TRUE(parse_commands(text.str(), &commands, &error)) << error.to_string();
  Node node;
  for (const Command& c : commands) EXPECT_EQ(node.apply(c), Reason::Ok);
  return extract_mesh(node);
}

// The spec cube's creases are all 0xFFFFFFFF: 24 fans, every corner carries
// its face's outward normal (top +y, bottom -y, front +z, right +x, back -z,
// left -x; see face_normals_test.cpp).
TEST(SplitNormals, SharpSpecCube) {
  const MeshArrays m = cube_from_corpus();
  ASSERT_EQ(m.corner_edge_creases, std::vector<std::uint32_t>(24, kCreaseMax));
  const SplitNormals s = compute_split_normals(m);
  ASSERT_EQ(s.status, MeshStatus::Ok);
  EXPECT_EQ(s.fan_count, 24);
  const Vec3 outward[6] = {{0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {1, 0, 0}, {0, 0, -1}, {-1, 0, 0}};
  for (int c = 0; c < 24; ++c) EXPECT_TRUE(near(s.corner_normals[static_cast<std::size_t>(c)], outward[c / 4], 1e-12)) << c;
}

// Creases 0: one fan per vertex; three right angles of three orthogonal
// faces, so the angle-weighted normal is (n1 + n2 + n3) / sqrt 3, which for
// a cube centred at 0 is the vertex position / sqrt 3.
TEST(SplitNormals, SmoothCube) {
  const MeshArrays m = test::spec_cube();
  const SplitNormals s = compute_split_normals(m);
  EXPECT_EQ(s.fan_count, 8);
  for (std::size_t c = 0; c < 24; ++c) {
    const Vec3 p = m.positions[static_cast<std::size_t>(m.face_vertices[c])];
    EXPECT_TRUE(near(s.corner_normals[c], scale(p, 1 / std::sqrt(3.0)), 1e-12)) << c << " " << show(s.corner_normals[c]);
  }
}

// Edge 0-1 tagged only on the top face's corner 0 (edge 0->1), edge 0-3 only
// on the left face's corner 0 (face 5 = 0,3,4,7, edge 0->3): one tag per
// edge makes it sharp. Vertex 0 splits into {top} and {back, left}; vertex 1
// (one sharp edge: its fan is cut open, not split) keeps one fan of top,
// right and back: (1,1,-1)/sqrt 3; likewise vertex 3: (-1,1,1)/sqrt 3.
TEST(SplitNormals, OneTagPerEdgeIsEnough) {
  MeshArrays m = test::spec_cube();
  m.corner_edge_creases[0] = kCreaseMax;       // face 0 corner 0: edge 0->1
  m.corner_edge_creases[5 * 4] = kCreaseMax;   // face 5 corner 0: edge 0->3
  const SplitNormals s = compute_split_normals(m);
  EXPECT_EQ(s.fan_count, 9);
  const double r2 = 1 / std::sqrt(2.0), r3 = 1 / std::sqrt(3.0);
  auto normal_at = [&](int f, int v) { return s.corner_normals[static_cast<std::size_t>(corner_of(m, f, v))]; };
  EXPECT_TRUE(near(normal_at(0, 0), {0, 1, 0}, 1e-12)) << show(normal_at(0, 0));
  EXPECT_TRUE(near(normal_at(4, 0), {-r2, 0, -r2}, 1e-12)) << show(normal_at(4, 0));
  EXPECT_TRUE(near(normal_at(5, 0), {-r2, 0, -r2}, 1e-12));
  for (int f : {0, 3, 4}) EXPECT_TRUE(near(normal_at(f, 1), {r3, r3, -r3}, 1e-12)) << f;
  for (int f : {0, 2, 5}) EXPECT_TRUE(near(normal_at(f, 3), {-r3, r3, r3}, 1e-12)) << f;
}

// Boundary edges are sharp but cut a half-disc fan open only: a flat grid,
// clockwise seen from +z, has one fan per vertex, all with normal +z.
TEST(SplitNormals, FlatGridBoundary) {
  const MeshArrays m = test::grid(3, 2, true);
  const SplitNormals s = compute_split_normals(m);
  EXPECT_EQ(s.fan_count, m.vertex_count());
  for (const Vec3& n : s.corner_normals) EXPECT_TRUE(near(n, {0, 0, 1}, 1e-12)) << show(n);
}

// A face flipped in a smooth closed mesh meets each neighbour with the same
// winding: all its edges are sharp, each of its corners is a fan of its own
// with the flipped face's (inward) normal; a fin's non-manifold edge is sharp.
TEST(SplitNormals, OpposedWindingAndNonManifoldEdgesAreSharp) {
  const MeshArrays m = test::flip_face(test::octahedron(), 2);
  const MeshTopology t = classify_mesh(m);
  const SplitNormals s = compute_split_normals(m, t);
  const Vec3 inward = face_normal(m, 2);
  for (int i = 0; i < 3; ++i) {
    const int c = m.face_offsets[2] + i;
    EXPECT_TRUE(near(s.corner_normals[static_cast<std::size_t>(c)], inward, 1e-12));
    EXPECT_TRUE(s.edge_sharp[static_cast<std::size_t>(t.corner_edge[static_cast<std::size_t>(c)])]);
  }
  EXPECT_EQ(s.fan_count, 6 + 3);  // 6 vertices, 3 of them with the flipped corner apart
  const MeshArrays fin = test::add_fin(test::spec_cube(), 0, 0);
  const MeshTopology tf = classify_mesh(fin);
  const SplitNormals sf = compute_split_normals(fin, tf);
  EXPECT_TRUE(sf.edge_sharp[static_cast<std::size_t>(tf.corner_edge[0])]);
}

TEST(SplitNormals, InvalidInputGivesAStatus) {
  EXPECT_EQ(compute_split_normals(test::make_mesh({{0, 0, 0}}, {{0, 0, 0}})).status, MeshStatus::RepeatedVertex);
}

// ---- properties on random meshes ----


MeshArrays random_normal_mesh(unsigned seed, double tag_probability) {
  std::mt19937 rng(seed);
  MeshArrays m;
  switch (rng() % 5) {
    case 0: m = test::spec_cube(); break;
    case 1: m = test::octahedron(); break;
    case 2: m = test::grid(1 + static_cast<int>(rng() % 4), 1 + static_cast<int>(rng() % 3), rng() % 2 == 0, &rng); break;
    case 3: m = test::torus(3 + static_cast<int>(rng() % 3), 3 + static_cast<int>(rng() % 3)); break;
    default: m = test::moebius(3 + static_cast<int>(rng() % 4)); break;
  }
  if (rng() % 4 == 0) m = test::flip_face(m, static_cast<int>(rng() % static_cast<unsigned>(m.face_count())));
  m = test::rotate_and_shuffle_faces(test::renumber_vertices(m, rng), rng);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  for (auto& p : m.positions)
    for (double& x : p) x += jitter(rng);
  std::bernoulli_distribution tag(tag_probability);
  for (auto& c : m.corner_edge_creases) c = tag(rng) ? kCreaseMax : (rng() % 2 ? 0u : 0x80000000u);
  return m;
}

// A random rigid motion (rotation by a unit quaternion, then a shift).
struct Motion {
  std::array<std::array<double, 3>, 3> r{};
  Vec3 shift{};
  Vec3 rotate(const Vec3& v) const {
    return {dot(r[0], v), dot(r[1], v), dot(r[2], v)};
  }
  Vec3 apply(const Vec3& v) const { return add(rotate(v), shift); }
};

Motion random_motion(std::mt19937& rng) {
  std::normal_distribution<double> g(0, 1);
  double w = g(rng), x = g(rng), y = g(rng), z = g(rng);
  const double l = std::sqrt(w * w + x * x + y * y + z * z);
  w /= l, x /= l, y /= l, z /= l;
  Motion m;
  m.r = {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
  m.shift = {g(rng) * 5, g(rng) * 5, g(rng) * 5};
  return m;
}

// Two faces meeting at a smooth edge give its end vertices one normal.
RC_GTEST_PROP(SplitNormals, SmoothEdgesShareNormals, (unsigned seed)) {
  const MeshArrays m = random_normal_mesh(seed, 0.3);
  const MeshTopology t = classify_mesh(m);
  const SplitNormals s = compute_split_normals(m, t);
  RC_ASSERT(s.status == MeshStatus::Ok);
  for (std::size_t e = 0; e < t.edges.size(); ++e) {
    if (s.edge_sharp[e]) continue;
    const int c1 = t.edge_corners[static_cast<std::size_t>(t.edge_corner_offsets[e])];
    const int c2 = t.edge_corners[static_cast<std::size_t>(t.edge_corner_offsets[e]) + 1];
    for (int v : {t.edges[e].a, t.edges[e].b}) {
      const int x = corner_of(m, t.corner_face[static_cast<std::size_t>(c1)], v);
      const int y = corner_of(m, t.corner_face[static_cast<std::size_t>(c2)], v);
      RC_ASSERT(s.corner_fan[static_cast<std::size_t>(x)] == s.corner_fan[static_cast<std::size_t>(y)]);
      RC_ASSERT(s.corner_normals[static_cast<std::size_t>(x)] == s.corner_normals[static_cast<std::size_t>(y)]);
    }
  }
  // Every corner of a fan has the fan's normal, and a fan is at one vertex.
  for (std::size_t c = 0; c < m.face_vertices.size(); ++c) {
    const auto fan = static_cast<std::size_t>(s.corner_fan[c]);
    RC_ASSERT(s.corner_normals[c] == s.fan_normals[fan]);
    RC_ASSERT(s.fan_vertex[fan] == m.face_vertices[c]);
  }
}

RC_GTEST_PROP(SplitNormals, AllSharpGivesFaceNormals, (unsigned seed)) {
  MeshArrays m = random_normal_mesh(seed, 1.0);
  const MeshTopology t = classify_mesh(m);
  const SplitNormals s = compute_split_normals(m, t);
  for (std::size_t c = 0; c < m.face_vertices.size(); ++c)
    RC_ASSERT(near(s.corner_normals[c], face_normal(m, t.corner_face[c]), 1e-12));
}

RC_GTEST_PROP(SplitNormals, NormalsTurnWithTheMesh, (unsigned seed)) {
  const MeshArrays m = random_normal_mesh(seed, 0.3);
  std::mt19937 rng(seed ^ 0x9e3779b9u);
  const Motion motion = random_motion(rng);
  MeshArrays moved = m;
  for (auto& p : moved.positions) p = motion.apply(p);
  const SplitNormals a = compute_split_normals(m), b = compute_split_normals(moved);
  RC_ASSERT(a.corner_fan == b.corner_fan);
  for (std::size_t c = 0; c < a.corner_normals.size(); ++c) {
    const Vec3 want = motion.rotate(a.corner_normals[c]);
    RC_ASSERT(near(b.corner_normals[c], want, 1e-9));
  }
}

// A custom normal set in a fan's space comes back, and after a rigid motion
// of the mesh it comes back turned with it.
RC_GTEST_PROP(SplitNormals, CustomNormalsRoundTrip, (unsigned seed)) {
  const MeshArrays m = random_normal_mesh(seed, 0.3);
  std::mt19937 rng(seed ^ 0x5bd1e995u);
  std::normal_distribution<double> g(0, 1);
  const SplitNormals s = compute_split_normals(m);
  const Motion motion = random_motion(rng);
  MeshArrays moved = m;
  for (auto& p : moved.positions) p = motion.apply(p);
  const SplitNormals sm = compute_split_normals(moved);
  std::vector<std::optional<CustomNormal>> custom(static_cast<std::size_t>(s.fan_count));
  std::vector<Vec3> wanted(custom.size());
  for (int fan = 0; fan < s.fan_count; ++fan) {
    const FanNormalSpace space = fan_normal_space(m, s, fan);
    RC_ASSERT(space.valid);
    RC_ASSERT(std::abs(dot(space.normal, space.reference)) < 1e-12);
    const Vec3 d = normalized({g(rng), g(rng), g(rng)});
    const CustomNormal cn = encode_custom_normal(space, d);
    RC_ASSERT(near(decode_custom_normal(space, cn), d, 1e-12));
    // The moved mesh's space turned with it: the same angles give R d.
    const FanNormalSpace moved_space = fan_normal_space(moved, sm, fan);
    RC_ASSERT(near(moved_space.reference, motion.rotate(space.reference), 1e-9));
    RC_ASSERT(near(decode_custom_normal(moved_space, cn), motion.rotate(d), 1e-9));
    custom[static_cast<std::size_t>(fan)] = cn;
    wanted[static_cast<std::size_t>(fan)] = d;
  }
  const std::vector<Vec3> corners = corner_normals_with_custom(m, s, custom);
  for (std::size_t c = 0; c < corners.size(); ++c)
    RC_ASSERT(near(corners[c], wanted[static_cast<std::size_t>(s.corner_fan[c])], 1e-12));
}

}  // namespace
}  // namespace vgc
