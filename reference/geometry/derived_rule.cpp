// derived_rule.cpp — see derived_rule.h. One entry per rule, in enum order
// (a static_assert counts them, a test checks the order).
#include "derived_rule.h"

namespace vgc {
namespace {

// clang-format off
constexpr DerivedRuleInfo kDerivedRules[] = {
    {DerivedRule::None, "none", false, "no rule"},
    {DerivedRule::VertexCreaseConstant, "derived.vertex_crease.constant", false,
     "with no layer named, every vertex's crease is the constant crease_set_vertex sent (2.6.2)"},
    {DerivedRule::VertexCreaseLayer, "derived.vertex_crease.layer", false,
     "with a VERTEX_UINT32 layer named, each vertex's crease is its slot in that layer, resolved when read (2.6.2)"},
    {DerivedRule::VertexCreaseLayerMissing, "derived.vertex_crease.layer_missing", false,
     "with a layer named that does not exist or is not VERTEX_UINT32, every vertex's crease is the constant (2.6.2, "
     "silent: the suite's reading)"},
    {DerivedRule::VertexCreaseInitial, "derived.vertex_crease.initial", false,
     "with vertex creases never set, every vertex's crease is a fresh node's constant 0: smooth (2.6.4, the "
     "suite's reading)"},
    {DerivedRule::EdgeCreaseConstant, "derived.edge_crease.constant", false,
     "with no layer named, every edge's crease is the constant crease_set_edge sent (2.6.2)"},
    {DerivedRule::EdgeCreaseLayer, "derived.edge_crease.layer", false,
     "with a POLYGON_CORNER_UINT32 layer named, the crease of polygon p's edge from corner i is slot p, component "
     "i, resolved when read (2.6.2, README)"},
    {DerivedRule::EdgeCreaseLayerMissing, "derived.edge_crease.layer_missing", false,
     "with a layer named that does not exist or is not POLYGON_CORNER_UINT32, every edge's crease is the constant "
     "(2.6.2, silent: the suite's reading)"},
    {DerivedRule::EdgeCreaseInitial, "derived.edge_crease.initial", false,
     "with edge creases never set, every edge's crease is a fresh node's constant 0: smooth (2.6.4, the suite's "
     "reading)"},
    {DerivedRule::EdgePerCorner, "derived.edge_crease.per_corner", true,
     "a polygon has one edge per used corner, from corner i to i+1 wrapping to 0: three for a triangle (fourth "
     "corner 0xFFFFFFFF), four for a quad (2.6.2, README)"},
    {DerivedRule::BonePoseRoot, "derived.bone_pose.root", false,
     "a bone whose parent is 0xFFFF is a root: its world pose is its own position and its rotation normalized "
     "(2.6.3)"},
    {DerivedRule::BonePoseParentMissing, "derived.bone_pose.parent_missing", false,
     "a bone whose parent id names no live bone is a root as well: its own position, its rotation normalized "
     "(2.6.3: a non-existing parent means no parent)"},
    {DerivedRule::BonePoseChained, "derived.bone_pose.chained", false,
     "a bone with a live parent is posed in its parent's frame: world_rot = parent_rot * rot, world_pos = "
     "parent_pos + parent_rot applied to pos (2.6.3: downstream bones move with their parent)"},
    {DerivedRule::BonePosePerBone, "derived.bone_pose.per_bone", true,
     "every live bone has one bone_pose line, and no other id has one (2.6.3)"},
};
// clang-format on
static_assert(sizeof(kDerivedRules) / sizeof(kDerivedRules[0]) == kDerivedRuleCount,
              "one DerivedRuleInfo per DerivedRule");

}  // namespace

const DerivedRuleInfo& derived_rule_info(DerivedRule r) {
  const auto i = static_cast<std::size_t>(r);
  return i < kDerivedRuleCount ? kDerivedRules[i] : kDerivedRules[0];
}

std::string_view derived_rule_name(DerivedRule r) { return derived_rule_info(r).name; }

bool parse_derived_rule_name(std::string_view name, DerivedRule* out) {
  for (const auto& info : kDerivedRules)
    if (info.name == name) {
      *out = info.rule;
      return true;
    }
  return false;
}

}  // namespace vgc
