// arbitrary_command.h — RapidCheck generators for commands.
//
// Spec: docs/spec_facts.md "Command set of the geometry node" (field
// widths, the wire aliases FLT_MAX / DBL_MAX / v0 = 0xFFFFFFFF / empty names,
// the "pick an id" values 0xFFFF and 0xFFFFFFFF, the 15-byte name limit) and
// 000 section 2.6.1 Table 2-1 (the eight layer type values).
//
// Rationale: every property over commands (codec round trips, node
// atomicity, conformance against another implementation) needs the same
// hostile inputs: NaNs with arbitrary payloads, -0.0, infinities, subnormals,
// the FLT_MAX / DBL_MAX delete sentinels, the all-ones ids, names of 0..40
// arbitrary bytes (NUL, quote, backslash, newline, high bytes), type bytes
// that are no layer type. Fields are filled through visit_fields
// (command_fields.h), so a field added to a command is generated without
// touching this file. Each field is drawn with its own `*gen` inside
// gen::exec, so a counterexample shrinks field by field: integers toward 0,
// names toward "", special floats toward 0.
//
// Two families:
//   gen_command()            any command value at all (rc::Arbitrary<Command>)
//   gen_command_for(node)    mostly-valid commands for the node's current state:
//                            small ids, existing layers/elements/bones, names
//                            from a small pool; occasionally hostile values.
// Both are deterministic given RapidCheck's seed (RC_PARAMS="seed=N").
//
// Defined once in arbitrary_command.cpp (library vgc_gen), not inline here:
// instantiating the generator of every command kind cost each of the eleven
// test files that include this header 20 to 30 s of compile time.
#pragma once

#include <rapidcheck.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "command.h"
#include "command_fields.h"
#include "command_text.h"
#include "magnitude.h"
#include "node.h"

namespace vgc {
namespace gen {

// ---- numbers ---------------------------------------------------------------

template <class F, class Bits> F bits_to(Bits b) {
  static_assert(sizeof(F) == sizeof(Bits), "same width");
  F f;
  std::memcpy(&f, &b, sizeof f);
  return f;
}

// Any double: ordinary values (shrinking toward 0), the special values,
// NaNs with random sign and payload, subnormals, raw bit patterns.
rc::Gen<double> gen_f64_any();

// Any float, with FLT_MAX (the real32 delete sentinel) among the specials.
rc::Gen<float> gen_f32_any();

// Quaternions (x, y, z, w) where a pose computation breaks: components
// whose squares underflow (every |c| below ~1.5e-154: the plain norm is 0)
// or overflow (a |c| above ~1.3e154, or four near 1e154 whose squares sum
// past DBL_MAX: the norm is infinite), subnormals and squares that are
// subnormal (1e-160: the norm is finite but inexact), ordinary quaternions
// scaled by 2^k for k across the whole exponent range, the zero quaternion
// with any signs of zero and a non-finite component (both rejected,
// BONE-VALUE-1). docs/commands.md 4.8: the reference scales by the largest
// |component| before the norm, so each accepted one is the rotation it is.
rc::Gen<std::array<double, 4>> gen_quaternion_extreme();

// uint32 ids and values: small ones, the all-ones "none / pick / max" value,
// its neighbour, four billion, every magnitude class (magnitude.h), anything.
rc::Gen<std::uint32_t> gen_u32_any();

// The same for uint16 and uint8 fields.
rc::Gen<std::uint16_t> gen_u16_any();

rc::Gen<std::uint8_t> gen_u8_any();

// Mostly one of Table 2-1's eight values, sometimes a byte that is none.
rc::Gen<std::uint8_t> gen_layer_type_byte();

// Mostly REAL32 (0) or REAL64 (1), sometimes an invalid format byte.
rc::Gen<std::uint8_t> gen_real_format_byte();

// One byte, biased toward the bytes that break quoting and C strings.
rc::Gen<char> gen_name_byte();

// Names and labels of 0..40 arbitrary bytes (valid ones are 0..15 bytes
// without NUL). Shrinks the length first, then each byte toward 'a'.
rc::Gen<std::string> gen_name();

// Any command of any of the 22 kinds, every field hostile-biased. Shrinks
// toward layer_create (kind 0) and toward zero/empty fields.
rc::Gen<Command> gen_command();

// Small pool of names, so that creases and bones hit existing layers.
rc::Gen<std::string> gen_small_name();

// Mostly-valid commands for `node` as it is now: layer ids 0..5, vertex ids
// 0..7, polygon ids 0..5, bone ids 0..4 (plus the "pick an id" values),
// existing ids preferred, corners drawn from live vertices, names from
// gen_small_name(); about one command in eight is fully arbitrary
// (gen_command()). The node is read only while generating.
//
// Layer ids: ids 0 and 1 are the base layers, which always exist and can
// be neither created nor destroyed (LAYER-BASE-2). Drawing a layer_create's
// id from the existing layers would name them 4 times in 5 on a fresh node,
// and almost every sequence would stay without weight, crease or data
// layers, hence without bones. So layer_create mostly draws a non-base id,
// 2..5 (a free one, or an existing one to re-create), sometimes a base id
// or "pick an id"; writes draw from the existing layers, base ones included
// (vertex_set_xyz on layer 0 is how vertices are made), or from 0..5.
rc::Gen<Command> gen_command_for(const Node& node);

// A sequence of `n` state-aware commands starting from a fresh node with
// `limits`: each command is drawn for the state the previous ones left.
rc::Gen<std::vector<Command>> gen_command_sequence(std::size_t n, NodeLimits limits = {});

}  // namespace gen

namespace cmd {
// RapidCheck prints counterexamples through showValue, found by argument-
// dependent lookup in the namespaces of Command's alternatives.
inline void showValue(const Command& c, std::ostream& os) { os << print_command(c); }
}  // namespace cmd

}  // namespace vgc

namespace rc {
template <> struct Arbitrary<vgc::Command> {
  static Gen<vgc::Command> arbitrary() { return vgc::gen::gen_command(); }
};
}  // namespace rc
