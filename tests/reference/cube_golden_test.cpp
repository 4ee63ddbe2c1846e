// The spec's cube (000 section 2.6.4, Example 2-1) applied to the reference
// node gives the snapshot in tests/golden/cube.snapshot. That file was
// written by hand from the spec's two tables, not copied from program output.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "command_text.h"
#include "crease.h"
#include "node.h"
#include "snapshot.h"

namespace vgc {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(CubeGolden, SnapshotMatchesSpecTables) {
  const std::string text = read_file(VGC_SOURCE_DIR "/corpora/examples/cube.vgc");
  ASSERT_FALSE(text.empty());
  std::vector<Command> commands;
  TextError error;
  ASSERT_TRUE(parse_commands(text, &commands, &error)) << error.to_string();
  ASSERT_EQ(commands.size(), 16u);
  Node node;
  for (const auto& c : commands) ASSERT_EQ(node.apply(c), Reason::Ok) << print_command(c);
  EXPECT_EQ(print_snapshot(node), read_file(VGC_SOURCE_DIR "/tests/golden/cube.snapshot"));
  EXPECT_EQ(node.vertices().size(), 8u);
  EXPECT_EQ(node.polygons().size(), 6u);
}

TEST(CubeGolden, EveryVertexAndEdgeIsMaximallySharp) {
  std::vector<Command> commands;
  TextError error;
  ASSERT_TRUE(parse_commands(read_file(VGC_SOURCE_DIR "/corpora/examples/cube.vgc"), &commands, &error));
  Node node;
  for (const auto& c : commands) node.apply(c);
  for (const auto& [v, slot] : node.vertices()) EXPECT_EQ(vertex_crease(node, v), kCreaseMax);
  int edges = 0;
  for (const auto& [p, slot] : node.polygons())
    for (int c = 0; c < corner_count(slot); ++c, ++edges) EXPECT_EQ(edge_crease(node, p, c), kCreaseMax);
  EXPECT_EQ(edges, 24);  // six quads, four edges each, seen from each side
}

}  // namespace
}  // namespace vgc
