// stream_mutator_hooks.h — the libFuzzer mutation hooks of the binary-stream
// targets (fuzz_stream, fuzz_differential). Include in exactly one .cpp of
// a target.
//
// Spec: as command_mutator.h.
//
// Seven mutations in eight are command-level (command_mutator.h); the eighth,
// and any input that does not decode completely, goes to libFuzzer's own
// byte mutator, so framing and codec edge cases keep being explored too.
// Under replay_main.cpp these are never called.
#pragma once

#include <cstddef>
#include <cstdint>

#include "command_mutator.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  if (seed % 8 != 0) {
    const std::size_t n = vgc::fuzz::mutate_stream(data, size, max_size, seed);
    if (n != 0) return n;
  }
  return LLVMFuzzerMutate(data, size, max_size);
}

extern "C" std::size_t LLVMFuzzerCustomCrossOver(const std::uint8_t* a, std::size_t a_size, const std::uint8_t* b,
                                                 std::size_t b_size, std::uint8_t* out, std::size_t max_out,
                                                 unsigned int seed) {
  return vgc::fuzz::cross_over_streams(a, a_size, b, b_size, out, max_out, seed);
}
