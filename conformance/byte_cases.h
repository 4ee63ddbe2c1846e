// byte_cases.h — the bridge from libFuzzer to the conformance properties:
// a property's random choices drawn from the fuzzer's input bytes.
//
// Spec: the properties of property.h, hence the clauses of clause.h.
//
// Rationale: no public tool runs RapidCheck properties under coverage
// guidance. A RapidCheck generator is a function of a seed and a size, so
// the input is read as chunks of 9 bytes, one per command: 8 bytes of seed
// and 1 of size, and the command is what the property's own state-aware
// generator (command_gen.h) draws from them for the model state reached so
// far. Mutating a chunk changes one command and leaves the others'
// choices alone; inserting or deleting a chunk inserts or deletes a
// command. A failing input becomes an ordinary command file, which `vgc
// replay` runs like any property counterexample.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "check_step.h"
#include "command_gen.h"
#include "implementation.h"

namespace vgc {

inline constexpr std::size_t kBytesPerCommand = 9;
inline constexpr std::size_t kMaxCommandsPerCase = 256;

// The commands a byte string stands for under `focus` (trailing bytes that
// do not fill a chunk are ignored; at most kMaxCommandsPerCase commands).
// Deterministic; never throws.
//
// `memo` (optional) keeps the previous call's chunks and what each drew, so
// that a call whose input starts with the same chunks draws only from its
// first different chunk on: a chunk's command depends only on the chunks
// before it (they make the model state its generator sees) and on itself.
// libFuzzer mutates one input several times in a row and most mutations
// keep a prefix, so the property targets pass one; drawing through
// RapidCheck (a Shrinkable tree per value, under ASan's allocator) was most
// of their time. The result is the same with or without it (tested:
// ByteCases.MemoDrawsWhatAFreshDrawDraws), and every command, remembered or
// drawn, is applied to the model as before (so the reference's coverage,
// which guides the campaign, is the same too).
class DrawMemo {
 private:
  friend std::vector<Command> commands_from_bytes(const std::uint8_t*, std::size_t, Focus, DrawMemo*);
  bool valid_ = false;
  Focus focus_ = Focus::Anything;
  std::vector<std::uint8_t> chunks_;           // the previous input's chunks that were read
  std::vector<std::optional<Command>> drawn_;  // per chunk: its command, or none (skipped)
};
std::vector<Command> commands_from_bytes(const std::uint8_t* data, std::size_t size, Focus focus,
                                         DrawMemo* memo = nullptr);

// Runs those commands from a fresh node against `sut`, compared with the
// reference as a property does; the first MUST-level finding, if any.
// Cheap when they agree: check_program_fast (fast_check.h) compares the
// documents once at the end and re-runs step by step only on a difference.
std::optional<Finding> check_byte_case(const std::uint8_t* data, std::size_t size, Focus focus,
                                       Implementation& sut, std::vector<Command>* program,
                                       DrawMemo* memo = nullptr);

// The focus of a property id ("layers.stateful"); false if unknown.
bool focus_of_property(std::string_view property_id, Focus* out);

}  // namespace vgc
