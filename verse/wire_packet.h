// wire_packet.h — one UDP datagram of the Verse r6 protocol: a 32-bit
// packet id and the commands after it; the XOR data encryption of r6.
//
// Spec: docs/verse_wire.md sections 1 (packet layout), 2 (encryption) and
// 5 (acknowledgements).
//
// Rationale: parse_packet() is the one entry point for every byte a peer
// sends once logged in, and the libFuzzer target fuzz_verse_packet runs it
// on arbitrary bytes. It never reads past `size`, keeps at most one command
// per 2 bytes after the 4-byte id (the shortest command, connect_terminate
// with an empty text, is `02 00`) and strings no longer than the packet,
// and reports a malformed packet as a ProtocolError naming the byte offset;
// the commands decoded before the error are kept (r6 also acts on them).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "wire_commands.h"
#include "wire_status.h"

namespace vgc::verse {

inline constexpr std::size_t kMaxPacketBytes = 1500;   // r6 V_NOQ_MAX_PACKET_SIZE, id included
inline constexpr std::size_t kDataKeyBytes = 64;       // r6 V_ENCRYPTION_DATA_KEY_SIZE
inline constexpr std::uint32_t kFirstDataPacketId = 2; // ids 0 and 1 belong to the login

using DataKey = std::array<std::uint8_t, kDataKeyBytes>;

struct Packet {
  std::uint32_t id = 0;
  std::vector<WireCommand> commands;
  // Parsed in the other bone_create form than the one asked for (see
  // parse_packet's either_bone_form).
  bool other_bone_form = false;
};

// Parses a decrypted data packet (id, then commands to the end), reading
// bone_create in form `bones`. With either_bone_form, a packet that does not
// parse in that form but parses to its end in the other one is taken in the
// other one (other_bone_form set): a peer of another release desynchronises
// nothing (docs/verse_wire.md section 4). Without it, as r6 does, a packet
// that does not parse keeps the commands before the bad one.
Status parse_packet(const std::uint8_t* data, std::size_t size, Packet* out, BoneForm bones = BoneForm::Spec,
                    bool either_bone_form = false);

// Builds a packet from already encoded commands (encode_command output).
std::string build_packet(std::uint32_t id, const std::string& encoded_commands);

// r6's XOR of bytes 4.. of a packet with the data key, starting at key
// offset key[id % 64]; its own inverse. The id (bytes 0..3) stays clear.
void xor_packet(std::string* packet, const DataKey& key);
void xor_packet(std::uint8_t* data, std::size_t size, const DataKey& key);

}  // namespace vgc::verse
