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

#include <string>

#include "node.h"

namespace vgc {

std::string print_derived(const Node& node);

}  // namespace vgc
