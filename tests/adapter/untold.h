// untold.h — a test decorator that forwards everything to the
// implementation it wraps except what comes next
// (Implementation::expect_commands), so that each command goes on its own
// round trip: the unbatched side of the Verse route's batching tests
// (issue 31; verse_route_test.cpp, verse_r6_session_test.cpp).
#pragma once

#include <vector>

#include "forwarding_implementation.h"

namespace vgc::test {

class Untold final : public ForwardingImplementation {
 public:
  explicit Untold(Implementation& sut) : ForwardingImplementation(&sut) {}
  void expect_commands(std::vector<Command> next) override { (void)next; }
  bool last_apply_batched() const override { return false; }
};

}  // namespace vgc::test
