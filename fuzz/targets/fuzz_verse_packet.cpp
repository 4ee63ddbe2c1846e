// fuzz_verse_packet.cpp — libFuzzer target over the Verse wire parsers a
// client runs on every datagram from a host (docs/verse_wire.md; vgc's
// verse/ layer): parse_packet (a logged-in packet, clear), parse_login_packet
// (the login stages), and Channel::on_datagram (decryption, acks, naks,
// packet ids) with a fixed data key.
//
// Spec: docs/verse_wire.md sections 1-5; docs/fuzzing.md.
//
// It checks, beyond "no crash, no sanitizer report": no more commands come
// out of a packet than its bytes can hold (below); every decoded command
// encodes again and decodes to itself (the codec is stable on whatever it
// accepted); a parse failure is a ProtocolError with a message. Seeds
// (corpora/fuzz/fuzz_verse_packet/) are real packets captured from
// `vgc serve --verse` (tests/verse/session_test.cpp, VGC_CAPTURE_DIR);
// corpora/fuzz/fuzz_verse_packet-crashes/ holds inputs that once stopped it.
//
// How many commands the bytes can hold. After the 4-byte packet id every
// command is its number byte and at least one byte of fields: the shortest
// is connect_terminate with an empty text (command 2, then the string's
// NUL: `02 00`, docs/verse_wire.md section 2; r6 v_unpack_connect_terminate
// reads exactly that string); every other command starts with a uint32
// (5 bytes or more), and an unknown number is an error. So a packet of
// `size` bytes yields at most (size - 4) / 2 commands, whether it parses
// or fails part-way (the commands before the error are kept, as r6 acts on
// them: wire_packet.h). Until issue 22 the bound was one command per
// 5 bytes, true only for commands of 5 bytes or more: the 17-byte packet
// `00 00 02 00` + `02 00` `02 25 3c 00` `02 00` `02 00` `02 00` `02` (five
// connect_terminates, then one cut short) stopped every campaign within
// seconds on a packet the parser reads correctly.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "wire_commands.h"
#include "wire_endpoint.h"
#include "wire_login.h"
#include "wire_packet.h"

namespace {

constexpr std::size_t kPacketIdBytes = 4;
constexpr std::size_t kShortestCommandBytes = 2;  // connect_terminate "": 02 00

// The most commands `size` bytes of packet can hold (see the top comment).
std::size_t most_commands(std::size_t size) {
  return size < kPacketIdBytes ? 0 : (size - kPacketIdBytes) / kShortestCommandBytes;
}

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz_verse_packet: %s\n", what.c_str());
  std::abort();
}

void check_stable(const vgc::verse::WireCommand& c, vgc::verse::BoneForm form) {
  using namespace vgc::verse;
  std::string bytes;
  const Status st = encode_command(c, &bytes, form);
  if (!st.ok()) fail("a decoded command does not encode again: " + describe(c) + ": " + st.detail);
  WireCommand back;
  std::size_t used = 0;
  const Status d =
      decode_command(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), &used, &back, form);
  if (!d.ok() || used != bytes.size()) fail("re-encoded " + describe(c) + " does not decode: " + d.detail);
  std::string again;
  (void)encode_command(back, &again, form);
  if (again != bytes) fail("re-encoded " + describe(c) + " decodes to something else: " + describe(back));
}

// parse_packet in one bone_create configuration: a failure is a
// protocol-error with a message, the bound holds, and every command is
// stable in the form it was read in.
void check_parse(const std::uint8_t* data, std::size_t size, vgc::verse::BoneForm form, bool either) {
  using namespace vgc::verse;
  Packet p;
  const Status st = parse_packet(data, size, &p, form, either);
  if (!st.ok() && (st.code != Status::Code::ProtocolError || st.detail.empty()))
    fail("parse_packet failed without a protocol-error message: " + st.to_string());
  if (p.commands.size() > most_commands(size))
    fail("more commands than the bytes can hold: " + std::to_string(p.commands.size()) + " from " +
         std::to_string(size) + " bytes");
  const BoneForm read_in = !p.other_bone_form ? form : form == BoneForm::Spec ? BoneForm::R6 : BoneForm::Spec;
  for (const WireCommand& c : p.commands) check_stable(c, read_in);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vgc::verse;
  // The spec's bone_create form, and r6's with either form accepted (what
  // a channel to an r6 peer runs, wire_endpoint.h set_bone_form).
  check_parse(data, size, BoneForm::Spec, false);
  check_parse(data, size, BoneForm::R6, true);

  LoginMessage m;
  const Status ls = parse_login_packet(data, size, &m);
  if (!ls.ok() && (ls.code != Status::Code::ProtocolError || ls.detail.empty()))
    fail("parse_login_packet failed without a protocol-error message");

  // The same bytes as an encrypted datagram through a channel's receive path.
  static const DataKey key = [] {
    DataKey k{};
    for (std::size_t i = 0; i < k.size(); ++i) k[i] = static_cast<std::uint8_t>(i * 37 + 11);
    return k;
  }();
  Channel ch(key, 0.25);
  std::vector<WireCommand> got;
  (void)ch.on_datagram(data, size, Clock::now(), &got);
  if (got.size() > most_commands(size))
    fail("the channel delivered more commands than the bytes can hold: " + std::to_string(got.size()) + " from " +
         std::to_string(size) + " bytes");
  (void)ch.take_datagrams(Clock::now());
  return 0;
}
