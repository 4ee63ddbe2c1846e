// crease.h — effective creases after interpretation.
//
// Spec: 000 section 2.6.2; README "Crease values" and the corner-to-edge rule.
//
// A crease setting is a constant or a named layer. The layer "must be of type
// VN_G_LAYER_VERTEX_UINT32 for vertex creases, and
// VN_G_LAYER_POLYGON_CORNER_UINT32 for edges". Edge creases: "each corner
// holds the crease data for the edge that starts in that corner", the edge
// from corner i to corner i+1, wrapping to 0 (a triangle's corner 2 wraps).
//
// Decision: a setting that names no layer, or a layer of another type, falls
// back to its constant def_crease, so every vertex and edge always has a
// crease. Names are resolved when read, so a crease layer may be created,
// destroyed or re-typed after the crease names it. Which of these readings
// applies is a named rule (derived_rule.h): the constant, the layer, the
// layer missing, or the fresh node's setting (a setting no crease command
// has written: its Written rule is node.initial_creases).
#pragma once

#include <cstdint>
#include <map>
#include <utility>

#include "derived_rule.h"
#include "node.h"

namespace vgc {

inline constexpr std::uint32_t kCreaseSmooth = 0;
inline constexpr std::uint32_t kCreaseMax = 0xFFFFFFFFu;

// Crease of a live vertex. Precondition: `vertex_id` is live.
std::uint32_t vertex_crease(const Node& node, std::uint32_t vertex_id);
// Crease of the edge starting at `corner` of a live polygon. Precondition:
// the polygon is live and corner < its corner count (3 or 4).
std::uint32_t edge_crease(const Node& node, std::uint32_t polygon_id, int corner);

// The rule that decides every vertex's (edge's) effective crease in `node`
// now: the same resolution as vertex_crease (edge_crease), so the rule is
// the branch the value came from.
DerivedRule vertex_crease_rule(const Node& node);
DerivedRule edge_crease_rule(const Node& node);

// Number of used corners of a polygon slot: 3 or 4.
int corner_count(const Slot& polygon);

}  // namespace vgc
