// wire_commands.h — the Verse r6 commands vgc sends and receives, as values,
// and their byte form inside a packet.
//
// Spec: docs/verse_wire.md sections 3 (system commands 0-19) and 4 (the
// geometry commands 48-64 and their aliases); docs/spec_facts.md sections
// 3 and 4 (command numbers, field order, aliases).
//
// Rationale: a geometry command on the wire is a vgc::Command (reference/
// node/command.h) plus the node id it is addressed to, so what the suite
// generates is exactly what is sent: encode_command() writes the fields as
// the command holds them, never "fixing" them (a 40-byte name goes out as
// 40 bytes and a NUL, the host's check is what gets judged). decode gives
// the alias form (LayerDestroy, LayerUnsubscribe, VertexDelete,
// PolygonDelete, BoneDestroy) whenever the bytes meet the alias condition,
// as r6's unpackers do; the fields the alias drops are not kept.
// Decoding is bounded by the bytes given: no field is read past the end,
// no string is longer than the packet, nothing is allocated beyond that.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>

#include "command.h"
#include "wire_status.h"

namespace vgc::verse {

// The two forms of bone_create (64) on the wire (docs/verse_wire.md section
// 4). Spec: Verse spec 2.6.3's bone (position, position curve, rotation
// quaternion, rotation curve), the form the suite's commands carry. R6: the
// form of r6's last release (v_cmd_def_g.c: position, then position,
// rotation and scale labels, no rotation value), the form every r6 host and
// r6's client library speak. In the R6 form a decoded bone has the identity
// rotation (0, 0, 0, 1) and its rotation label as rot_label (the scale label
// is dropped); a bone whose rotation is not the identity cannot be encoded.
enum class BoneForm : std::uint8_t { Spec, R6 };
const char* bone_form_name(BoneForm f);  // "spec" / "r6"

// Command numbers (the first byte of each command inside a packet).
inline constexpr std::uint8_t kCmdConnect = 0;           // login stages, not in data packets
inline constexpr std::uint8_t kCmdConnectAccept = 1;     // login stage, not in data packets
inline constexpr std::uint8_t kCmdConnectTerminate = 2;
inline constexpr std::uint8_t kCmdPacketAck = 7;
inline constexpr std::uint8_t kCmdPacketNak = 8;
inline constexpr std::uint8_t kCmdNodeIndexSubscribe = 9;
inline constexpr std::uint8_t kCmdNodeCreate = 10;
inline constexpr std::uint8_t kCmdNodeSubscribe = 11;
inline constexpr std::uint8_t kCmdTagGroupCreate = 16;
inline constexpr std::uint8_t kCmdNodeNameSet = 19;
inline constexpr std::uint8_t kCmdGeometryFirst = 48;    // g_layer_create
inline constexpr std::uint8_t kCmdGeometryLast = 64;     // g_bone_create

// Node types of node_create / node_index_subscribe (r6 VNodeType).
inline constexpr std::uint8_t kNodeTypeObject = 0;
inline constexpr std::uint8_t kNodeTypeGeometry = 1;
inline constexpr std::uint8_t kNodeTypeCount = 7;        // a type >= 7 means node_destroy
// Owner field of node_create (r6 VNodeOwner); 255 means node_destroy.
inline constexpr std::uint8_t kOwnerOther = 0;
inline constexpr std::uint8_t kOwnerMine = 1;
inline constexpr std::uint32_t kAnyNodeId = 0xFFFFFFFFu;  // node_create: "host, pick an id"

// Longest string field accepted or written (r6's longest, node_name_set and
// connect_terminate: 512 bytes with the NUL).
inline constexpr std::size_t kMaxWireString = 512;

namespace wire {
struct ConnectTerminate { std::string bye; };               // 2
struct PacketAck { std::uint32_t packet_id = 0; };          // 7
struct PacketNak { std::uint32_t packet_id = 0; };          // 8
struct NodeIndexSubscribe { std::uint32_t mask = 0; };      // 9: bit t = node type t
struct NodeCreate {                                         // 10
  std::uint32_t node_id = kAnyNodeId;
  std::uint8_t type = kNodeTypeGeometry;
  std::uint8_t owner = kOwnerMine;
};
struct NodeDestroy { std::uint32_t node_id = 0; };          // 10 with owner 255 or type >= 7
struct NodeSubscribe { std::uint32_t node_id = 0; };        // 11, flag byte 1
struct NodeUnsubscribe { std::uint32_t node_id = 0; };      // 11, flag byte 0
struct TagGroupCreate {                                     // 16 (decoded so a real host's subscribe
  std::uint32_t node_id = 0;                                //  answer parses; vgc's host sends none)
  std::uint16_t group_id = 0;
  std::string name;
};
struct NodeNameSet {                                        // 19
  std::uint32_t node_id = 0;
  std::string name;
};
struct Geometry {                                           // 48..64
  std::uint32_t node_id = 0;
  vgc::Command command;
};
}  // namespace wire

using WireCommand =
    std::variant<wire::ConnectTerminate, wire::PacketAck, wire::PacketNak, wire::NodeIndexSubscribe,
                 wire::NodeCreate, wire::NodeDestroy, wire::NodeSubscribe, wire::NodeUnsubscribe,
                 wire::TagGroupCreate, wire::NodeNameSet, wire::Geometry>;

// The command number a value is sent as (48..64 for geometry).
std::uint8_t command_number(const WireCommand& c);
std::uint8_t geometry_command_number(const vgc::Command& c);
// "node_create", "g_vertex_set_xyz_real32", ... for logs and errors.
std::string describe(const WireCommand& c);

// Appends the command's bytes (number, then fields) to *out. Fails
// (ProtocolError, *out unchanged) only for what the wire cannot carry: a
// string with a NUL inside or longer than kMaxWireString, a bone rotation in
// the R6 form.
Status encode_command(const WireCommand& c, std::string* out, BoneForm bones = BoneForm::Spec);

// Decodes one command from data[0..size): on success *used is its length
// (number byte included). An unknown command number, a truncated field or a
// string without its NUL within the bytes is a ProtocolError naming the
// command and the field.
Status decode_command(const std::uint8_t* data, std::size_t size, std::size_t* used, WireCommand* out,
                      BoneForm bones = BoneForm::Spec);

// The value decode_command(encode_command(c)) gives: the alias form where
// the fields meet an alias condition (LayerCreate with an empty name ->
// LayerDestroy, ...), c itself otherwise. Round-trip tests compare to it.
vgc::Command wire_canonical(const vgc::Command& c);

}  // namespace vgc::verse
