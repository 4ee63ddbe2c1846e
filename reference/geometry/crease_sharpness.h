// crease_sharpness.h — from the node's 32-bit crease values to subdivision
// sharpness, and the small sharpness rules of uniform creasing.
//
// Spec: 000 section 2.6 ("Catmull/Clark subdivision surfaces ... creases with
// which one can control the degree of subdivision allowed for each vertex
// and edge") and 2.6.2 ("zero represents a smooth surface (no crease), while
// MAX_UINT32 should give the maximum amount of crease"); README "Crease
// values"; 2.6.4 (the cube: 0xffffffff "means maximum sharpness everywhere").
//
// Rationale: the spec names the two ends and nothing in between. The suite
// needs ONE mapping so that the reference and OpenSubdiv subdivide the same
// surface. Sharpness is expressed the way OpenSubdiv's Sdc::Crease does
// (a float, 0 smooth, >= 10 infinitely sharp, semi-sharp sharpness s lasts
// s subdivision levels), so that every rule below is one of Sdc::Crease's
// small functions and can be checked against it.
//
// Decision (the mapping): sharpness(c) = 10 * c / 0xFFFFFFFF, computed in
// double and rounded DOWN to float; sharpness(0xFFFFFFFF) = 10 exactly
// (infinitely sharp). Why: linear is the plainest reading of "zero ...
// smooth, MAX_UINT32 ... maximum"; 10 is Sdc::Crease::SHARPNESS_INFINITE, so
// the top value is the one and only infinitely sharp value (rounding down
// keeps every c < 0xFFFFFFFF strictly below 10: a to-nearest float rounding
// would make the top ~2^8 values infinite too). The mapping is monotone
// non-decreasing (double division and rounding down both are), and every
// c > 0 gives sharpness > 0 (the smallest, 10/0xFFFFFFFF, is a normal float).
// Float because Sdc stores sharpness as float: the reference then runs the
// same sharpness arithmetic as the oracle, bit for bit.
//
// Decision (shared edges): two polygons may store different creases for
// the edge they share (each corner holds the crease of the edge starting
// there). The edge's crease is the MAXIMUM of the values stored for it.
// Why: it is symmetric and independent of polygon order and of which side
// was written last; it is idempotent (one value is itself); and a crease
// one polygon asks for is never erased by its neighbour's default, which
// matches the spec's intent that creases "avoid getting all smoothed out".
//
// Decision (boundary edges): an edge used by exactly one polygon is
// infinitely sharp whatever its stored crease (OpenSubdiv always sharpens
// boundary edges; Sdc::Crease::SharpenBoundaryEdge), as is an edge used by
// more than two polygons (OpenSubdiv's non-manifold rule). A boundary VERTEX
// keeps its own crease (Sdc VTX_BOUNDARY_EDGE_ONLY): a corner of a single
// polygon therefore follows the crease rule unless its crease makes it a
// corner.
#pragma once

#include <cstdint>
#include <vector>

namespace vgc {

inline constexpr float kSharpnessSmooth = 0.0f;     // Sdc::Crease::SHARPNESS_SMOOTH
inline constexpr float kSharpnessInfinite = 10.0f;  // Sdc::Crease::SHARPNESS_INFINITE

// The sharpness of a vertex or edge crease value (the mapping above).
// Total: every input has a result in [0, 10].
float crease_to_sharpness(std::uint32_t crease);

// The crease of an edge from the values its polygons store for it (the
// maximum). Precondition: `stored` is not empty (else returns 0).
std::uint32_t combine_edge_creases(const std::vector<std::uint32_t>& stored);

// The sharpness an edge used by `face_count` polygons subdivides with:
// infinite unless face_count == 2, else crease_to_sharpness(crease).
float edge_sharpness_for(std::uint32_t crease, int face_count);

// Sdc::Crease's predicates.
inline bool is_smooth(float s) { return s <= kSharpnessSmooth; }
inline bool is_sharp(float s) { return s > kSharpnessSmooth; }
inline bool is_infinite(float s) { return s >= kSharpnessInfinite; }
inline bool is_semi_sharp(float s) { return kSharpnessSmooth < s && s < kSharpnessInfinite; }

// Uniform creasing (Sdc CREASE_UNIFORM): the sharpness of a child vertex or
// child edge. Smooth stays smooth, infinite stays infinite, s > 1 gives
// s - 1 (in float, as Sdc), otherwise smooth.
float subdivide_sharpness(float s);

// The vertex rules of Sdc::Crease::Rule.
enum class CreaseRule { Smooth, Dart, Crease, Corner };

// Sdc::Crease::DetermineVertexVertexRule: a sharp vertex is a corner;
// otherwise by the number of sharp incident edges: 0 smooth, 1 dart,
// 2 crease, more corner.
CreaseRule determine_vertex_rule(float vertex_sharpness, const std::vector<float>& edge_sharpness);

// Sdc::Crease::ComputeFractionalWeightAtVertex for uniform creasing: the
// weight of the parent rule when a vertex's rule changes between parent
// and child. The average of the sharpness of every feature that becomes
// smooth (the vertex if sharp in the parent and smooth in the child; each
// incident edge with 0 < s <= 1), clamped to 1; 0 if none. Float arithmetic
// in the same order as Sdc.
float fractional_weight_at_vertex(float vertex_sharpness, float child_vertex_sharpness,
                                  const std::vector<float>& edge_sharpness);

}  // namespace vgc
