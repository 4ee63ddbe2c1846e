// r6_replay_test.cpp — replays the recorded r6 interop transcripts
// (tests/verse/r6_fixtures/*.txt, written by record.sh from an r6 tree) with
// no r6 present: every data packet r6's client library sent or received,
// decrypted by vgc with the recorded key, must be the bytes r6 decrypted,
// and vgc's decoding of every command in it must be r6's: same command
// number, same length, same fields (as r6's callbacks printed them).
//
// Spec: docs/verse_wire.md sections 1-4 (encodings, encryption, commands,
// aliases) and 10 (the transcripts, what is compared, the one field vgc
// does not keep: bone_create's scale label).
//
// Rationale: vgc's codec was written from r6's sources; these transcripts
// are what r6 does as it runs, so a codec fact that is wrong (a real64's
// word order, an alias condition, a field width) fails here by packet,
// command and field, not as a timeout somewhere in a certify run.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "wire_commands.h"
#include "transcript_values.h"
#include "wire_packet.h"

namespace vgc::verse {
namespace {

struct RecordedCmd {
  unsigned number = 0, length = 0;
  std::string decoded;
};
struct RecordedPacket {
  char dir = 'r';
  std::uint32_t id = 0;
  std::string raw, plain;
  std::vector<RecordedCmd> cmds;
  int line = 0;
};
struct Transcript {
  std::string key;
  std::vector<RecordedPacket> packets;
  bool complete = false;  // "end" seen
};

using vgc_transcript::unhex;

Transcript load(const std::string& path) {
  Transcript t;
  std::ifstream in(path);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "key") {
      std::string h;
      s >> h;
      t.key = unhex(h);
    } else if (tag == "packet") {
      RecordedPacket p;
      s >> p.dir >> p.id;
      p.line = n;
      t.packets.push_back(p);
    } else if (tag == "raw" && !t.packets.empty()) {
      std::string h;
      s >> h;
      t.packets.back().raw = unhex(h);
    } else if (tag == "plain" && !t.packets.empty()) {
      std::string h;
      s >> h;
      t.packets.back().plain = unhex(h);
    } else if (tag == "cmd" && !t.packets.empty()) {
      RecordedCmd c;
      s >> c.number >> c.length;
      std::getline(s >> std::ws, c.decoded);
      t.packets.back().cmds.push_back(c);
    } else if (tag == "end") {
      t.complete = true;
    }
  }
  return t;
}

// The text r6_tap.cpp writes, for vgc's decoded values.
using vgc_transcript::r32;
using vgc_transcript::r64;
std::string str(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (c == 0) break;
    if (c > 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02x", c);
      out += b;
    }
  }
  return out.empty() ? "\\empty" : out;
}
std::string u(std::uint64_t v) { return std::to_string(v); }

std::string slot_head(const char* verb, std::uint32_t node, unsigned layer, const char* what, std::uint32_t id) {
  return std::string(verb) + " node=" + u(node) + " layer=" + u(layer) + " " + what + "=" + u(id);
}

std::string render_geometry(std::uint32_t node, const Command& command, unsigned number) {
  return std::visit(
      [&](const auto& c) -> std::string {
        using T = std::decay_t<decltype(c)>;
        const std::string n = "node=" + u(node);
        if constexpr (std::is_same_v<T, cmd::LayerCreate>) {
          return "g_layer_create " + n + " layer=" + u(c.layer_id) + " name=" + str(c.name) + " type=" + u(c.type) +
                 " def_uint=" + u(c.def_uint) + " def_real=" + r64(c.def_real);
        } else if constexpr (std::is_same_v<T, cmd::LayerDestroy>) {
          return "g_layer_destroy " + n + " layer=" + u(c.layer_id);
        } else if constexpr (std::is_same_v<T, cmd::LayerSubscribe>) {
          return "g_layer_subscribe " + n + " layer=" + u(c.layer_id) + " type=" + u(c.real_format);
        } else if constexpr (std::is_same_v<T, cmd::LayerUnsubscribe>) {
          return "g_layer_unsubscribe " + n + " layer=" + u(c.layer_id);
        } else if constexpr (std::is_same_v<T, cmd::VertexSetXyzReal32>) {
          return slot_head("g_vertex_set_xyz_real32", node, c.layer_id, "vertex", c.vertex_id) + " x=" + r32(c.x) +
                 " y=" + r32(c.y) + " z=" + r32(c.z);
        } else if constexpr (std::is_same_v<T, cmd::VertexSetXyzReal64>) {
          return slot_head("g_vertex_set_xyz_real64", node, c.layer_id, "vertex", c.vertex_id) + " x=" + r64(c.x) +
                 " y=" + r64(c.y) + " z=" + r64(c.z);
        } else if constexpr (std::is_same_v<T, cmd::VertexDelete>) {
          return std::string(number == 50 ? "g_vertex_delete_real32 " : "g_vertex_delete_real64 ") + n +
                 " vertex=" + u(c.vertex_id);
        } else if constexpr (std::is_same_v<T, cmd::VertexSetUint32>) {
          return slot_head("g_vertex_set_uint32", node, c.layer_id, "vertex", c.vertex_id) + " value=" + u(c.value);
        } else if constexpr (std::is_same_v<T, cmd::VertexSetReal64>) {
          return slot_head("g_vertex_set_real64", node, c.layer_id, "vertex", c.vertex_id) + " value=" + r64(c.value);
        } else if constexpr (std::is_same_v<T, cmd::VertexSetReal32>) {
          return slot_head("g_vertex_set_real32", node, c.layer_id, "vertex", c.vertex_id) + " value=" + r32(c.value);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetCornerUint32>) {
          return slot_head("g_polygon_set_corner_uint32", node, c.layer_id, "polygon", c.polygon_id) +
                 " v0=" + u(c.v[0]) + " v1=" + u(c.v[1]) + " v2=" + u(c.v[2]) + " v3=" + u(c.v[3]);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetCornerReal64>) {
          return slot_head("g_polygon_set_corner_real64", node, c.layer_id, "polygon", c.polygon_id) +
                 " v0=" + r64(c.v[0]) + " v1=" + r64(c.v[1]) + " v2=" + r64(c.v[2]) + " v3=" + r64(c.v[3]);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetCornerReal32>) {
          return slot_head("g_polygon_set_corner_real32", node, c.layer_id, "polygon", c.polygon_id) +
                 " v0=" + r32(c.v[0]) + " v1=" + r32(c.v[1]) + " v2=" + r32(c.v[2]) + " v3=" + r32(c.v[3]);
        } else if constexpr (std::is_same_v<T, cmd::PolygonDelete>) {
          return "g_polygon_delete " + n + " polygon=" + u(c.polygon_id);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetFaceUint8>) {
          return slot_head("g_polygon_set_face_uint8", node, c.layer_id, "polygon", c.polygon_id) +
                 " value=" + u(c.value);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetFaceUint32>) {
          return slot_head("g_polygon_set_face_uint32", node, c.layer_id, "polygon", c.polygon_id) +
                 " value=" + u(c.value);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetFaceReal64>) {
          return slot_head("g_polygon_set_face_real64", node, c.layer_id, "polygon", c.polygon_id) +
                 " value=" + r64(c.value);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetFaceReal32>) {
          return slot_head("g_polygon_set_face_real32", node, c.layer_id, "polygon", c.polygon_id) +
                 " value=" + r32(c.value);
        } else if constexpr (std::is_same_v<T, cmd::CreaseSetVertex>) {
          return "g_crease_set_vertex " + n + " layer=" + str(c.layer) + " def_crease=" + u(c.def_crease);
        } else if constexpr (std::is_same_v<T, cmd::CreaseSetEdge>) {
          return "g_crease_set_edge " + n + " layer=" + str(c.layer) + " def_crease=" + u(c.def_crease);
        } else if constexpr (std::is_same_v<T, cmd::BoneCreate>) {
          // r6's form (BoneForm::R6): vgc keeps no scale label, so the text
          // ends before it (compared without r6's scale_label field).
          return "g_bone_create " + n + " bone=" + u(c.bone_id) + " weight=" + str(c.weight) +
                 " reference=" + str(c.reference) + " parent=" + u(c.parent) + " pos_x=" + r64(c.pos[0]) +
                 " pos_y=" + r64(c.pos[1]) + " pos_z=" + r64(c.pos[2]) + " position_label=" + str(c.pos_label) +
                 " rotation_label=" + str(c.rot_label);
        } else {
          static_assert(std::is_same_v<T, cmd::BoneDestroy>);
          return "g_bone_destroy " + n + " bone=" + u(c.bone_id);
        }
      },
      command);
}

std::string render(const WireCommand& command, unsigned number) {
  return std::visit(
      [&](const auto& c) -> std::string {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, wire::ConnectTerminate>) {
          return "connect_terminate bye=" + str(c.bye);
        } else if constexpr (std::is_same_v<T, wire::PacketAck>) {
          return "packet_ack id=" + u(c.packet_id);
        } else if constexpr (std::is_same_v<T, wire::PacketNak>) {
          return "packet_nak id=" + u(c.packet_id);
        } else if constexpr (std::is_same_v<T, wire::NodeIndexSubscribe>) {
          return "node_index_subscribe mask=" + u(c.mask);
        } else if constexpr (std::is_same_v<T, wire::NodeCreate>) {
          return "node_create node=" + u(c.node_id) + " type=" + u(c.type) + " owner=" + u(c.owner);
        } else if constexpr (std::is_same_v<T, wire::NodeDestroy>) {
          return "node_destroy node=" + u(c.node_id);
        } else if constexpr (std::is_same_v<T, wire::NodeSubscribe>) {
          return "node_subscribe node=" + u(c.node_id);
        } else if constexpr (std::is_same_v<T, wire::NodeUnsubscribe>) {
          return "node_unsubscribe node=" + u(c.node_id);
        } else if constexpr (std::is_same_v<T, wire::TagGroupCreate>) {
          return "tag_group_create node=" + u(c.node_id) + " group=" + u(c.group_id) + " name=" + str(c.name);
        } else if constexpr (std::is_same_v<T, wire::NodeNameSet>) {
          return "node_name_set node=" + u(c.node_id) + " name=" + str(c.name);
        } else {
          static_assert(std::is_same_v<T, wire::Geometry>);
          return render_geometry(c.node_id, c.command, number);
        }
      },
      command);
}

// r6's text of a bone_create without the scale label vgc does not keep.
std::string comparable(const std::string& r6_text) {
  if (r6_text.rfind("g_bone_create ", 0) != 0) return r6_text;
  std::size_t at = r6_text.find(" scale_label=");
  return at == std::string::npos ? r6_text : r6_text.substr(0, at);
}

bool reencodable(const WireCommand& w) {
  const auto* g = std::get_if<wire::Geometry>(&w);
  if (g == nullptr) return !std::holds_alternative<wire::NodeDestroy>(w) && !std::holds_alternative<wire::NodeUnsubscribe>(w);
  return !std::holds_alternative<cmd::LayerDestroy>(g->command) &&
         !std::holds_alternative<cmd::LayerUnsubscribe>(g->command) &&
         !std::holds_alternative<cmd::VertexDelete>(g->command) &&
         !std::holds_alternative<cmd::PolygonDelete>(g->command) &&
         !std::holds_alternative<cmd::BoneCreate>(g->command) && !std::holds_alternative<cmd::BoneDestroy>(g->command);
}

// Replays one transcript; *compared counts the commands compared.
void replay(const std::string& file, std::set<unsigned>* numbers_seen, std::size_t* compared_out,
            std::set<std::string>* verbs_seen) {
  Transcript t = load(std::string(VGC_R6_FIXTURES) + "/" + file);
  EXPECT_TRUE(t.complete) << file << ": no 'end' line (a partial recording)";
  EXPECT_EQ(t.key.size(), kDataKeyBytes) << file;
  DataKey key{};
  for (std::size_t i = 0; i < key.size() && i < t.key.size(); ++i) key[i] = static_cast<std::uint8_t>(t.key[i]);
  std::size_t compared = 0;
  *compared_out = 0;
  for (const RecordedPacket& p : t.packets) {
    const std::string where = file + ":" + std::to_string(p.line) + " packet " + p.dir + " " + std::to_string(p.id);
    std::string plain = p.raw;
    xor_packet(&plain, key);
    EXPECT_EQ(plain, p.plain) << where << ": vgc's decryption differs from r6's";
    const auto* data = reinterpret_cast<const std::uint8_t*>(p.plain.data());
    std::size_t pos = 4;
    for (const RecordedCmd& c : p.cmds) {
      ASSERT_LT(pos, p.plain.size()) << where << ": r6 decoded more than the packet holds";
      EXPECT_EQ(data[pos], c.number) << where << " at byte " << pos;
      std::size_t used = 0;
      WireCommand decoded;
      Status st = decode_command(data + pos, p.plain.size() - pos, &used, &decoded, BoneForm::R6);
      EXPECT_TRUE(st.ok()) << where << " at byte " << pos << ": vgc does not decode what r6 decoded as \""
                           << c.decoded << "\": " << st.detail;
      if (!st.ok()) break;
      EXPECT_EQ(used, 1u + c.length) << where << " at byte " << pos << ": vgc read " << used
                                     << " bytes, r6 read " << 1 + c.length << " (\"" << c.decoded << "\")";
      if (c.decoded != "(no callback)") {
        EXPECT_EQ(render(decoded, c.number), comparable(c.decoded)) << where << " at byte " << pos;
      }
      // vgc's encoder writes the same bytes for what it decoded (the
      // aliases and bone_create excepted: decoding keeps no 50/51, no
      // type/def bytes of a destroy, no scale label).
      if (reencodable(decoded)) {
        std::string again;
        EXPECT_TRUE(encode_command(decoded, &again, BoneForm::R6).ok()) << where;
        EXPECT_EQ(again, p.plain.substr(pos, used)) << where << " at byte " << pos << ": vgc encodes \""
                                                    << c.decoded << "\" differently from r6";
      }
      numbers_seen->insert(c.number);
      verbs_seen->insert(c.decoded.substr(0, c.decoded.find(' ')));
      ++compared;
      pos += 1 + c.length;
    }
    EXPECT_EQ(pos, p.plain.size()) << where << ": r6 decoded the packet to its end, the replay did not";
    *compared_out = compared;
  }
}

// Every alias of docs/verse_wire.md section 4, as r6's callbacks name them.
const char* const kAliases[] = {"g_layer_destroy",        "g_layer_unsubscribe", "g_vertex_delete_real32",
                                "g_vertex_delete_real64", "g_polygon_delete",    "g_bone_destroy"};

TEST(R6Replay, R6HostTranscriptDecodesAsR6DecodedIt) {
  std::set<unsigned> seen;
  std::size_t compared = 0;
  std::set<std::string> verbs;
  replay("r6_host.txt", &seen, &compared, &verbs);
  for (const char* alias : kAliases) EXPECT_EQ(verbs.count(alias), 1u) << "the transcript holds no " << alias;
  EXPECT_GT(compared, 100u);
  for (unsigned n = kCmdGeometryFirst; n <= kCmdGeometryLast; ++n)
    EXPECT_EQ(seen.count(n), 1u) << "the transcript holds no command " << n;
}

TEST(R6Replay, VgcHostTranscriptDecodesAsR6DecodedIt) {
  std::set<unsigned> seen;
  std::size_t compared = 0;
  std::set<std::string> verbs;
  replay("vgc_host.txt", &seen, &compared, &verbs);
  for (const char* alias : kAliases) EXPECT_EQ(verbs.count(alias), 1u) << "the transcript holds no " << alias;
  EXPECT_GT(compared, 100u);
  for (unsigned n = kCmdGeometryFirst; n <= kCmdGeometryLast; ++n)
    EXPECT_EQ(seen.count(n), 1u) << "the transcript holds no command " << n;
}

}  // namespace
}  // namespace vgc::verse
