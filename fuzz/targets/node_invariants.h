// node_invariants.h — what must hold of a geometry node after every command.
//
// Spec: 000 section 2.6.1 (base layers 0 "vertex" VERTEX_XYZ and 1 "polygon"
// POLYGON_CORNER_UINT32 "always present"; every layer of a stack sized by its
// base layer; polygons of three or four corners referencing valid vertices),
// 2.6.3 (the parent link "defines hierarchies of bones"), README (names at
// most 15 visible bytes, corners pairwise distinct, Table 2-1 type values),
// and the reference's decisions in node.cpp (names unique in the node; a
// rejected command changes nothing; finite base positions).
//
// Rationale: fuzz_stream runs random command streams into the reference and
// calls these after each command. They read the node's state only through
// its public maps, so a unit test can hand them a broken state directly and
// see every rule fail once (tests/fuzz/node_invariants_test.cpp).
// Each function returns an empty string when the rule holds, otherwise one
// line saying which rule failed and where. Never throws.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "command.h"
#include "node.h"

namespace vgc::fuzz {

// Every structural invariant of a node's stored state (the maps of Node).
std::string check_state(const std::map<std::uint16_t, Layer>& layers,
                        const std::map<std::uint16_t, Bone>& bones);
inline std::string check_node(const Node& node) { return check_state(node.layers(), node.bones()); }

// What one command may change, for the incremental checks below: the
// vertices and polygons it names, whole layers (layer commands) and bones.
// `whole_state` when it asks the node to pick an id (0xFFFF / 0xFFFFFFFF),
// so that what it touches is not known beforehand: then the incremental
// checks are the full ones.
struct Touched {
  std::vector<std::uint32_t> vertices, polygons;
  std::vector<std::uint16_t> layers, bones;
  bool vertex_delete = false;  // polygons naming the vertex go too
  bool whole_state = false;
};
Touched touched_by(const Command& c);

// The invariants of check_state that a command touching `t` can break,
// checked where it touched: base layers; every layer's id, type and name
// (names unique) and its slot count against its base layer (O(layers));
// the touched elements live in exactly the layers of their stack, finite
// positions, polygons' corners; for touched layers, the exact id sets; for
// touched bones, names and the parent chain (a new cycle passes through the
// bone that was set); after a vertex delete, no polygon names it. The
// whole of check_state holds when every step passed this and the state
// started valid, except for one class of bug it leaves to the full check at
// the end of the input: an element of the same stack changed under another
// id with the counts unchanged.
std::string check_touched(const std::map<std::uint16_t, Layer>& layers, const std::map<std::uint16_t, Bone>& bones,
                          const Touched& t);
inline std::string check_touched(const Node& node, const Touched& t) {
  return check_touched(node.layers(), node.bones(), t);
}

// A fingerprint of the part of the state `t` names, plus every layer's
// header and slot count, the crease settings and the bone count; the whole
// state_digest when t.whole_state. Around a rejected command: the state it
// names must not change. (fuzz_stream also checks the whole state once per
// input: the applied commands alone, from a fresh node, must end in the
// same state_digest.)
std::uint64_t touched_digest(const Node& node, const Touched& t);

// A 64-bit fingerprint (not cryptographic) of everything print_snapshot() prints: every layer
// (id, name, type, defaults, subscription, every slot's values bit for bit),
// both crease settings, every bone. Equal states give equal digests; a
// change of any printed value changes it except with probability ~2^-64.
// fuzz_stream compares digests around each command because printing the
// snapshot text after every command costs more than the rest of the run.
std::uint64_t state_digest(const Node& node);

// One command step: `applied` is what the node answered; `before` and
// `after` are print_snapshot() (or state_digest()) around the command. A
// rejected command must leave them unchanged.
std::string check_step(bool applied, const std::string& before, const std::string& after);
std::string check_step(bool applied, std::uint64_t before, std::uint64_t after);

// Two print_snapshot() calls on the same unchanged node must agree.
std::string check_deterministic(const std::string& first, const std::string& second);

}  // namespace vgc::fuzz
