// command_binary_test.cpp — the binary form of commands (reference/node/command_binary.cpp):
// byte layout, round trips, streams, truncation, bad tags, arbitrary bytes,
// and the 255-byte name limit of the encoding.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "arbitrary_command.h"
#include "command_binary.h"

namespace vgc {
namespace {

std::vector<std::uint8_t> bytes(const std::string& s) { return {s.begin(), s.end()}; }

std::string encoded(const Command& c) {
  std::string out;
  EXPECT_TRUE(encode_command(c, &out));
  return out;
}

TEST(CommandBinary, LayoutIsTagThenLittleEndianFieldsInWireOrder) {
  EXPECT_EQ(bytes(encoded(cmd::VertexDelete{0x01020304u})),
            (std::vector<std::uint8_t>{6, 0x04, 0x03, 0x02, 0x01}));
  // layer_create: tag 0, u16 id, name (length byte + bytes), u8 type, u32 def_uint, f64 def_real.
  EXPECT_EQ(bytes(encoded(cmd::LayerCreate{0x0102, "uv", 129, 0xA0B0C0D0u, 1.0})),
            (std::vector<std::uint8_t>{0, 0x02, 0x01, 2, 'u', 'v', 129, 0xD0, 0xC0, 0xB0, 0xA0,
                                       0, 0, 0, 0, 0, 0, 0xF0, 0x3F}));
  // real32: IEEE bits, little-endian. 1.0f = 0x3F800000; -0.0f = 0x80000000.
  EXPECT_EQ(bytes(encoded(cmd::VertexSetXyzReal32{1, 2, 1.0f, -0.0f, 0.0f})),
            (std::vector<std::uint8_t>{4, 1, 0, 2, 0, 0, 0, 0, 0, 0x80, 0x3F, 0, 0, 0, 0x80, 0, 0, 0, 0}));
  EXPECT_EQ(bytes(encoded(cmd::BoneDestroy{0xFFFF})), (std::vector<std::uint8_t>{21, 0xFF, 0xFF}));
}

TEST(CommandBinary, EveryKindRoundTripsWithDefaultFields) {
  for (std::size_t k = 0; k < kCommandKinds; ++k) {
    std::string s(1, static_cast<char>(k));
    // Encode a default-constructed command of kind k via decode of its zero bytes:
    // build it by encoding a decoded value instead, to stay independent of field lists.
    Command c;
    std::vector<std::uint8_t> zeros(200, 0);
    zeros[0] = static_cast<std::uint8_t>(k);
    std::size_t pos = 0;
    ASSERT_EQ(decode_command(zeros.data(), zeros.size(), &pos, &c), DecodeStatus::Ok) << k;
    EXPECT_EQ(c.index(), k);
    const std::string e = encoded(c);
    EXPECT_EQ(e.size(), pos) << k;
    EXPECT_EQ(e, std::string(zeros.begin(), zeros.begin() + static_cast<long>(pos))) << k;
  }
}

RC_GTEST_PROP(CommandBinaryProperty, EncodeThenDecodeIsBitEqual, (Command c)) {
  std::string e;
  RC_ASSERT(encode_command(c, &e));
  const auto b = bytes(e);
  std::size_t pos = 0;
  Command back;
  RC_ASSERT(decode_command(b.data(), b.size(), &pos, &back) == DecodeStatus::Ok);
  RC_ASSERT(pos == b.size());
  RC_ASSERT(bit_equal(c, back));
  RC_ASSERT(decode_command(b.data(), b.size(), &pos, &back) == DecodeStatus::End);
}

RC_GTEST_PROP(CommandBinaryProperty, ConcatenatedStreamRoundTrips, (std::vector<Command> cs)) {
  std::string e;
  for (const auto& c : cs) RC_ASSERT(encode_command(c, &e));
  const auto b = bytes(e);
  std::vector<Command> back;
  RC_ASSERT(decode_commands(b.data(), b.size(), &back) == DecodeStatus::End);
  RC_ASSERT(back.size() == cs.size());
  for (std::size_t i = 0; i < cs.size(); ++i) RC_ASSERT(bit_equal(cs[i], back[i]));
}

RC_GTEST_PROP(CommandBinaryProperty, EveryProperPrefixIsTruncatedAndLeavesPos, (Command c)) {
  const std::string head("\x06\x01\x00\x00\x00", 5);  // vertex_delete 1, decoded first
  std::string e;
  RC_ASSERT(encode_command(c, &e));
  for (std::size_t cut = 1; cut < e.size(); ++cut) {
    const auto b = bytes(head + e.substr(0, cut));
    std::size_t pos = 0;
    Command out;
    RC_ASSERT(decode_command(b.data(), b.size(), &pos, &out) == DecodeStatus::Ok);
    RC_ASSERT(pos == head.size());
    out = cmd::BoneDestroy{77};
    RC_ASSERT(decode_command(b.data(), b.size(), &pos, &out) == DecodeStatus::Truncated);
    RC_ASSERT(pos == head.size());
    RC_ASSERT(bit_equal(out, Command{cmd::BoneDestroy{77}}));  // output untouched
    std::vector<Command> all;
    RC_ASSERT(decode_commands(b.data(), b.size(), &all) == DecodeStatus::Truncated);
    RC_ASSERT(all.size() == 1u);
  }
}

TEST(CommandBinary, TagsPastTheLastKindAreBadTagsAndLeavePos) {
  for (int tag = static_cast<int>(kCommandKinds); tag < 256; ++tag) {
    const std::vector<std::uint8_t> b{6, 0, 0, 0, 0, static_cast<std::uint8_t>(tag), 0, 0, 0, 0, 0, 0, 0, 0};
    std::size_t pos = 5;
    Command out;
    EXPECT_EQ(decode_command(b.data(), b.size(), &pos, &out), DecodeStatus::BadTag) << tag;
    EXPECT_EQ(pos, 5u);
    std::vector<Command> all;
    EXPECT_EQ(decode_commands(b.data(), b.size(), &all), DecodeStatus::BadTag);
    EXPECT_EQ(all.size(), 1u);
  }
  EXPECT_STREQ(decode_status_name(DecodeStatus::BadTag), "bad-tag");
  EXPECT_STREQ(decode_status_name(DecodeStatus::Truncated), "truncated");
}

TEST(CommandBinary, EmptyInputIsEnd) {
  std::size_t pos = 0;
  Command out;
  EXPECT_EQ(decode_command(nullptr, 0, &pos, &out), DecodeStatus::End);
  std::vector<Command> all;
  EXPECT_EQ(decode_commands(nullptr, 0, &all), DecodeStatus::End);
  EXPECT_TRUE(all.empty());
}

TEST(CommandBinary, NamesOver255BytesRefuseToEncodeAndAppendNothing) {
  std::string out = "keep";
  EXPECT_FALSE(encode_command(cmd::LayerCreate{2, std::string(256, 'a'), 2, 0, 0}, &out));
  EXPECT_EQ(out, "keep");
  cmd::BoneCreate b;
  b.weight = "w";
  b.rot_label = std::string(1000, 'r');
  EXPECT_FALSE(encode_command(b, &out));
  EXPECT_EQ(out, "keep");
  EXPECT_TRUE(encode_command(cmd::LayerCreate{2, std::string(255, 'a'), 2, 0, 0}, &out));
  EXPECT_EQ(out.size(), 4u + 1 + 2 + 1 + 255 + 1 + 4 + 8);
  EXPECT_EQ(static_cast<unsigned char>(out[4 + 3]), 255u);
}

RC_GTEST_PROP(CommandBinaryProperty, ArbitraryBytesNeverCrashAndDecodedPrefixReencodes,
              (std::vector<std::uint8_t> b)) {
  std::vector<Command> all;
  const DecodeStatus s = decode_commands(b.data(), b.size(), &all);
  RC_ASSERT(s != DecodeStatus::Ok);
  std::string e;
  for (const auto& c : all) RC_ASSERT(encode_command(c, &e));
  RC_ASSERT(e.size() <= b.size());
  RC_ASSERT(std::equal(e.begin(), e.end(), b.begin(), [](char x, std::uint8_t y) {
    return static_cast<std::uint8_t>(x) == y;
  }));
  if (s == DecodeStatus::End) RC_ASSERT(e.size() == b.size());
}

// Bytes biased toward valid tags so decoding gets into the fields.
RC_GTEST_PROP(CommandBinaryProperty, TagLedNoiseNeverCrashes, ()) {
  const auto chunks = *rc::gen::container<std::vector<std::vector<std::uint8_t>>>(
      rc::gen::map(rc::gen::pair(rc::gen::inRange<std::uint8_t>(0, kCommandKinds + 2),
                                 rc::gen::container<std::vector<std::uint8_t>>(rc::gen::arbitrary<std::uint8_t>())),
                   [](std::pair<std::uint8_t, std::vector<std::uint8_t>> p) {
                     p.second.insert(p.second.begin(), p.first);
                     return p.second;
                   }));
  std::vector<std::uint8_t> b;
  for (const auto& c : chunks) b.insert(b.end(), c.begin(), c.end());
  std::vector<Command> all;
  const DecodeStatus s = decode_commands(b.data(), b.size(), &all);
  RC_ASSERT(s != DecodeStatus::Ok);
}

}  // namespace
}  // namespace vgc
