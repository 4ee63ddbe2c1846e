// derived_document.h — canonical text of what a node's stored data means,
// made for diffing.
//
// Spec: 000 section 2.6.2 (effective creases, crease.h) and 2.6.3 (bone
// poses, bone_pose.h); docs/commands.md 6.2 "Derived document" defines the
// format for other implementations.
//
// The derived document is deterministic (ids ascending, numbers in the exact
// forms of number_text.h) and ends in a line "end": the effective crease of
// every live vertex and polygon edge, and every bone's world pose. Two
// conforming nodes fed the same commands agree exactly on creases and within
// rounding on bone poses. Its companion, the snapshot of what is stored, is
// printed by the node part (reference/node/snapshot.h); this one lives with
// the geometry because it interprets the state. Every line is decided by a
// named rule (derived_rule.h), which derived_rule_of names.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "derived_rule.h"
#include "node.h"

namespace vgc {

std::string print_derived(const Node& node);

// Its lines one identity at a time, exactly as print_derived prints them
// (each ending in "\n"; print_derived is made of them), for a digest that
// follows the node line by line (document_digest.h).
inline constexpr const char* kDerivedHeader = "vgc-derived 1\n";
std::string derived_vertex_line(const Node& node, std::uint32_t vertex_id);
// Every "edge_crease" line of the live polygon `polygon_id` (`polygon` its slot).
std::string derived_polygon_lines(const Node& node, std::uint32_t polygon_id, const Slot& polygon);
std::map<std::uint16_t, std::string> derived_bone_lines(const Node& node);  // bone id -> "bone_pose" line

// The rule that decided the values of the derived line `line` of `node`,
// by its kind and identity (the first words; the values are not read):
// "vertex_crease" and "edge_crease" lines are all decided by their
// setting's rule (crease.h), whatever their element; a "bone_pose <id>"
// line by bone_pose_rule (per_bone for an id with no bone, or no bone id
// at all). So it also
// answers for a line only an implementation prints, and for the forms a
// NodeDigest reports of a line gone ("edge_crease 5", "bone_pose 3").
// DerivedRule::None for any other line (the header, "end", a malformed one).
DerivedRule derived_rule_of(const Node& node, std::string_view line);
// The rule that decides which lines of `kind` exist, when a derived rule
// does: "edge_crease" derived.edge_crease.per_corner (a polygon's corner
// count), "bone_pose" derived.bone_pose.per_bone. None for "vertex_crease":
// one line per live vertex, as the snapshot's vertex lines (judged first).
DerivedRule derived_place_rule(std::string_view kind);

}  // namespace vgc
