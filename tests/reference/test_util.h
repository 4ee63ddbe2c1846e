// test_util.h — small helpers shared by the reference tests: build commands
// from their text form and apply them.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "command_text.h"
#include "node.h"
#include "reason.h"
#include "snapshot.h"

namespace vgc::test {

// One command from its text form; a parse failure fails the calling test.
inline Command C(std::string_view line) {
  Command c;
  bool blank = false;
  TextError e;
  if (!parse_command_line(line, 1, &c, &blank, &e)) ADD_FAILURE() << "bad test command: " << e.to_string();
  return c;
}

// Applies one command given as text.
inline Reason A(Node& node, std::string_view line) { return node.apply(C(line)); }

// Applies a script (one command per line) and expects every command to apply.
inline void apply_all(Node& node, std::string_view text) {
  std::vector<Command> cs;
  TextError e;
  ASSERT_TRUE(parse_commands(text, &cs, &e)) << e.to_string();
  for (const auto& c : cs) ASSERT_EQ(reason_name(node.apply(c)), "OK") << print_command(c);
}

// The spec's cube (000 2.6.4), without creases.
inline constexpr std::string_view kCubeScript = R"(
vertex_set_xyz_real64 0 0 -1 1 -1
vertex_set_xyz_real64 0 1 1 1 -1
vertex_set_xyz_real64 0 2 1 1 1
vertex_set_xyz_real64 0 3 -1 1 1
vertex_set_xyz_real64 0 4 -1 -1 1
vertex_set_xyz_real64 0 5 1 -1 1
vertex_set_xyz_real64 0 6 1 -1 -1
vertex_set_xyz_real64 0 7 -1 -1 -1
polygon_set_corner_uint32 1 0 0 1 2 3
polygon_set_corner_uint32 1 1 4 5 6 7
polygon_set_corner_uint32 1 2 3 2 5 4
polygon_set_corner_uint32 1 3 2 1 6 5
polygon_set_corner_uint32 1 4 1 0 7 6
polygon_set_corner_uint32 1 5 0 3 4 7
)";

}  // namespace vgc::test
