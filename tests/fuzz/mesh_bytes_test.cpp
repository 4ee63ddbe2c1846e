// mesh_bytes_test.cpp — fuzz/targets/mesh_bytes.h: the committed cube seed is the
// spec's cube as the reference node extracts it; the decoding is total and
// follows the documented table; encode and decode are inverse.
#include "mesh_bytes.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "command_text.h"
#include "node.h"

namespace vgc::fuzz {
namespace {

std::vector<std::uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

MeshArrays spec_cube() {
  std::ifstream in(VGC_SOURCE_DIR "/corpora/examples/cube.vgc");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<Command> cs;
  TextError e;
  EXPECT_TRUE(parse_commands(text, &cs, &e)) << e.to_string();
  Node node;
  for (const Command& c : cs) EXPECT_EQ(node.apply(c), Reason::Ok);
  return extract_mesh(node);
}

void expect_same_mesh(const MeshArrays& a, const MeshArrays& b) {
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.vertex_creases, b.vertex_creases);
  EXPECT_EQ(a.face_sizes, b.face_sizes);
  EXPECT_EQ(a.face_offsets, b.face_offsets);
  EXPECT_EQ(a.face_vertices, b.face_vertices);
  EXPECT_EQ(a.corner_edge_creases, b.corner_edge_creases);
}

TEST(MeshBytes, CubeSeedIsTheSpecCube) {
  const MeshArrays cube = spec_cube();
  ASSERT_EQ(cube.vertex_count(), 8);
  for (const char* target : {"fuzz_mesh_manifold", "fuzz_mesh_subdivision"}) {
    const auto bytes = read_bytes(std::string(VGC_SOURCE_DIR "/corpora/fuzz/") + target + "/seed-cube.bin");
    ASSERT_FALSE(bytes.empty()) << target;
    expect_same_mesh(decode_mesh_bytes(bytes.data(), bytes.size()), cube);
  }
}

TEST(MeshBytes, EncodeDecodeRoundTrip) {
  const MeshArrays cube = spec_cube();
  std::vector<std::uint8_t> bytes;
  ASSERT_TRUE(encode_mesh_bytes(cube, &bytes));
  expect_same_mesh(decode_mesh_bytes(bytes.data(), bytes.size()), cube);
  MeshArrays off = cube;
  off.positions[0][0] = 0.25;  // not on the lattice
  EXPECT_FALSE(encode_mesh_bytes(off, &bytes));
}

TEST(MeshBytes, DecodingFollowsTheTable) {
  // 3 vertices; vertex 0 = (x -1, y 1, z 0) crease index 1; then a triangle
  // 0, V, -1 with corner 1's edge creased (index 3); then a 2-gon
  // (0xF2) 4 % 3 = 1, 0xFF = -2, crease 0; then a cut-off quad.
  const std::vector<std::uint8_t> in = {3,    0x00 | 1 << 2 | 2 << 4 | 1 << 6, 0x15, 0x3F, 0x00, 0,    0xFC, 0xFE,
                                        0xC2, 0xF2,                            4,    0xFF, 0x00, 0x01, 0,    1};
  const MeshArrays m = decode_mesh_bytes(in.data(), in.size());
  ASSERT_EQ(m.vertex_count(), 3);
  EXPECT_EQ(m.positions[0], (std::array<double, 3>{-1.0, 1.0, 0.0}));
  EXPECT_EQ(m.vertex_creases[0], kMeshCreases[1]);
  EXPECT_EQ(m.positions[1], (std::array<double, 3>{1.0, 1.0, 1.0}));
  EXPECT_EQ(m.vertex_creases[2], 0u);
  EXPECT_EQ(m.positions[2], (std::array<double, 3>{0.5, 0.5, 0.5}));
  ASSERT_EQ(m.face_count(), 2);
  EXPECT_EQ(m.face_sizes, (std::vector<int>{3, 2}));
  EXPECT_EQ(m.face_vertices, (std::vector<int>{0, 3, -1, 1, -2}));
  EXPECT_EQ(m.corner_edge_creases, (std::vector<std::uint32_t>{0, 0xFFFFFFFFu, 0, 0, 0}));
}

TEST(MeshBytes, EveryPrefixDecodes) {
  const auto bytes = read_bytes(VGC_SOURCE_DIR "/corpora/fuzz/fuzz_mesh_manifold/seed-cube.bin");
  for (std::size_t n = 0; n <= bytes.size(); ++n) {
    const MeshArrays m = decode_mesh_bytes(n ? bytes.data() : nullptr, n);
    EXPECT_EQ(m.face_offsets.size(), m.face_sizes.size());
    EXPECT_EQ(m.corner_edge_creases.size(), m.face_vertices.size());
    EXPECT_LE(m.face_count(), 6);
  }
}

}  // namespace
}  // namespace vgc::fuzz
