// bone_pose.cpp — see bone_pose.h.
#include "bone_pose.h"

#include <cmath>
#include <vector>

namespace vgc {

std::array<double, 4> quat_multiply(const std::array<double, 4>& a, const std::array<double, 4>& b) {
  const double ax = a[0], ay = a[1], az = a[2], aw = a[3];
  const double bx = b[0], by = b[1], bz = b[2], bw = b[3];
  return {aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
          aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz};
}

std::array<double, 4> quat_normalize(const std::array<double, 4>& q) {
  // Scaled as hypot does: divide by the largest |component| first, so that
  // the squares summed below lie in [1, 4] and neither underflow (2e-162:
  // its square is below the smallest normal double) nor overflow (1e300).
  // Every finite non-zero quaternion (all that bone_create accepts,
  // BONE-VALUE-1) is thus normalized to the rotation it is.
  double m = 0;
  for (double c : q) {
    if (!std::isfinite(c)) return {0, 0, 0, 1};
    m = std::fmax(m, std::fabs(c));
  }
  if (!(m > 0)) return {0, 0, 0, 1};
  std::array<double, 4> r{q[0] / m, q[1] / m, q[2] / m, q[3] / m};
  const double n = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
  for (double& c : r) c /= n;
  if (q[3] < 0)  // the sign as sent: a w that underflows to -0 here still flips
    for (double& c : r) c = -c;
  return r;
}

std::array<double, 3> quat_rotate(const std::array<double, 4>& q, const std::array<double, 3>& v) {
  const std::array<double, 4> p{v[0], v[1], v[2], 0};
  const std::array<double, 4> conj{-q[0], -q[1], -q[2], q[3]};
  const auto r = quat_multiply(quat_multiply(q, p), conj);
  return {r[0], r[1], r[2]};
}

DerivedRule bone_pose_rule(const Node& node, std::uint16_t id) {
  const auto& bones = node.bones();
  const auto it = bones.find(id);
  if (it == bones.end()) return DerivedRule::BonePosePerBone;
  const std::uint16_t parent = it->second.parent;
  if (parent == kNone16) return DerivedRule::BonePoseRoot;
  return bones.count(parent) ? DerivedRule::BonePoseChained : DerivedRule::BonePoseParentMissing;
}

std::map<std::uint16_t, BonePose> bone_world_poses(const Node& node) {
  std::map<std::uint16_t, BonePose> poses;
  const auto& bones = node.bones();
  for (const auto& [id, unused] : bones) {
    // Walk up to the nearest ancestor already posed (or a root), then come
    // back down. The forest invariant bounds the walk by the bone count.
    std::vector<std::uint16_t> chain;
    for (std::uint16_t b = id; bones.count(b) && !poses.count(b) && chain.size() <= bones.size();
         b = bones.at(b).parent)
      chain.push_back(b);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const Bone& bone = bones.at(*it);
      BonePose pose;
      pose.rule = bone_pose_rule(node, *it);
      const auto parent = poses.find(bone.parent);  // posed before it: the chain is walked down
      if (pose.rule != DerivedRule::BonePoseChained || parent == poses.end()) {  // a root
        pose.pos = bone.pos;
        pose.rot = quat_normalize(bone.rot);
      } else {
        const BonePose& P = parent->second;
        pose.rot = quat_normalize(quat_multiply(P.rot, quat_normalize(bone.rot)));
        const auto d = quat_rotate(P.rot, bone.pos);
        pose.pos = {P.pos[0] + d[0], P.pos[1] + d[1], P.pos[2] + d[2]};
      }
      poses[*it] = pose;
    }
  }
  return poses;
}

}  // namespace vgc
