// bone_pose.h — a bone's pose in the node's space, after walking its parents.
//
// Spec: 000 section 2.6.3: bones have "a position ... a rotation", parents
// define skeletons, and "if you rotate any bone, all bones 'downstream' of
// it will rotate, too". The text's drawing algorithm is missing, so:
//
// Decision: a bone's position and rotation are relative to its parent's
// frame. For a root (parent missing):  world_rot = normalize(rot),
// world_pos = pos. Otherwise:  world_rot = normalize(P.world_rot * normalize(rot)),
// world_pos = P.world_pos + rotate(P.world_rot, pos). Quaternions are
// (x, y, z, w); the reported quaternion has w >= 0 (q and -q are one rotation).
// The three cases are named rules (derived_rule.h): derived.bone_pose.root
// (parent 0xFFFF), .parent_missing (a parent id naming no live bone) and
// .chained; each pose records the one that decided it.
#pragma once

#include <array>
#include <cstdint>
#include <map>

#include "derived_rule.h"
#include "node.h"

namespace vgc {

struct BonePose {
  std::array<double, 3> pos{};
  std::array<double, 4> rot{0, 0, 0, 1};
  DerivedRule rule = DerivedRule::BonePoseRoot;  // the rule that decided it (bone_pose_rule)
};

// Poses of every bone, by id. The node's bones form a forest (node.cpp).
std::map<std::uint16_t, BonePose> bone_world_poses(const Node& node);
// The rule that decides the pose of bone `id`: root, parent_missing or
// chained for a live bone (the branch bone_world_poses takes), per_bone for
// an id with no bone (it has no pose line).
DerivedRule bone_pose_rule(const Node& node, std::uint16_t id);

// Quaternion helpers, (x, y, z, w).
std::array<double, 4> quat_multiply(const std::array<double, 4>& a, const std::array<double, 4>& b);
// Unit length with w >= 0, scaled by the largest |component| first (as
// hypot), so any finite non-zero q, however tiny or huge its components,
// gives the rotation it is; zero or non-finite q gives the identity.
std::array<double, 4> quat_normalize(const std::array<double, 4>& q);
std::array<double, 3> quat_rotate(const std::array<double, 4>& q, const std::array<double, 3>& v);

}  // namespace vgc
