// command_gen.h — RapidCheck generators of commands, aware of the model's state.
//
// Spec: the command set of docs/spec_facts.md; each focus aims at the
// clauses of one group of the catalog (clause.h).
//
// Rationale: uniformly random commands are almost all rejected (no such
// layer, no such vertex) and never reach the interesting rules. These
// generators look at the reference model's current state and mostly pick
// live ids, existing layer names and valid types, with a steady share of
// near-misses (an id just past the live ones, a name one byte too long, a
// wrong-typed layer, a corner repeated, a NaN with a payload) where the
// rules are decided. Everything they make is still a valid test: any
// command may be sent to any node.
//
// Some rules show only in a state several commands build together; there
// the weights follow the state. Creases: polygons, a crease layer, a
// setting naming it and unequal values in it are all needed before an
// off-by-one corner (CREASE-EDGE-LAYER-1) is visible, so the focus weighs
// toward whichever piece is missing and, once they are there, toward
// unequal corner writes into the named layer. Bones: about one rotation in
// ten is extreme (gen::gen_quaternion_extreme: norms that underflow to 0 or
// overflow, subnormals, signed zeros), where a pose's normalization
// divides by zero or loses precision.
#pragma once

#include <rapidcheck.h>

#include <string_view>

#include "command.h"
#include "node.h"

namespace vgc {

enum class Focus {
  Layers,    // layer create / re-create / destroy / subscribe, stacks growing and shrinking
  Polygons,  // vertices and polygons: corners, deletion, real32/real64 forms
  Creases,   // crease settings, crease layers, corner-to-edge values
  Bones,     // weight/reference layers, parents, poses
  Values,    // value writes of every layer type with special floats
  Ids,       // "pick an id" and very large ids
  Anything,  // a mix of all of the above
};

// One command for the model state `model`, drawn with the weights of `focus`.
rc::Gen<Command> gen_command(const Node& model, Focus focus);

}  // namespace vgc
