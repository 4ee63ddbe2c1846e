// r6_tap.h — our own taps on an already-built r6 libverse.a: every data
// packet r6's client library sends or receives, with the data key, and what
// r6's own unpackers decoded from it (the callback arguments), as text.
//
// Spec: docs/verse_wire.md section 12 ("Interop with r6's client library":
// the transcript format, how the taps work).
//
// Rationale: r6 is linked, never copied. The taps are GNU ld --wrap
// wrappers (the link flags are in tests/verse/r6_interop/CMakeLists.txt and
// record.sh) around r6 functions that one r6 object file calls in another:
// v_fs_add_func (so each command's unpacker is reached through a trampoline
// that records the command number and the bytes r6's unpacker consumed),
// v_fs_unpack / v_fs_unpack_beginning (the decrypted packet r6 decodes),
// callback_send_packet_ack/nak, v_n_receive_data / v_n_send_data (the raw
// datagrams). A packet r6 *sends* is decoded by r6's own unpacker too
// (decode-only: the callbacks record and do nothing else), so the
// transcript says, for both directions, what r6 reads from those bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "../transcript_values.h"

namespace r6tap {

struct Cmd {
  unsigned number = 0;     // command byte
  unsigned length = 0;     // bytes r6's unpacker consumed after the command byte
  std::string decoded;     // the callback r6 called, with its arguments; "" when none
};

struct PacketRecord {
  char dir = 'r';          // 'r' received by r6's library, 's' sent by it
  std::uint32_t id = 0;
  std::string raw;         // the datagram as on the wire (encrypted)
  std::string plain;       // after r6's decryption
  std::vector<Cmd> cmds;   // what r6's unpackers made of `plain`, in order
  bool unpacked = false;
};

// Everything recorded so far, in the order the packets were first seen.
const std::vector<PacketRecord>& records();
// The data key of the session (64 bytes), empty before the accept.
std::string data_key();
// The id of the last data packet r6's library sent that held more than
// acks and naks (0: none yet), and whether the peer acknowledged an id.
std::uint32_t last_command_packet();
bool acknowledged(std::uint32_t id);
// Drops the records and acks kept so far (a long-running program calls it
// between sessions' steps, outside any callback).
void forget();
// Called by the program's callbacks: appends one decoded command text to the
// command r6's unpacker is running now (ignored outside an unpack).
void note_decoded(const std::string& text);
// True while r6 decodes a packet the library sent (callbacks must only record).
bool decode_only();
// Text helpers shared by the callbacks: "%.9g" for real32, "%.17g" for
// real64, strings with bytes outside 0x21..0x7e (and '\\') as \xNN.
using vgc_transcript::r32;  // the transcript's way of writing reals (../transcript_values.h)
using vgc_transcript::r64;
std::string str(const char* s);
using vgc_transcript::hex;

}  // namespace r6tap
