// command_mutator_test.cpp — the structure-aware mutator keeps streams
// well-formed, is deterministic, and reaches every command kind and the
// sentinel values it is meant to favour.
#include "command_mutator.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <fstream>
#include <iterator>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "command_binary.h"
#include "command_text.h"
#include "node.h"

namespace vgc::fuzz {
namespace {

std::string cube_stream() {
  std::ifstream in(VGC_SOURCE_DIR "/corpora/examples/cube.vgc");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<Command> cs;
  TextError e;
  EXPECT_TRUE(parse_commands(text, &cs, &e));
  std::string out;
  for (const Command& c : cs) EXPECT_TRUE(encode_command(c, &out));
  return out;
}

std::vector<Command> decode_all(const std::string& s) {
  std::vector<Command> cs;
  EXPECT_EQ(decode_commands(reinterpret_cast<const std::uint8_t*>(s.data()), s.size(), &cs), DecodeStatus::End);
  return cs;
}

TEST(CommandMutator, MutantsDecodeAreDeterministicAndVaried) {
  const std::string cube = cube_stream();
  std::set<std::size_t> kinds;
  bool saw_none32 = false, saw_nan = false, saw_delete_sentinel = false, saw_none16 = false;
  std::size_t changed = 0;
  constexpr unsigned kSeeds = 3000;
  std::string current = cube;
  for (unsigned seed = 0; seed < kSeeds; ++seed) {
    std::string buf = seed % 50 == 0 ? cube : current;  // walk, restarting now and then
    const std::size_t old = buf.size();
    buf.resize(4096);
    std::string again = buf;
    const std::size_t n = mutate_stream(reinterpret_cast<std::uint8_t*>(buf.data()), old, 4096, seed);
    const std::size_t m = mutate_stream(reinterpret_cast<std::uint8_t*>(again.data()), old, 4096, seed);
    ASSERT_EQ(n, m);
    buf.resize(n);
    again.resize(m);
    ASSERT_EQ(buf, again) << "seed " << seed << " is not deterministic";
    if (n == 0) continue;  // everything deleted: the caller falls back
    ASSERT_LE(n, 4096u);
    const std::vector<Command> cs = decode_all(buf);
    if (buf != (seed % 50 == 0 ? cube : current)) ++changed;
    for (const Command& c : cs) {
      kinds.insert(c.index());
      const std::string line = print_command(c);
      saw_none32 |= line.find("0xFFFFFFFF") != std::string::npos;
      saw_none16 |= line.find(" 0xFFFF ") != std::string::npos;
      saw_nan |= line.find("nan") != std::string::npos;
      if (const auto* v = std::get_if<cmd::VertexSetXyzReal64>(&c))
        saw_delete_sentinel |= v->x == DBL_MAX || v->y == DBL_MAX || v->z == DBL_MAX;
      if (const auto* v = std::get_if<cmd::VertexSetXyzReal32>(&c))
        saw_delete_sentinel |= v->x == FLT_MAX || v->y == FLT_MAX || v->z == FLT_MAX;
    }
    current = buf.size() < 2000 ? buf : cube;
  }
  EXPECT_EQ(kinds.size(), kCommandKinds) << "not every command kind was generated";
  EXPECT_GT(changed, kSeeds * 9 / 10);
  EXPECT_TRUE(saw_none32);
  EXPECT_TRUE(saw_none16);
  EXPECT_TRUE(saw_nan);
  EXPECT_TRUE(saw_delete_sentinel);
}

// From nothing, a short walk of mutations reaches the states the polygon
// and bone rules need: a polygon the node accepts (its corners live
// vertices) and a bone whose parent is a bone the stream creates. Without
// the id-linking and polygon edits this took libFuzzer minutes from an
// empty corpus (docs/fuzzing.md "Time to find").
TEST(CommandMutator, ReachesLinkedStatesFromAnEmptyStream) {
  int polygon_walks = 0, bone_walks = 0;
  constexpr int kWalks = 50;
  for (unsigned walk = 0; walk < kWalks; ++walk) {
    std::vector<Command> cs;
    bool polygon = false, linked_bone = false;
    for (unsigned step = 0; step < 40 && !(polygon && linked_bone); ++step) {
      mutate_commands(&cs, walk * 1000 + step);
      if (cs.size() > 60) cs.resize(60);
      Node node;
      for (const Command& c : cs) node.apply(c);
      polygon |= !node.polygons().empty();
      for (const auto& [id, b] : node.bones())
        linked_bone |= b.parent != id && node.bones().count(b.parent) > 0;
    }
    polygon_walks += polygon;
    bone_walks += linked_bone;
  }
  EXPECT_GE(polygon_walks, kWalks * 3 / 4) << "walks of 40 edits that built an accepted polygon";
  EXPECT_GE(bone_walks, kWalks / 10) << "walks of 40 edits that built a bone under another";
}

TEST(CommandMutator, UndecodableInputIsLeftForByteMutation) {
  std::string bad = cube_stream();
  bad.push_back(static_cast<char>(200));  // no command has tag 200
  const std::string before = bad;
  EXPECT_EQ(mutate_stream(reinterpret_cast<std::uint8_t*>(bad.data()), bad.size(), bad.size(), 1), 0u);
  EXPECT_EQ(bad, before);
}

TEST(CommandMutator, CrossOverSplicesAtCommandBoundaries) {
  const std::string a = cube_stream();
  std::string b;
  ASSERT_TRUE(encode_command(cmd::BoneDestroy{3}, &b));
  ASSERT_TRUE(encode_command(cmd::LayerDestroy{4}, &b));
  for (unsigned seed = 0; seed < 200; ++seed) {
    std::string out(8192, '\0');
    const std::size_t n = cross_over_streams(reinterpret_cast<const std::uint8_t*>(a.data()), a.size(),
                                             reinterpret_cast<const std::uint8_t*>(b.data()), b.size(),
                                             reinterpret_cast<std::uint8_t*>(out.data()), out.size(), seed);
    out.resize(n);
    decode_all(out);
  }
}

// The splice as it was first written: decode both streams, join a's first
// cut_a commands with b's from cut_b on, re-encode as many as fit.
std::string splice_by_reencoding(const std::string& a, const std::string& b, std::size_t max_out, unsigned seed) {
  std::vector<Command> ca, cb;
  if (decode_commands(reinterpret_cast<const std::uint8_t*>(a.data()), a.size(), &ca) != DecodeStatus::End ||
      decode_commands(reinterpret_cast<const std::uint8_t*>(b.data()), b.size(), &cb) != DecodeStatus::End)
    return {};
  std::mt19937 rng(seed);
  const std::size_t cut_a = rng() % (ca.size() + 1);
  const std::size_t cut_b = rng() % (cb.size() + 1);
  std::vector<Command> joined(ca.begin(), ca.begin() + static_cast<std::ptrdiff_t>(cut_a));
  joined.insert(joined.end(), cb.begin() + static_cast<std::ptrdiff_t>(cut_b), cb.end());
  std::string out;
  for (const Command& c : joined) {
    const std::size_t before = out.size();
    if (!encode_command(c, &out)) continue;
    if (out.size() > max_out) {
      out.resize(before);
      break;
    }
  }
  return out;
}

// The cross-over copies command bytes instead of re-encoding them: the
// same output, byte for byte, as decoding, joining and re-encoding, for
// streams of every kind of command (the mutator's own) and every room
// left in the output, down to a command's length exactly. Seen fail with
// a command that fills the output to the last byte left out.
TEST(CommandMutator, CrossOverGivesTheBytesReencodingGives) {
  std::vector<std::string> streams;
  std::vector<Command> cs;
  decode_commands(reinterpret_cast<const std::uint8_t*>(cube_stream().data()), cube_stream().size(), &cs);
  for (unsigned seed = 0; seed < 40; ++seed) {
    mutate_commands(&cs, seed);
    std::string s;
    for (const Command& c : cs) encode_command(c, &s);
    streams.push_back(s);
  }
  streams.push_back(std::string());
  streams.push_back(cube_stream() + std::string(1, static_cast<char>(200)));  // does not decode
  int spliced = 0;
  for (unsigned seed = 0; seed < 400; ++seed) {
    const std::string& a = streams[seed % streams.size()];
    const std::string& b = streams[(seed * 7 + 3) % streams.size()];
    const std::string whole = splice_by_reencoding(a, b, 1 << 20, seed);
    for (std::size_t max_out : {std::size_t{1} << 20, whole.size(), whole.size() / 2, std::size_t{9}}) {
      const std::string expected = splice_by_reencoding(a, b, max_out, seed);
      std::string out(max_out, '\0');
      const std::size_t n = cross_over_streams(reinterpret_cast<const std::uint8_t*>(a.data()), a.size(),
                                               reinterpret_cast<const std::uint8_t*>(b.data()), b.size(),
                                               reinterpret_cast<std::uint8_t*>(out.data()), max_out, seed);
      out.resize(n);
      ASSERT_EQ(out, expected) << "seed " << seed << ", max_out " << max_out;
      spliced += !expected.empty();
    }
  }
  EXPECT_GT(spliced, 1000);
}

}  // namespace
}  // namespace vgc::fuzz
