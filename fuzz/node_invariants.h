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

#include "node.h"

namespace vgc::fuzz {

// Every structural invariant of a node's stored state (the maps of Node).
std::string check_state(const std::map<std::uint16_t, Layer>& layers,
                        const std::map<std::uint16_t, Bone>& bones);
inline std::string check_node(const Node& node) { return check_state(node.layers(), node.bones()); }

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
