// byte_cases.cpp — see byte_cases.h.
#include "byte_cases.h"

#include <rapidcheck.h>

#include "fast_check.h"
#include "property.h"
#include "runner.h"

namespace vgc {

std::vector<Command> commands_from_bytes(const std::uint8_t* data, std::size_t size, Focus focus) {
  std::vector<Command> out;
  Node model;
  for (std::size_t at = 0; at + kBytesPerCommand <= size && out.size() < kMaxCommandsPerCase;
       at += kBytesPerCommand) {
    std::uint64_t seed = 0;
    for (int i = 0; i < 8; ++i) seed |= std::uint64_t{data[at + static_cast<std::size_t>(i)]} << (8 * i);
    const int gen_size = data[at + 8] % 101;  // RapidCheck sizes run 0..100
    try {
      Command c = gen_command(model, focus)(rc::Random(seed), gen_size).value();
      model.apply(c);
      out.push_back(std::move(c));
    } catch (...) {
      // A generator that cannot produce a value for this state: skip the chunk.
    }
  }
  return out;
}

std::optional<Finding> check_byte_case(const std::uint8_t* data, std::size_t size, Focus focus,
                                       Implementation& sut, std::vector<Command>* program) {
  const std::vector<Command> commands = commands_from_bytes(data, size, focus);
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
