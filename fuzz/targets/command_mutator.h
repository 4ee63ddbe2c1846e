// command_mutator.h — structure-aware mutation of binary command streams.
//
// Spec: docs/spec_facts.md (the command set, id widths, the sentinels
// 0xFFFF / 0xFFFFFFFF, FLT_MAX / DBL_MAX deletes); reference/node/command_binary.h
// (the stream format).
//
// Rationale: byte-level mutation of a stream mostly breaks its framing (a
// length byte, a tag), so most mutants decode to a short prefix. These
// functions decode the stream into commands, change it at the command level
// (insert, delete, duplicate, swap, change one field through the
// visit_fields schema, point an id field at an id the stream creates,
// insert vertices with a polygon on them, or a weight layer with a bone on
// it) and re-encode it, so every mutant
// is a well-formed stream. Values are biased towards what finds bugs in this node: small ids
// (they hit live elements), the all-ones sentinels, FLT_MAX / DBL_MAX (the
// delete forms), NaN, infinities, -0.0, and a small pool of layer names that
// creases and bones can refer to. Deterministic: same input and seed, same
// output. Never throws.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "command.h"

namespace vgc::fuzz {

// Mutates the stream data[0, size) in place into at most max_size bytes and
// returns the new size. Returns 0, leaving data as it was, when the stream
// does not decode completely (the caller falls back to byte mutation).
std::size_t mutate_stream(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned seed);

// Splices two streams at command boundaries (a prefix of one, a suffix of
// the other) into out[0, max_out); returns the size, 0 when either does not
// decode.
std::size_t cross_over_streams(const std::uint8_t* a, std::size_t a_size, const std::uint8_t* b,
                               std::size_t b_size, std::uint8_t* out, std::size_t max_out, unsigned seed);

// The command-level mutation itself, for tests: applies 1..3 random edits.
void mutate_commands(std::vector<Command>* commands, unsigned seed);

}  // namespace vgc::fuzz
