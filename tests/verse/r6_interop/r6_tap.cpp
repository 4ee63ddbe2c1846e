// r6_tap.cpp — the ld --wrap taps of r6_tap.h on an already-built r6
// libverse.a. Spec: docs/verse_wire.md section 12.
#include "r6_tap.h"

#include <array>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <utility>

// r6's own functions, declared here with the signatures of its sources
// (v_func_storage.c, v_network.c, v_network_out_que.c, v_encryption.c,
// v_connection.c); they are linked from the user's libverse.a.
extern "C" {
typedef unsigned int (*R6Unpack)(const char* data, std::size_t length);
struct R6Address { unsigned int ip; unsigned short port; };
void __real_v_fs_add_func(unsigned int cmd_id, R6Unpack unpack_func, void* pack_func, void* alias_func);
void __real_v_fs_unpack(std::uint8_t* data, unsigned int length);
void __real_v_fs_unpack_beginning(const std::uint8_t* data, unsigned int length);
void __real_callback_send_packet_ack(void* user, std::uint32_t packet_id);
void __real_callback_send_packet_nak(void* user, std::uint32_t packet_id);
int __real_v_n_receive_data(R6Address* address, char* data, std::size_t length);
int __real_v_n_send_data(R6Address* address, const char* data, std::size_t length);
void v_e_data_decrypt_packet(std::uint8_t* to, const std::uint8_t* from, std::size_t size, const std::uint8_t* key);
const std::uint8_t* v_con_get_data_key(void);

void __wrap_v_fs_add_func(unsigned int cmd_id, R6Unpack unpack_func, void* pack_func, void* alias_func);
void __wrap_v_fs_unpack(std::uint8_t* data, unsigned int length);
void __wrap_v_fs_unpack_beginning(const std::uint8_t* data, unsigned int length);
void __wrap_callback_send_packet_ack(void* user, std::uint32_t packet_id);
void __wrap_callback_send_packet_nak(void* user, std::uint32_t packet_id);
int __wrap_v_n_receive_data(R6Address* address, char* data, std::size_t length);
int __wrap_v_n_send_data(R6Address* address, const char* data, std::size_t length);
}

namespace r6tap {
namespace {

constexpr std::size_t kKeyBytes = 64;  // r6 V_ENCRYPTION_DATA_KEY_SIZE

struct TapState {
  std::vector<PacketRecord> packets;
  std::map<std::pair<char, std::uint32_t>, std::size_t> index;  // (dir, id) -> packets[]
  std::string key;
  PacketRecord* current = nullptr;  // the packet r6 is decoding now
  bool decode_only = false;
  R6Unpack unpackers[256] = {};
  std::uint32_t last_command_packet = 0;
  std::set<std::uint32_t> acked;
};

TapState& tap() {
  static TapState s;
  return s;
}

std::uint32_t packet_id(const std::uint8_t* d) {
  return (std::uint32_t(d[0]) << 24) | (std::uint32_t(d[1]) << 16) | (std::uint32_t(d[2]) << 8) | d[3];
}

// The record of (dir, id); a new one when `create`, else nullptr if none.
PacketRecord* find(char dir, std::uint32_t id, bool create) {
  TapState& s = tap();
  auto it = s.index.find({dir, id});
  if (it != s.index.end()) return &s.packets[it->second];
  if (!create) return nullptr;
  s.index[{dir, id}] = s.packets.size();
  s.packets.push_back(PacketRecord{});
  s.packets.back().dir = dir;
  s.packets.back().id = id;
  return &s.packets.back();
}

// The unpacker r6 registered for command N, reached through a trampoline
// that records the command and how many bytes r6's unpacker consumed.
unsigned int run_unpacker(unsigned int number, const char* data, std::size_t length) {
  TapState& s = tap();
  if (s.current != nullptr) s.current->cmds.push_back(Cmd{number, 0, ""});
  std::size_t at = s.current != nullptr ? s.current->cmds.size() - 1 : 0;
  PacketRecord* rec = s.current;
  unsigned int used = s.unpackers[number](data, length);
  if (rec != nullptr) rec->cmds[at].length = used;
  return used;
}

template <unsigned N>
unsigned int trampoline(const char* data, std::size_t length) {
  return run_unpacker(N, data, length);
}

template <std::size_t... I>
constexpr std::array<R6Unpack, sizeof...(I)> make_trampolines(std::index_sequence<I...>) {
  return {&trampoline<I>...};
}

const std::array<R6Unpack, 256> kTrampolines = make_trampolines(std::make_index_sequence<256>{});

// Decodes a packet r6 is about to send with r6's own unpacker (decode-only).
void decode_sent(const char* data, std::size_t length) {
  TapState& s = tap();
  if (length < 4 || s.key.size() != kKeyBytes) return;
  std::uint32_t id = packet_id(reinterpret_cast<const std::uint8_t*>(data));
  if (id < 2) return;  // login packets
  PacketRecord* rec = find('s', id, true);
  if (rec->unpacked) return;  // a resend of the same packet
  rec->raw.assign(data, length);
  std::string plain(length, '\0');
  v_e_data_decrypt_packet(reinterpret_cast<std::uint8_t*>(&plain[0]),
                          reinterpret_cast<const std::uint8_t*>(data), length,
                          reinterpret_cast<const std::uint8_t*>(s.key.data()));
  rec->plain = plain;
  rec->unpacked = true;
  PacketRecord* saved = s.current;
  bool saved_mode = s.decode_only;
  s.decode_only = true;
  s.current = rec;
  __real_v_fs_unpack_beginning(reinterpret_cast<const std::uint8_t*>(plain.data()), length);
  // v_fs_unpack may write nothing, but takes a non-const pointer.
  std::string copy = plain;
  __real_v_fs_unpack(reinterpret_cast<std::uint8_t*>(&copy[0]), length);
  s.current = saved;
  s.decode_only = saved_mode;
  for (const Cmd& c : rec->cmds)
    if (c.number != 7 && c.number != 8) s.last_command_packet = id;
}

}  // namespace

const std::vector<PacketRecord>& records() { return tap().packets; }
std::uint32_t last_command_packet() { return tap().last_command_packet; }
bool acknowledged(std::uint32_t id) { return tap().acked.count(id) != 0; }
void forget() {
  TapState& s = tap();
  s.packets.clear();
  s.index.clear();
  s.acked.clear();
  s.current = nullptr;
}

std::string data_key() {
  TapState& s = tap();
  if (s.key.empty()) {
    const std::uint8_t* k = v_con_get_data_key();
    if (k != nullptr) s.key.assign(reinterpret_cast<const char*>(k), kKeyBytes);
  }
  return s.key;
}

void note_decoded(const std::string& text) {
  TapState& s = tap();
  if (s.current == nullptr || s.current->cmds.empty()) return;
  Cmd& c = s.current->cmds.back();
  c.decoded += c.decoded.empty() ? text : " | " + text;
}

bool decode_only() { return tap().decode_only; }

std::string str(const char* s) {
  std::string out;
  if (s == nullptr) return "\\null";
  for (const unsigned char* p = reinterpret_cast<const unsigned char*>(s); *p != 0; ++p) {
    if (*p > 0x20 && *p < 0x7f && *p != '\\') {
      out += static_cast<char>(*p);
    } else {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02x", *p);
      out += b;
    }
  }
  return out.empty() ? "\\empty" : out;
}

}  // namespace r6tap

using r6tap::tap;

extern "C" void __wrap_v_fs_add_func(unsigned int cmd_id, R6Unpack unpack_func, void* pack_func,
                                     void* alias_func) {
  if (cmd_id < 256 && unpack_func != nullptr) {
    r6tap::tap().unpackers[cmd_id] = unpack_func;
    unpack_func = r6tap::kTrampolines[cmd_id];
  }
  __real_v_fs_add_func(cmd_id, unpack_func, pack_func, alias_func);
}

extern "C" void __wrap_v_fs_unpack_beginning(const std::uint8_t* data, unsigned int length) {
  auto& s = r6tap::tap();
  if (s.decode_only || length < 4) {  // decode_sent() sets the record itself
    __real_v_fs_unpack_beginning(data, length);
    return;
  }
  r6tap::PacketRecord* rec = r6tap::find('r', r6tap::packet_id(data), true);
  rec->plain.assign(reinterpret_cast<const char*>(data), length);
  r6tap::PacketRecord* saved = s.current;
  s.current = rec;
  __real_v_fs_unpack_beginning(data, length);
  s.current = saved;
}

extern "C" void __wrap_v_fs_unpack(std::uint8_t* data, unsigned int length) {
  auto& s = r6tap::tap();
  if (s.decode_only || length < 4) {
    __real_v_fs_unpack(data, length);
    return;
  }
  r6tap::PacketRecord* rec = r6tap::find('r', r6tap::packet_id(data), true);
  rec->unpacked = true;
  r6tap::PacketRecord* saved = s.current;
  s.current = rec;
  __real_v_fs_unpack(data, length);
  s.current = saved;
}

static void note_ack_nak(unsigned number, std::uint32_t id) {
  auto& s = r6tap::tap();
  if (s.current == nullptr) return;
  // Leading acks/naks are read by v_fs_unpack_beginning without an
  // unpacker; one in the middle goes through the trampoline, which already
  // opened a command for it.
  bool opened = !s.current->cmds.empty() && s.current->cmds.back().number == number &&
                s.current->cmds.back().decoded.empty();
  if (!opened) s.current->cmds.push_back(r6tap::Cmd{number, 4, ""});
  r6tap::note_decoded(std::string(number == 7 ? "packet_ack" : "packet_nak") + " id=" + std::to_string(id));
}

extern "C" void __wrap_callback_send_packet_ack(void* user, std::uint32_t packet_id) {
  note_ack_nak(7, packet_id);
  if (!r6tap::tap().decode_only) r6tap::tap().acked.insert(packet_id);
  if (!r6tap::tap().decode_only) __real_callback_send_packet_ack(user, packet_id);
}

extern "C" void __wrap_callback_send_packet_nak(void* user, std::uint32_t packet_id) {
  note_ack_nak(8, packet_id);
  if (!r6tap::tap().decode_only) __real_callback_send_packet_nak(user, packet_id);
}

extern "C" int __wrap_v_n_receive_data(R6Address* address, char* data, std::size_t length) {
  int n = __real_v_n_receive_data(address, data, length);
  auto& s = r6tap::tap();
  if (n >= 4 && s.key.size() == r6tap::kKeyBytes) {
    std::uint32_t id = r6tap::packet_id(reinterpret_cast<const std::uint8_t*>(data));
    if (id >= 2) {
      r6tap::PacketRecord* rec = r6tap::find('r', id, true);
      if (rec->raw.empty()) rec->raw.assign(data, static_cast<std::size_t>(n));
    }
  }
  return n;
}

extern "C" int __wrap_v_n_send_data(R6Address* address, const char* data, std::size_t length) {
  r6tap::decode_sent(data, length);
  return __real_v_n_send_data(address, data, length);
}
