// snapshot.h — canonical text of a node's whole state, made for diffing.
//
// Spec: 000 section 2.6 (what a node holds); docs/commands.md "Snapshot"
// defines the format for other implementations.
//
// Two documents, each deterministic (ids ascending, numbers in the exact
// forms of number_text.h) and ending in a line "end":
//   snapshot: what is stored — layers, creases as set, live vertices and
//             polygons, every slot of every other layer, bones as sent.
//   derived:  what the stored data means — the effective crease of every
//             live vertex and polygon edge, and every bone's world pose.
// Two conforming nodes fed the same commands print the same snapshot byte
// for byte; their derived documents agree exactly on creases and within
// rounding on bone poses.
#pragma once

#include <string>

#include "node.h"

namespace vgc {

std::string print_snapshot(const Node& node);
std::string print_derived(const Node& node);

}  // namespace vgc
