// byte_cases.cpp — see byte_cases.h.
#include "byte_cases.h"

#include <rapidcheck.h>

#include <cstring>

#include "fast_check.h"
#include "property.h"
#include "check_step.h"

namespace vgc {

namespace {

// What chunk `at` (its first byte) of `data` draws for the state `model` is in.
std::optional<Command> draw(const std::uint8_t* data, std::size_t at, const Node& model, Focus focus) {
  std::uint64_t seed = 0;
  for (int i = 0; i < 8; ++i) seed |= std::uint64_t{data[at + static_cast<std::size_t>(i)]} << (8 * i);
  const int gen_size = data[at + 8] % 101;  // RapidCheck sizes run 0..100
  try {
    return gen_command(model, focus)(rc::Random(seed), gen_size).value();
  } catch (...) {
    return std::nullopt;  // a generator that cannot produce a value for this state: skip the chunk
  }
}

}  // namespace

std::vector<Command> commands_from_bytes(const std::uint8_t* data, std::size_t size, Focus focus, DrawMemo* memo) {
  // How many leading chunks are the memo's: their commands are remembered.
  std::size_t same = 0;
  if (memo && memo->valid_ && memo->focus_ == focus)
    while (same < memo->drawn_.size() && (same + 1) * kBytesPerCommand <= size &&
           std::memcmp(data + same * kBytesPerCommand, memo->chunks_.data() + same * kBytesPerCommand,
                       kBytesPerCommand) == 0)
      ++same;
  std::vector<Command> out;
  Node model;
  std::size_t chunk = 0;
  for (std::size_t at = 0; at + kBytesPerCommand <= size && out.size() < kMaxCommandsPerCase;
       at += kBytesPerCommand, ++chunk) {
    if (chunk < same) {
      if (const std::optional<Command>& c = memo->drawn_[chunk]) {
        model.apply(*c);
        out.push_back(*c);
      }
      continue;
    }
    std::optional<Command> c = draw(data, at, model, focus);
    if (memo) {
      if (memo->drawn_.size() <= chunk) memo->drawn_.resize(chunk + 1);
      memo->drawn_[chunk] = c;
    }
    if (!c) continue;
    model.apply(*c);
    out.push_back(std::move(*c));
  }
  if (memo) {
    memo->valid_ = true;
    memo->focus_ = focus;
    memo->chunks_.assign(data, data + chunk * kBytesPerCommand);
    memo->drawn_.resize(chunk);
  }
  return out;
}

std::optional<Finding> check_byte_case(const std::uint8_t* data, std::size_t size, Focus focus,
                                       Implementation& sut, std::vector<Command>* program, DrawMemo* memo) {
  const std::vector<Command> commands = commands_from_bytes(data, size, focus, memo);
  // Cheap on agreement, exact (check_step per command) on a difference.
  const ReplayResult r = check_program_fast(commands, sut).replay;
  if (program) {
    program->assign(commands.begin(), r.failed_at < 0 ? commands.begin() : commands.begin() + r.failed_at + 1);
    if (!r.failure) *program = commands;
  }
  return r.failure;
}

bool focus_of_property(std::string_view property_id, Focus* out) {
  if (const PropertySpec* p = find_property(property_id)) {
    *out = p->focus;
    return true;
  }
  return false;
}

}  // namespace vgc
