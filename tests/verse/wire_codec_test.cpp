// wire_codec_test.cpp — verse/wire_commands, wire_packet, wire_login:
// every geometry command and alias round-trips, the bytes are r6's layout
// (docs/verse_wire.md sections 1-4), and hostile packets are
// protocol-errors, never crashes.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <set>

#include "arbitrary_command.h"
#include "transcript_values.h"
#include "wire_commands.h"
#include "wire_login.h"
#include "wire_packet.h"

namespace vgc::verse {
namespace {

std::vector<Command> every_kind() {
  return {cmd::LayerCreate{2, "weights", 1, 7, 0.5},
          cmd::LayerDestroy{2},
          cmd::LayerSubscribe{0, 1},
          cmd::LayerUnsubscribe{3},
          cmd::VertexSetXyzReal32{0, 5, 1.5f, -2.0f, 3.0f},
          cmd::VertexSetXyzReal64{0, 6, 1.0, 2.0, -0.0},
          cmd::VertexDelete{7},
          cmd::VertexSetUint32{2, 1, 9},
          cmd::VertexSetReal64{3, 1, 0.25},
          cmd::VertexSetReal32{3, 1, 0.5f},
          cmd::PolygonSetCornerUint32{1, 0, {0, 1, 2, 0xFFFFFFFFu}},
          cmd::PolygonSetCornerReal64{4, 0, {1, 2, 3, 4}},
          cmd::PolygonSetCornerReal32{4, 0, {1, 2, 3, 4}},
          cmd::PolygonDelete{3},
          cmd::PolygonSetFaceUint8{5, 0, 200},
          cmd::PolygonSetFaceUint32{5, 0, 123456},
          cmd::PolygonSetFaceReal64{5, 1, std::numeric_limits<double>::quiet_NaN()},
          cmd::PolygonSetFaceReal32{5, 1, -0.0f},
          cmd::CreaseSetVertex{"sharp", 5},
          cmd::CreaseSetEdge{"", 0xFFFFFFFFu},
          cmd::BoneCreate{4, "w", "r", 0xFFFF, {1, 2, 3}, "pos", {0, 0, 0.6, 0.8}, "rot"},
          cmd::BoneDestroy{4}};
}

using vgc_transcript::hex;

Command decode_one(const std::string& bytes) {
  WireCommand w;
  std::size_t used = 0;
  Status st = decode_command(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), &used, &w);
  EXPECT_TRUE(st.ok()) << st.to_string();
  EXPECT_EQ(used, bytes.size());
  EXPECT_TRUE(std::holds_alternative<wire::Geometry>(w));
  if (!std::holds_alternative<wire::Geometry>(w)) return {};
  EXPECT_EQ(std::get<wire::Geometry>(w).node_id, 77u);
  return std::get<wire::Geometry>(w).command;
}

TEST(VerseCodec, EveryGeometryCommandAndAliasRoundTrips) {
  std::set<std::size_t> kinds;
  for (const Command& c : every_kind()) {
    kinds.insert(c.index());
    std::string bytes;
    ASSERT_TRUE(encode_command(wire::Geometry{77, c}, &bytes).ok());
    const Command back = decode_one(bytes);
    EXPECT_TRUE(bit_equal(back, c)) << command_verb(c) << " came back as " << command_verb(back);
  }
  EXPECT_EQ(kinds.size(), kCommandKinds) << "every_kind() must list every command of command.h";
}

TEST(VerseCodec, BytesFollowTheR6Layout) {
  // g_layer_create: 48, node u32, layer u16, name + NUL, type u8, def_uint u32, def_real f64. A real64
  // goes as r6 on a little-endian machine packs it (docs/verse_wire.md section 1): its low 32 bits first,
  // then its high 32 bits, each big-endian. 0.5 is 0x3FE0000000000000.
  std::string b;
  ASSERT_TRUE(encode_command(wire::Geometry{9, cmd::LayerCreate{2, "ab", 1, 7, 0.5}}, &b).ok());
  EXPECT_EQ(hex(b), "30" "00000009" "0002" "616200" "01" "00000007" "00000000" "3fe00000");
  // -4.0 (0xC010000000000000) in g_vertex_set_xyz_real64, as the r6 host sent it in the issue 18 run;
  // read high word first it was 1.5920149086e-314.
  b.clear();
  ASSERT_TRUE(encode_command(wire::Geometry{77, cmd::VertexSetXyzReal64{0, 0, -4, -4, -4}}, &b).ok());
  EXPECT_EQ(hex(b), "33" "0000004d" "0000" "00000000" "00000000c0100000" "00000000c0100000" "00000000c0100000");
  {
    const Command back = decode_one(b);
    const auto* v = std::get_if<cmd::VertexSetXyzReal64>(&back);
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(v->x, -4.0);
  }
  // g_vertex_delete_real32 as r6 sends it: 50, layer 0, FLT_MAX three times.
  b.clear();
  ASSERT_TRUE(encode_command(wire::Geometry{1, cmd::VertexDelete{7}}, &b).ok());
  EXPECT_EQ(hex(b), "32" "00000001" "0000" "00000007" "7f7fffff7f7fffff7f7fffff");
  // g_polygon_delete: 55 on layer 1, all four corners 0xFFFFFFFF.
  b.clear();
  ASSERT_TRUE(encode_command(wire::Geometry{1, cmd::PolygonDelete{3}}, &b).ok());
  EXPECT_EQ(hex(b), "37" "00000001" "0001" "00000003" "ffffffffffffffffffffffffffffffff");
  // g_layer_unsubscribe: 49 with format 255.
  b.clear();
  ASSERT_TRUE(encode_command(wire::Geometry{1, cmd::LayerUnsubscribe{4}}, &b).ok());
  EXPECT_EQ(hex(b), "31" "00000001" "0004" "ff");
  // System commands: node_create(~0, geometry, mine), node_subscribe, packet_ack.
  b.clear();
  ASSERT_TRUE(encode_command(wire::NodeCreate{}, &b).ok());
  ASSERT_TRUE(encode_command(wire::NodeSubscribe{5}, &b).ok());
  ASSERT_TRUE(encode_command(wire::PacketAck{0x01020304}, &b).ok());
  EXPECT_EQ(hex(b), "0a" "ffffffff" "01" "01" "0b" "00000005" "01" "07" "01020304");
}

TEST(VerseCodec, RawFormsDecodeToTheirAliasOnlyWhereR6Says) {
  auto through = [](const Command& c) {
    std::string b;
    EXPECT_TRUE(encode_command(wire::Geometry{77, c}, &b).ok());
    return decode_one(b);
  };
  EXPECT_TRUE(bit_equal(through(cmd::LayerCreate{3, "", 1, 0, 0}), Command{cmd::LayerDestroy{3}}));
  EXPECT_TRUE(bit_equal(through(cmd::LayerSubscribe{3, 9}), Command{cmd::LayerUnsubscribe{3}}));
  EXPECT_TRUE(bit_equal(through(cmd::VertexSetXyzReal64{3, 8, 0, DBL_MAX, 0}), Command{cmd::VertexDelete{8}}));
  EXPECT_TRUE(bit_equal(through(cmd::VertexSetXyzReal32{0, 8, 0, 0, FLT_MAX}), Command{cmd::VertexDelete{8}}));
  EXPECT_TRUE(bit_equal(through(cmd::BoneCreate{6, "", "r", 1, {}, "", {0, 0, 0, 1}, ""}), Command{cmd::BoneDestroy{6}}));
  // Only layer 1's v0 = 0xFFFFFFFF is a polygon delete.
  const Command other_layer = cmd::PolygonSetCornerUint32{4, 2, {0xFFFFFFFFu, 1, 2, 3}};
  EXPECT_TRUE(bit_equal(through(other_layer), other_layer));
  const Command base_layer = cmd::PolygonSetCornerUint32{1, 2, {0xFFFFFFFFu, 1, 2, 3}};
  EXPECT_TRUE(bit_equal(through(base_layer), Command{cmd::PolygonDelete{2}}));
}

RC_GTEST_PROP(VerseCodec, AnyCommandRoundTripsToItsCanonicalForm, (const Command& c)) {
  std::string bytes = "prefix";
  const Status st = encode_command(wire::Geometry{0xFFFFFFFFu, c}, &bytes);
  if (!st.ok()) {  // only names holding a NUL cannot be sent
    RC_ASSERT(st.code == Status::Code::ProtocolError);
    RC_ASSERT(bytes == "prefix");
    return;
  }
  WireCommand w;
  std::size_t used = 0;
  RC_ASSERT(decode_command(reinterpret_cast<const std::uint8_t*>(bytes.data()) + 6, bytes.size() - 6, &used, &w).ok());
  RC_ASSERT(used == bytes.size() - 6);
  RC_ASSERT(bit_equal(std::get<wire::Geometry>(w).command, wire_canonical(c)));
}

// bone_create in r6's form (r6 v_gen_pack_g_node.c verse_send_g_bone_create):
// node, bone_id, weight, reference, parent, pos x y z, then position,
// rotation and scale labels; bone_destroy as r6 sends it.
TEST(VerseCodec, BoneCreateInR6sFormHasR6sBytes) {
  cmd::BoneCreate b{2, "w", "", 0xFFFF, {1, 0, 0}, "p", {0, 0, 0, 1}, "r"};
  std::string bytes;
  ASSERT_TRUE(encode_command(wire::Geometry{5, b}, &bytes, BoneForm::R6).ok());
  EXPECT_EQ(hex(bytes), "40" "00000005" "0002" "7700" "00" "ffff" "000000003ff00000" "0000000000000000"
                        "0000000000000000" "7000" "7200" "00");
  std::size_t used = 0;
  WireCommand w;
  ASSERT_TRUE(decode_command(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), &used, &w,
                             BoneForm::R6).ok());
  EXPECT_EQ(used, bytes.size());
  EXPECT_TRUE(bit_equal(std::get<wire::Geometry>(w).command, Command(b)));
  // The same bytes read in the spec's form run out (the rotation is missing).
  EXPECT_FALSE(decode_command(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), &used, &w).ok());
  bytes.clear();
  ASSERT_TRUE(encode_command(wire::Geometry{5, cmd::BoneDestroy{2}}, &bytes, BoneForm::R6).ok());
  EXPECT_EQ(hex(bytes), "40" "00000005" "0002" "00" "00" "ffff" "ffffffff7fefffff" "ffffffff7fefffff"
                        "ffffffff7fefffff" "00" "00" "00");
  // A rotation r6's form cannot carry is refused, nothing written.
  bytes.clear();
  b.rot = {0, 1, 0, 0};
  EXPECT_EQ(encode_command(wire::Geometry{5, b}, &bytes, BoneForm::R6).code, Status::Code::ProtocolError);
  EXPECT_TRUE(bytes.empty());
}

TEST(VersePacket, APacketInTheOtherBoneFormIsReadInItWhenAsked) {
  std::string cmds;
  ASSERT_TRUE(encode_command(wire::Geometry{5, cmd::BoneCreate{2, "w", "", 0xFFFF, {1, 0, 0}, "p", {0, 0, 0, 1}, "r"}},
                             &cmds, BoneForm::R6).ok());
  ASSERT_TRUE(encode_command(wire::NodeNameSet{5, "vgc-barrier-1"}, &cmds).ok());
  const std::string bytes = build_packet(3, cmds);
  Packet p;
  const auto* d = reinterpret_cast<const std::uint8_t*>(bytes.data());
  EXPECT_EQ(parse_packet(d, bytes.size(), &p).code, Status::Code::ProtocolError);  // r6's own behaviour
  ASSERT_TRUE(parse_packet(d, bytes.size(), &p, BoneForm::Spec, true).ok());
  EXPECT_TRUE(p.other_bone_form);
  ASSERT_EQ(p.commands.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<wire::NodeNameSet>(p.commands[1]));
  ASSERT_TRUE(parse_packet(d, bytes.size(), &p, BoneForm::R6, true).ok());
  EXPECT_FALSE(p.other_bone_form);
}

TEST(VerseCodec, NamesWithNulCannotBeEncoded) {
  std::string b;
  const Status st = encode_command(wire::Geometry{1, cmd::LayerCreate{2, std::string("a\0b", 3), 1, 0, 0}}, &b);
  EXPECT_EQ(st.code, Status::Code::ProtocolError);
  EXPECT_TRUE(b.empty());
}

std::string sample_packet() {
  std::string cmds;
  for (const Command& c : every_kind()) EXPECT_TRUE(encode_command(wire::Geometry{77, c}, &cmds).ok());
  EXPECT_TRUE(encode_command(wire::NodeNameSet{77, "name"}, &cmds).ok());
  return build_packet(9, cmds);
}

Status parse(const std::string& bytes, Packet* p) {
  return parse_packet(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), p);
}

TEST(VersePacket, ParsesEveryCommandOfAPacket) {
  Packet p;
  ASSERT_TRUE(parse(sample_packet(), &p).ok());
  EXPECT_EQ(p.id, 9u);
  EXPECT_EQ(p.commands.size(), every_kind().size() + 1);
}

TEST(VersePacket, EveryTruncationIsAProtocolErrorOrAShorterPacket) {
  const std::string whole = sample_packet();
  Packet full;
  ASSERT_TRUE(parse(whole, &full).ok());
  std::size_t errors = 0;
  for (std::size_t n = 0; n < whole.size(); ++n) {
    Packet p;
    const Status st = parse(whole.substr(0, n), &p);
    if (st.ok()) {
      EXPECT_LT(p.commands.size(), full.commands.size()) << "cut at " << n;
    } else {
      EXPECT_EQ(st.code, Status::Code::ProtocolError);
      EXPECT_FALSE(st.detail.empty());
      ++errors;
    }
    EXPECT_LE(p.commands.size(), n / 5 + 1);
  }
  EXPECT_GT(errors, whole.size() / 2);
}

TEST(VersePacket, HostileBytesAreNamedProtocolErrors) {
  Packet p;
  Status st = parse(build_packet(3, std::string("\xc8\x00\x00", 3)), &p);
  EXPECT_EQ(st.code, Status::Code::ProtocolError);
  EXPECT_NE(st.detail.find("unknown command number 200"), std::string::npos) << st.detail;
  // A layer name running to the end of the packet without its NUL.
  std::string unterminated = std::string("\x30\x00\x00\x00\x01\x00\x02", 7) + std::string(600, 'a');
  st = parse(build_packet(3, unterminated), &p);
  EXPECT_EQ(st.code, Status::Code::ProtocolError);
  EXPECT_NE(st.detail.find("name"), std::string::npos) << st.detail;
  // Longer than any r6 packet.
  std::string acks;
  for (int i = 0; i < 400; ++i) ASSERT_TRUE(encode_command(wire::PacketAck{static_cast<std::uint32_t>(i)}, &acks).ok());
  st = parse(build_packet(3, acks), &p);
  EXPECT_EQ(st.code, Status::Code::ProtocolError);
  EXPECT_NE(st.detail.find("longer than 1500"), std::string::npos) << st.detail;
  // Shorter than the id; an id and nothing else.
  EXPECT_EQ(parse(std::string("\x00\x01", 2), &p).code, Status::Code::ProtocolError);
  EXPECT_EQ(parse(build_packet(3, ""), &p).code, Status::Code::ProtocolError);
  // The commands before a bad one are kept.
  std::string two;
  ASSERT_TRUE(encode_command(wire::NodeSubscribe{4}, &two).ok());
  two += '\xfe';
  st = parse(build_packet(3, two), &p);
  EXPECT_EQ(st.code, Status::Code::ProtocolError);
  ASSERT_EQ(p.commands.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<wire::NodeSubscribe>(p.commands[0]));
}

TEST(VersePacket, XorIsItsOwnInverseAndLeavesTheIdClear) {
  DataKey key = make_data_key();
  const std::string clear = sample_packet();
  std::string p = clear;
  xor_packet(&p, key);
  EXPECT_EQ(p.substr(0, 4), clear.substr(0, 4));
  EXPECT_NE(p, clear);
  xor_packet(&p, key);
  EXPECT_EQ(p, clear);
}

TEST(VerseLogin, RsaRoundTripAndTheLoginBlock) {
  const RsaKey k = make_rsa_key();
  EXPECT_GE(k.n[0], 0x80) << "the modulus has its top bit set";
  KeyBytes block{}, enc{}, dec{};
  ASSERT_TRUE(make_login_block("alice", "secret", &block));
  ASSERT_TRUE(rsa_apply(block, k.e, k.n, &enc).ok());
  EXPECT_NE(enc, block);
  ASSERT_TRUE(rsa_apply(enc, k.d, k.n, &dec).ok());
  EXPECT_EQ(dec, block);
  std::string name, pass;
  ASSERT_TRUE(read_login_block(dec, &name, &pass).ok());
  EXPECT_EQ(name, "alice");
  EXPECT_EQ(pass, "secret");
  // Known answer: 2^65537 mod 1000003 = 2^(65537 mod 1000002) ... checked with a small modulus.
  KeyBytes two{}, e{}, n{}, out{};
  two[63] = 2;
  e[61] = 0x01; e[63] = 0x01;  // 65537
  n[61] = 0x0f; n[62] = 0x42; n[63] = 0x43;  // 1000003 (prime)
  ASSERT_TRUE(rsa_apply(two, e, n, &out).ok());
  std::uint64_t r = 1, base = 2;
  for (std::uint64_t x = 65537; x; x >>= 1, base = base * base % 1000003)
    if (x & 1) r = r * base % 1000003;
  EXPECT_EQ((std::uint64_t{out[61]} << 16) | (std::uint64_t{out[62]} << 8) | out[63], r);
  // Hostile keys.
  EXPECT_EQ(rsa_apply(two, e, KeyBytes{}, &out).code, Status::Code::ProtocolError);
  KeyBytes big{};
  big.fill(0xff);
  EXPECT_EQ(rsa_apply(big, e, n, &out).code, Status::Code::ProtocolError);
  EXPECT_FALSE(make_login_block(std::string(32, 'x'), "p", &block));
}

TEST(VerseLogin, StagePacketsRoundTripAndShortOnesAreErrors) {
  const RsaKey k = make_rsa_key();
  login::Challenge c;
  c.seconds = 5;
  c.e = k.e;
  c.n = k.n;
  const std::string bytes = build_login_packet(c);
  EXPECT_EQ(bytes.size(), 4u + 1 + 1 + 1 + 8 + 128);
  LoginMessage m;
  ASSERT_TRUE(parse_login_packet(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), &m).ok());
  ASSERT_TRUE(std::holds_alternative<login::Challenge>(m));
  EXPECT_EQ(std::get<login::Challenge>(m).n, k.n);
  for (std::size_t n = 0; n < bytes.size(); ++n)
    EXPECT_EQ(parse_login_packet(reinterpret_cast<const std::uint8_t*>(bytes.data()), n, &m).code,
              Status::Code::ProtocolError)
        << n;
}

}  // namespace
}  // namespace vgc::verse
