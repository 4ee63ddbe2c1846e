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
// the geometry because it interprets the state.
#pragma once

#include <cstdint>
#include <map>
#include <string>

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

}  // namespace vgc
