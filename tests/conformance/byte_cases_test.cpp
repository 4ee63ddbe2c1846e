// byte_cases_test.cpp — conformance/byte_cases: the fuzz targets' bridge
// from input bytes to a property's commands.
//
// Spec: as byte_cases.h.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "byte_cases.h"
#include "command_text.h"

namespace vgc {
namespace {

bool same_commands(const std::vector<Command>& a, const std::vector<Command>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!bit_equal(a[i], b[i])) return false;
  return true;
}

// A DrawMemo changes how often a chunk is drawn, never what: a chain of
// inputs each mutated from the one before (as libFuzzer mutates one input
// several times in a row: a byte changed, bytes inserted or erased, cut,
// grown, and the focus switched) draws with one memo exactly what a fresh
// draw without one gives. Seen fail (at step 2) with the memo leaving
// every other remembered command out of the model it draws the rest for.
TEST(ByteCases, MemoDrawsWhatAFreshDrawDraws) {
  const Focus foci[] = {Focus::Anything, Focus::Layers, Focus::Polygons, Focus::Ids};
  std::mt19937 rng(7);
  std::vector<std::uint8_t> input(9 * 40);
  for (auto& b : input) b = static_cast<std::uint8_t>(rng());
  DrawMemo memo;
  Focus focus = Focus::Anything;
  int nonempty = 0;
  for (int step = 0; step < 120; ++step) {
    switch (rng() % 6) {
      case 0: if (!input.empty()) input[rng() % input.size()] ^= static_cast<std::uint8_t>(1 + rng() % 255); break;
      case 1: input.insert(input.begin() + static_cast<std::ptrdiff_t>(rng() % (input.size() + 1)),
                           static_cast<std::size_t>(1 + rng() % 12), static_cast<std::uint8_t>(rng()));
              break;
      case 2: if (!input.empty()) input.erase(input.begin() + static_cast<std::ptrdiff_t>(rng() % input.size())); break;
      case 3: input.resize(input.size() / 2 + rng() % (input.size() / 2 + 1)); break;
      case 4: for (int i = 0; i < 30; ++i) input.push_back(static_cast<std::uint8_t>(rng())); break;
      case 5: focus = foci[rng() % 4]; break;
    }
    // The size byte of a chunk past the middle alone: the memo must see it.
    if (step % 3 == 2 && input.size() >= 9 * 4)
      input[9 * (input.size() / 18) + 8] = static_cast<std::uint8_t>(input[9 * (input.size() / 18) + 8] + 50);
    const std::vector<Command> fresh = commands_from_bytes(input.data(), input.size(), focus);
    const std::vector<Command> memoized = commands_from_bytes(input.data(), input.size(), focus, &memo);
    ASSERT_TRUE(same_commands(fresh, memoized)) << "step " << step << ": fresh\n"
                                                << print_commands(fresh) << "memoized\n"
                                                << print_commands(memoized);
    if (!fresh.empty()) ++nonempty;
  }
  EXPECT_GT(nonempty, 100);  // the chain kept drawing commands
}

// A chunk that differs from the memo's in its size byte alone is drawn
// again (most generators draw at the nominal size whatever the byte says,
// so this looks for a chunk whose size does change its command). Seen fail
// with the memo comparing a chunk's first 8 bytes only.
TEST(ByteCases, MemoSeesAChangedSizeByte) {
  std::mt19937 rng(11);
  for (int attempt = 0; attempt < 50; ++attempt) {
    std::vector<std::uint8_t> a(9 * 20);
    for (auto& b : a) b = static_cast<std::uint8_t>(rng());
    for (std::size_t k = 0; k < 20; ++k) {
      std::vector<std::uint8_t> b = a;
      b[9 * k + 8] = static_cast<std::uint8_t>(b[9 * k + 8] + 50);
      const std::vector<Command> fresh_b = commands_from_bytes(b.data(), b.size(), Focus::Anything);
      if (same_commands(commands_from_bytes(a.data(), a.size(), Focus::Anything), fresh_b)) continue;
      DrawMemo memo;
      commands_from_bytes(a.data(), a.size(), Focus::Anything, &memo);
      EXPECT_TRUE(same_commands(fresh_b, commands_from_bytes(b.data(), b.size(), Focus::Anything, &memo)));
      return;
    }
  }
  FAIL() << "no chunk whose size byte changes what it draws";
}

}  // namespace
}  // namespace vgc
