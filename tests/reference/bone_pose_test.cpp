// bone_pose_test.cpp — bone world poses (reference/geometry/bone_pose.cpp). Every
// expected value is worked out by hand in the comments, from the rule in
// bone_pose.h: root: (pos, normalize(rot)); child of P: world_rot =
// normalize(P.rot * normalize(rot)), world_pos = P.pos + rotate(P.rot, pos).
#include <gtest/gtest.h>

#include <cmath>

#include "bone_pose.h"
#include "test_util.h"

namespace vgc {
namespace {

using test::A;
using test::apply_all;

const double kS = std::sqrt(0.5);  // sin 45 = cos 45

std::string bone(int id, int parent, const std::string& pos, const std::string& rot) {
  return "bone_create " + std::to_string(id) + " \"w\" \"\" " + std::to_string(parent) + " " + pos + " \"\" " +
         rot + " \"\"";
}

void expect_pose(const BonePose& p, std::array<double, 3> pos, std::array<double, 4> rot, const char* what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.pos[i], pos[i], 1e-12) << what << " pos[" << i << "]";
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(p.rot[i], rot[i], 1e-12) << what << " rot[" << i << "]";
}

TEST(BonePose, RootPoseIsItsPositionAndNormalizedRotationWithNonNegativeW) {
  Node n;
  apply_all(n, "layer_create 2 \"w\" VERTEX_REAL 0 0\n");
  ASSERT_EQ(A(n, bone(0, 0xFFFF, "1 2 3", "0 0 2 0")), Reason::Ok);  // 180 about Z, length 2
  ASSERT_EQ(A(n, bone(1, 77, "-1 0 0", "0 0 0 -3")), Reason::Ok);    // identity as -3: w flips to +1
  ASSERT_EQ(A(n, bone(2, 0xFFFF, "0 0 0", "0 0 -1 -1")), Reason::Ok);  // -90 about Z written as -q
  const auto poses = bone_world_poses(n);
  ASSERT_EQ(poses.size(), 3u);
  expect_pose(poses.at(0), {1, 2, 3}, {0, 0, 1, 0}, "bone 0");
  expect_pose(poses.at(1), {-1, 0, 0}, {0, 0, 0, 1}, "bone 1");
  expect_pose(poses.at(2), {0, 0, 0}, {0, 0, kS, kS}, "bone 2");  // -(0,0,-s,-s)
}

TEST(BonePose, RotatingAParent90DegreesAboutZMovesAndRotatesEveryDownstreamBone) {
  Node n;
  apply_all(n, "layer_create 2 \"w\" VERTEX_REAL 0 0\n");
  // A chain 0 -> 1 -> 2 along +X then +Y, and 3, a root, unaffected.
  apply_all(n, bone(0, 0xFFFF, "1 0 0", "0 0 0 1") + "\n" + bone(1, 0, "2 0 0", "0 0 0 1") + "\n" +
                   bone(2, 1, "0 3 0", "0 0 0 1") + "\n" + bone(3, 0xFFFF, "5 5 5", "0 0 0 1") + "\n");
  auto poses = bone_world_poses(n);
  // Unrotated: positions add up.
  expect_pose(poses.at(0), {1, 0, 0}, {0, 0, 0, 1}, "bone 0");
  expect_pose(poses.at(1), {3, 0, 0}, {0, 0, 0, 1}, "bone 1");
  expect_pose(poses.at(2), {3, 3, 0}, {0, 0, 0, 1}, "bone 2");

  // Rotate bone 0 by 90 degrees about Z: q = (0, 0, sin 45, cos 45).
  // Rz90 maps (x, y, z) to (-y, x, z).
  ASSERT_EQ(A(n, bone(0, 0xFFFF, "1 0 0", "0 0 0.7071067811865476 0.7071067811865476")), Reason::Ok);
  poses = bone_world_poses(n);
  // Bone 0 itself stays where it is: its position is in its parent's (the node's) frame.
  expect_pose(poses.at(0), {1, 0, 0}, {0, 0, kS, kS}, "bone 0");
  // Bone 1: (1,0,0) + Rz90 (2,0,0) = (1,0,0) + (0,2,0) = (1,2,0); rotation = q.
  expect_pose(poses.at(1), {1, 2, 0}, {0, 0, kS, kS}, "bone 1");
  // Bone 2: (1,2,0) + Rz90 (0,3,0) = (1,2,0) + (-3,0,0) = (-2,2,0); rotation = q.
  expect_pose(poses.at(2), {-2, 2, 0}, {0, 0, kS, kS}, "bone 2");
  // Bone 3 is not downstream.
  expect_pose(poses.at(3), {5, 5, 5}, {0, 0, 0, 1}, "bone 3");
}

TEST(BonePose, ChildRotationComposesAfterItsParents) {
  Node n;
  apply_all(n, "layer_create 2 \"w\" VERTEX_REAL 0 0\n");
  // Parent: 90 about Z. Child: 90 about X, unnormalized (length 2), at the origin of the parent.
  // Grandchild at (0,0,1) in the child's frame.
  apply_all(n, bone(0, 0xFFFF, "0 0 0", "0 0 1 1") + "\n" + bone(1, 0, "0 0 0", "2 0 0 2") + "\n" +
                   bone(2, 1, "0 0 1", "0 0 0 1") + "\n");
  const auto poses = bone_world_poses(n);
  // qz * qx with qz = (0,0,s,s), qx = (s,0,0,s):
  //   w = s*s - 0 = 1/2;  v = s*(s,0,0) + s*(0,0,s) + (0,0,s) x (s,0,0) = (1/2, 0, 1/2) + (0, 1/2, 0).
  expect_pose(poses.at(1), {0, 0, 0}, {0.5, 0.5, 0.5, 0.5}, "bone 1");
  // (1/2,1/2,1/2,1/2) is 120 degrees about (1,1,1): x->y, y->z, z->x, so (0,0,1) -> (1,0,0).
  // Check by steps: Rx90 (0,0,1) = (0,-1,0); Rz90 (0,-1,0) = (1,0,0).
  expect_pose(poses.at(2), {1, 0, 0}, {0.5, 0.5, 0.5, 0.5}, "bone 2");
}

TEST(BonePose, MissingOrDestroyedParentMakesARootAndRecreationReattaches) {
  Node n;
  apply_all(n, "layer_create 2 \"w\" VERTEX_REAL 0 0\n");
  apply_all(n, bone(0, 0xFFFF, "10 0 0", "0 0 1 1") + "\n" + bone(1, 0, "1 0 0", "0 0 0 1") + "\n");
  expect_pose(bone_world_poses(n).at(1), {10, 1, 0}, {0, 0, kS, kS}, "attached");
  ASSERT_EQ(A(n, "bone_destroy 0"), Reason::Ok);
  expect_pose(bone_world_poses(n).at(1), {1, 0, 0}, {0, 0, 0, 1}, "root after destroy");
  ASSERT_EQ(A(n, bone(0, 0xFFFF, "0 10 0", "0 0 0 1")), Reason::Ok);
  expect_pose(bone_world_poses(n).at(1), {1, 10, 0}, {0, 0, 0, 1}, "re-attached");
}

TEST(BonePose, PosesDoNotDependOnIdOrder) {
  Node n;
  apply_all(n, "layer_create 2 \"w\" VERTEX_REAL 0 0\n");
  // Child ids below their parents' ids: 0 -> parent 5 -> parent 9 (root).
  apply_all(n, bone(0, 5, "1 0 0", "0 0 0 1") + "\n" + bone(5, 9, "0 1 0", "0 0 0 1") + "\n" +
                   bone(9, 0xFFFF, "0 0 1", "0 0 1 1") + "\n");
  const auto poses = bone_world_poses(n);
  // Bone 5: (0,0,1) + Rz90 (0,1,0) = (0,0,1) + (-1,0,0) = (-1,0,1).
  expect_pose(poses.at(5), {-1, 0, 1}, {0, 0, kS, kS}, "bone 5");
  // Bone 0: (-1,0,1) + Rz90 (1,0,0) = (-1,0,1) + (0,1,0) = (-1,1,1).
  expect_pose(poses.at(0), {-1, 1, 1}, {0, 0, kS, kS}, "bone 0");
}

// Every rotation bone_create accepts (finite, not all zero) is applied as the
// rotation it is, however tiny or huge its components: normalization scales
// by the largest |component| first (as hypot does), so squares neither
// underflow to 0 (2e-162: the plain norm squared is 4e-324, subnormal and
// rounded) nor overflow to infinity (-1e300). Both examples are 180 degrees
// about X, which maps the child's local (0,1,0) to (0,-1,0).
TEST(BonePose, ExtremeQuaternionComponentsAreNormalizedAsTheRotationTheyAre) {
  // (written rotation, the x of the reported unit quaternion: w is 0 or, once flipped to >= 0, ~0)
  const std::pair<const char*, double> cases[] = {
      {"2e-162 0 0 0", 1}, {"-1e300 0 0 0", -1}, {"1e-320 0 0 0", 1}, {"1.7e308 0 0 0", 1}, {"-1.7e308 0 0 -1e-300", 1}};
  for (const auto& [rot, sx] : cases) {
    Node n;
    apply_all(n, "layer_create 2 \"w\" VERTEX_REAL 0 0\n");
    ASSERT_EQ(A(n, bone(0, 0xFFFF, "0 0 0", rot)), Reason::Ok) << rot;
    ASSERT_EQ(A(n, bone(1, 0, "0 1 0", "0 0 0 1")), Reason::Ok) << rot;
    const auto poses = bone_world_poses(n);
    expect_pose(poses.at(0), {0, 0, 0}, {sx, 0, 0, 0}, rot);
    expect_pose(poses.at(1), {0, -1, 0}, {sx, 0, 0, 0}, rot);
  }
  // Mixed scales: 90 degrees about Z written with components near the top of the range.
  const auto q = quat_normalize({0, 0, 1e308, 1e308});
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(q[i], (std::array<double, 4>{0, 0, kS, kS})[i], 1e-15) << i;
  const auto t = quat_normalize({0, 0, -3e-320, -3e-320});  // subnormal, and -q: w flips to +
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(t[i], (std::array<double, 4>{0, 0, kS, kS})[i], 1e-15) << i;
}

TEST(BonePose, QuaternionHelpersFollowTheHamiltonProduct) {
  // i * j = k, j * i = -k (Hamilton).
  const auto k = quat_multiply({1, 0, 0, 0}, {0, 1, 0, 0});
  EXPECT_EQ(k, (std::array<double, 4>{0, 0, 1, 0}));
  const auto mk = quat_multiply({0, 1, 0, 0}, {1, 0, 0, 0});
  EXPECT_EQ(mk, (std::array<double, 4>{0, 0, -1, 0}));
  const auto v = quat_rotate({0, 0, kS, kS}, {1, 0, 0});
  EXPECT_NEAR(v[0], 0, 1e-15);
  EXPECT_NEAR(v[1], 1, 1e-15);
  EXPECT_EQ(quat_normalize({0, 0, 0, 0}), (std::array<double, 4>{0, 0, 0, 1}));
}

}  // namespace
}  // namespace vgc
