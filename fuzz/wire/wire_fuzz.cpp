// wire_fuzz.cpp — see wire_fuzz.h.
#include "wire_fuzz.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <thread>

#include "check_step.h"
#include "clause.h"
#include "coverage_record.h"
#include "coverage_region.h"
#include "launched_host.h"
#include "command_text.h"
#include "display_text.h"
#include "exec_implementation.h"
#include "document_diff.h"
#include "forwarding_implementation.h"
#include "snapshot.h"
#include "live_implementation.h"
#include "restartable_host.h"
#include "node.h"
#include "verse_client.h"
#include "verse_implementation.h"
#include "wire_commands.h"
#include "wire_packet.h"

#include "campaign.h"

namespace vgc::fuzz {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// ---- bodies: hex pairs and {node} tokens ----

std::string hex_of(const std::string& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (unsigned char b : bytes) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out;
}

constexpr const char* kNodeToken = "{node}";

// A command for our node as a body: its number, {node}, the rest. The node
// id is the 4 bytes after the number in every command addressed to a node
// (docs/verse_wire.md sections 3-4).
std::string node_command_body(const verse::WireCommand& c) {
  std::string bytes;
  if (!verse::encode_command(c, &bytes).ok() || bytes.size() < 5) return {};
  return hex_of(bytes.substr(0, 1)) + kNodeToken + hex_of(bytes.substr(5));
}

std::string geometry_body(const Command& c) { return node_command_body(verse::wire::Geometry{0, c}); }

// A body's length in bytes.
std::size_t body_size(const std::string& body) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < body.size();) {
    if (body.compare(i, 6, kNodeToken) == 0) {
      n += 4;
      i += 6;
    } else {
      n += 1;
      i += 2;
    }
  }
  return n;
}

// What is wrong with a body read from a transcript, with the 1-based
// column (within the body) where it goes wrong; nullopt for a body of
// hex byte pairs and {node} tokens.
std::optional<std::pair<std::size_t, std::string>> body_error(std::string_view body) {
  auto is_hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
  for (std::size_t i = 0; i < body.size();) {
    if (body.compare(i, 6, kNodeToken) == 0) {
      i += 6;
    } else if (!is_hex(body[i])) {
      return std::pair{i + 1, fmt::format("'{}' is not a hex digit (a body is hex byte pairs and {})",
                                          escape_unprintable(body.substr(i, 1)), kNodeToken)};
    } else if (i + 1 >= body.size() || !is_hex(body[i + 1])) {
      return std::pair{i + 1, std::string("half a byte: hex digits come in pairs")};
    } else {
      i += 2;
    }
  }
  return std::nullopt;
}

// The first `k` bytes of a body (a {node} cut in the middle becomes zeros).
std::string body_prefix(const std::string& body, std::size_t k) {
  std::string out;
  std::size_t n = 0;
  for (std::size_t i = 0; i < body.size() && n < k;) {
    if (body.compare(i, 6, kNodeToken) == 0) {
      if (k - n >= 4) out += kNodeToken;
      else out += std::string(2 * (k - n), '0');
      n += std::min<std::size_t>(4, k - n);
      i += 6;
    } else {
      out += body.substr(i, 2);
      ++n;
      i += 2;
    }
  }
  return out;
}

WireDatagram data_packet(std::int64_t offset, std::string body, std::vector<Command> applies = {}) {
  WireDatagram g;
  g.offset = offset;
  g.body = std::move(body);
  g.applies = std::move(applies);
  return g;
}

WireDatagram raw_packet(std::string bytes) {
  WireDatagram g;
  g.raw = true;
  g.body = std::move(bytes);
  return g;
}

// ---- the input generator ----

class Draw {
 public:
  Draw(std::uint64_t seed, std::uint64_t index) : rng_(seed * 0x9E3779B97F4A7C15ull ^ (index + 1) * 0xBF58476D1CE4E5B9ull) {}
  std::uint64_t below(std::uint64_t n) { return n == 0 ? 0 : rng_() % n; }
  bool coin() { return below(2) == 0; }
  std::string bytes(std::size_t n) {
    std::string out(n, '\0');
    for (char& c : out) c = static_cast<char>(below(256));
    return out;
  }
  template <class T>
  const T& pick(const std::vector<T>& v) { return v[below(v.size())]; }

 private:
  std::mt19937_64 rng_;
};

// Ids at every magnitude (docs/verse_wire.md: u16 layer and bone ids, u32
// node, vertex, polygon and packet ids).
const std::vector<std::uint32_t>& magnitudes32() {
  static const std::vector<std::uint32_t> v = {0u, 1u, 2u, 0x7Fu, 0xFFu, 0x100u, 0x1004u, 0x1005u, 0x7FFFu,
                                               0xFFFFu, 0x10000u, 0xFFFFFFu, 0x1000000u, 0x7FFFFFFFu,
                                               0x80000000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
  return v;
}

// A command that changes nothing whether a host acts on it or not: a
// vertex write on a layer no input creates (rejected: NO_SUCH_LAYER).
Command no_op() { return cmd::VertexSetXyzReal64{0x7777, 0, 1, 2, 3}; }

// A well-formed vertex write on layer 0 that a conforming host applies:
// vertex ids 3..99 (the base program holds 0..2, the probes 100..163).
Command vertex_write(Draw& d) {
  static const std::vector<double> values = {0.0, 1.0, -1.0, 0.5, -0.0, 1e-300, 1e300, 123.25};
  cmd::VertexSetXyzReal64 v;
  v.layer_id = 0;
  v.vertex_id = static_cast<std::uint32_t>(3 + d.below(97));
  v.x = d.pick(values);
  v.y = d.pick(values);
  v.z = static_cast<double>(d.below(1000)) / 8;
  return v;
}

// Any command a client might send, for truncation and padding.
Command some_command(Draw& d) {
  switch (d.below(4)) {
    case 0: {
      cmd::LayerCreate l;
      l.layer_id = static_cast<std::uint16_t>(d.below(8));
      l.name = "wire_" + std::to_string(d.below(100));
      l.type = static_cast<std::uint8_t>(d.below(6));
      return l;
    }
    case 1: {
      cmd::PolygonSetCornerUint32 p;
      p.layer_id = 1;
      p.polygon_id = static_cast<std::uint32_t>(d.below(50));
      p.v = {0, 1, 2, 0xFFFFFFFFu};
      return p;
    }
    case 2: {
      cmd::BoneCreate b;
      b.bone_id = static_cast<std::uint16_t>(d.below(8));
      b.weight = "w";
      b.parent = 0xFFFF;
      b.rot = {0, 0, 0, 1};
      return b;
    }
    default: return vertex_write(d);
  }
}

WireInput truncated(Draw& d) {
  WireInput in;
  in.kind = "truncated";
  const std::string body = geometry_body(some_command(d));
  const std::size_t size = body_size(body);
  const std::size_t k = 1 + d.below(std::max<std::size_t>(1, size - 1));
  in.what = fmt::format("a {}-byte command cut after {} bytes", size, k);
  in.ids = 1;
  in.datagrams.push_back(data_packet(0, body_prefix(body, k)));
  return in;
}

WireInput over_long(Draw& d) {
  WireInput in;
  in.kind = "over-long";
  // Junk after a command: up to and past r6's 1500-byte receive buffer.
  static const std::vector<std::size_t> lengths = {1, 100, 1300, 1392, 1496, 1600, 4000, 9000};
  const std::size_t n = d.pick(lengths);
  Command c = vertex_write(d);
  std::vector<Command> applies;
  if (4 + body_size(geometry_body(c)) + n <= 1500) {
    applies.push_back(c);  // what comes before the junk is acted on (docs/verse_wire.md section 8)
  } else {
    // Past 1500 bytes a host may drop the datagram whole (vgc's does) or read
    // its first 1500 bytes (r6's buffer): the command is one that changes
    // nothing either way.
    c = no_op();
  }
  std::string junk = d.bytes(n);
  // The junk starts with an unknown command number, so nothing of it is a
  // command a host could act on.
  junk[0] = static_cast<char>(0x41 + d.below(0xBE));  // 65..254: beyond the geometry commands
  in.what = fmt::format("a vertex write followed by {} bytes of junk (packet of {} bytes)", n,
                        4 + body_size(geometry_body(c)) + n);
  in.ids = 1;
  in.datagrams.push_back(data_packet(0, geometry_body(c) + hex_of(junk), applies));
  return in;
}

WireInput unknown_command(Draw& d) {
  WireInput in;
  in.kind = "unknown-command";
  static const std::vector<std::uint8_t> unknown = {3, 4, 5, 6, 12, 13, 14, 15, 17, 18, 20, 32, 47, 65, 66, 128, 200, 255};
  const std::uint8_t number = d.pick(unknown);
  const std::string tail = d.bytes(d.below(64));
  in.what = fmt::format("command number {} and {} bytes", number, tail.size());
  in.ids = 1;
  in.datagrams.push_back(data_packet(0, hex_of(std::string(1, static_cast<char>(number))) + hex_of(tail)));
  return in;
}

WireInput long_string(Draw& d) {
  WireInput in;
  in.kind = "long-string";
  in.ids = 1;
  switch (d.below(4)) {
    case 0: {  // node_name_set with a name far past r6's 16 bytes; no NUL at all when cut at the end
      const std::size_t n = 600 + d.below(500);
      const bool terminated = d.coin();
      in.what = fmt::format("node_name_set of {} bytes, {}", n, terminated ? "NUL-terminated" : "with no NUL");
      std::string body = node_command_body(verse::wire::NodeNameSet{0, "x"});
      body = body_prefix(body, body_size(body) - 2) + hex_of(std::string(n, 'n')) + (terminated ? "00" : "");
      in.datagrams.push_back(data_packet(0, body));
      break;
    }
    case 1: {  // layer_create with a name over 15 bytes: the spec rejects it (LAYER-NAME-1)
      cmd::LayerCreate l;
      l.layer_id = static_cast<std::uint16_t>(2 + d.below(4));
      l.name = std::string(16 + d.below(48), 'L');
      l.type = 2;
      in.what = fmt::format("layer_create {} with a {}-byte name", l.layer_id, l.name.size());
      in.datagrams.push_back(data_packet(0, geometry_body(l), {l}));
      break;
    }
    case 2: {  // a string running to the end of the packet
      cmd::LayerCreate l;
      l.layer_id = 2;
      l.name = "unterminated";
      std::string body = geometry_body(l);
      // Its number, the node id, the layer id (7 bytes), then the name's bytes: the packet ends there.
      const std::size_t cut = 7 + l.name.size();
      in.what = "layer_create whose name has no NUL before the packet ends";
      in.datagrams.push_back(data_packet(0, body_prefix(body, cut)));
      break;
    }
    default: {  // connect_terminate with a text far past its 512 bytes
      const std::size_t n = 513 + d.below(800);
      in.what = fmt::format("connect_terminate with a {}-byte text, no NUL", n);
      in.datagrams.push_back(data_packet(0, "02" + hex_of(std::string(n, 't'))));
      break;
    }
  }
  return in;
}

WireInput id_magnitude(Draw& d) {
  WireInput in;
  in.kind = "id-magnitude";
  in.ids = 1;
  const std::uint32_t id = d.pick(magnitudes32());
  switch (d.below(4)) {
    case 0: {  // a geometry command to a node id of every magnitude
      // A command that changes nothing, should the id be our node's (node
      // ids are the host's to pick).
      const Command v = no_op();
      std::string bytes;
      (void)verse::encode_command(verse::wire::Geometry{id, v}, &bytes);
      in.what = fmt::format("vertex_set_xyz_real64 on node {:#x}", id);
      in.datagrams.push_back(data_packet(0, hex_of(bytes)));
      in.kind = "id-magnitude-node";
      break;
    }
    case 1: {  // a vertex id on our node, applied as the spec says
      cmd::VertexSetXyzReal64 v;
      v.vertex_id = id;
      v.x = 2;
      v.y = 3;
      in.what = fmt::format("vertex_set_xyz_real64 0 {:#x} on our node", id);
      in.datagrams.push_back(data_packet(0, geometry_body(v), {v}));
      break;
    }
    case 2: {  // a layer id on our node that does not exist (rejected: nothing changes)
      cmd::VertexSetXyzReal64 v;
      v.layer_id = static_cast<std::uint16_t>(std::max<std::uint32_t>(2, id & 0xFFFF));
      v.vertex_id = 7;
      in.what = fmt::format("vertex_set_xyz_real64 on layer {:#x} of our node", v.layer_id);
      in.datagrams.push_back(data_packet(0, geometry_body(v), {v}));
      break;
    }
    default: {  // a packet id far from the session's (earlier: dropped; later: a gap)
      // Acted on or not, nothing changes.
      const Command c = no_op();
      static const std::vector<std::int64_t> offsets = {-1, -2, -1000, 2, 1000, 1025, 1 << 20};
      const std::int64_t off = d.pick(offsets);
      in.ids = 0;  // takes no id in order: the session's next id is untouched
      in.what = fmt::format("a vertex write under packet id next{:+d} (out of the session's order)", off);
      in.datagrams.push_back(data_packet(off, geometry_body(c)));
      in.kind = "packet-id";
      // Not applied: an earlier id is a duplicate; a later one leaves a gap
      // the session does not fill in order (a host may act on it or wait:
      // not judged), and the session is logged in again after it.
      break;
    }
  }
  return in;
}

WireInput packet_order(Draw& d) {
  WireInput in;
  in.kind = "packet-order";
  const std::uint32_t n = static_cast<std::uint32_t>(2 + d.below(4));
  in.ids = n;
  std::vector<std::string> bodies;
  std::vector<Command> commands;
  for (std::uint32_t i = 0; i < n; ++i) {
    Command c = vertex_write(d);
    auto& v = std::get<cmd::VertexSetXyzReal64>(c);
    v.vertex_id = 3 + i * 20 + static_cast<std::uint32_t>(d.below(20));
    commands.push_back(c);
    bodies.push_back(geometry_body(c));
  }
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
  for (std::uint32_t i = n - 1; i > 0; --i) std::swap(order[i], order[d.below(i + 1)]);
  const bool duplicate = d.coin();
  for (std::uint32_t k : order) {
    in.datagrams.push_back(data_packet(k, bodies[k], {commands[k]}));
    if (duplicate && d.coin()) in.datagrams.push_back(data_packet(k, bodies[k], {commands[k]}));  // resent, same bytes
  }
  if (d.coin()) {  // an id already sent, with other bytes: a duplicate, not acted on
    cmd::VertexSetXyzReal64 v;
    v.vertex_id = 1;
    v.x = 99;
    in.datagrams.push_back(data_packet(order[0], geometry_body(v), {v}));
  }
  std::string shown;
  for (const WireDatagram& g : in.datagrams) shown += (shown.empty() ? "" : ",") + std::to_string(g.offset);
  in.what = fmt::format("{} vertex writes in packets sent in the order {}{}", n, shown,
                        duplicate ? " (some resent)" : "");
  return in;
}

WireInput burst(Draw& d) {
  WireInput in;
  in.kind = "burst";
  const std::size_t n = 50 + d.below(250);
  if (d.coin()) {  // reliable: through the session's channel, packed as a client flushes
    for (std::size_t i = 0; i < n; ++i) {
      const Command c = vertex_write(d);
      in.reliable.push_back(c);
    }
    in.what = fmt::format("a burst of {} vertex writes in as few packets as they fit", n);
  } else {  // junk datagrams as fast as they go (unknown command numbers: nothing to apply)
    in.ids = static_cast<std::uint32_t>(n);
    for (std::uint32_t i = 0; i < n; ++i)
      in.datagrams.push_back(data_packet(i, hex_of(std::string(1, static_cast<char>(0xF0 + d.below(15)))) +
                                            hex_of(d.bytes(d.below(200)))));
    in.what = fmt::format("a burst of {} junk packets in order", n);
  }
  return in;
}

WireInput raw_datagram(Draw& d) {
  WireInput in;
  in.kind = "raw-datagram";
  switch (d.below(3)) {
    case 0:
      in.what = "a login-stage packet (id 0, stage 0) in the middle of a session";
      in.datagrams.push_back(raw_packet("00000000" "0000" + hex_of(d.bytes(d.below(140)))));
      break;
    case 1:
      in.what = "a datagram shorter than a packet id";
      in.datagrams.push_back(raw_packet(hex_of(d.bytes(d.below(4)))));
      break;
    default:
      in.what = "a datagram past 1500 bytes";
      in.datagrams.push_back(raw_packet(hex_of(d.bytes(1501 + d.below(3000)))));
      break;
  }
  return in;
}

// ---- the queue: inputs made from inputs that reached new code of the host ----

// Whether an input can be placed before or after another: it takes its
// packet ids in the session's order (a packet-id input is placed relative
// to the session's next id alone, and logs in again after it).
bool combinable(const WireInput& in) {
  bool data = false;
  for (const WireDatagram& g : in.datagrams) data = data || !g.raw;
  return in.ids > 0 || !data;
}

// Whether a conforming host applies no command from the input.
bool applies_nothing(const WireInput& in) {
  if (!in.reliable.empty()) return false;
  for (const WireDatagram& g : in.datagrams)
    if (!g.applies.empty()) return false;
  return true;
}

// `a`'s datagrams, then `b`'s (its ids after a's). `b` applies nothing, so
// whatever a's garbage did to the session, the model stays exact.
WireInput followed_by(const WireInput& a, const WireInput& b) {
  WireInput out = a;
  out.kind = a.kind + "+" + b.kind;
  out.what = a.what + "; then " + b.what;
  out.ids = a.ids + b.ids;
  for (WireDatagram g : b.datagrams) {
    if (!g.raw) g.offset += a.ids;
    out.datagrams.push_back(std::move(g));
  }
  return out;
}

// A combination stays an input of a few packets.
constexpr std::size_t kMaxCombinedDatagrams = 400;

// The input `index` of a guided campaign: every other one drawn afresh
// (make_wire_input), the others made from the queue: a queued input with a
// fresh one or with another queued one, in the order that keeps the model
// exact (the one a conforming host applies commands from first; when both
// apply commands, a fresh input that applies none is drawn to follow).
// Deterministic given the seed, the index and the queue.
WireInput next_wire_input(std::uint64_t seed, std::uint64_t index, const std::vector<WireInput>& queue,
                          bool* from_queue) {
  *from_queue = false;
  WireInput fresh = make_wire_input(seed, index);
  if (queue.empty()) return fresh;
  Draw d(seed ^ 0x51AFD7ED558CCD1Dull, index);
  if (d.coin()) return fresh;
  const WireInput& a = queue[d.below(queue.size())];
  const WireInput& b = d.coin() ? fresh : queue[d.below(queue.size())];
  const WireInput* first = nullptr;
  const WireInput* second = nullptr;
  WireInput garbage;
  if (applies_nothing(a)) {
    first = &b, second = &a;
  } else if (applies_nothing(b)) {
    first = &a, second = &b;
  } else {
    for (std::uint64_t k = 0; k < 8 && !second; ++k) {
      garbage = make_wire_input(seed ^ 0x2545F4914F6CDD1Dull, index * 8 + k);
      if (applies_nothing(garbage) && combinable(garbage)) first = &a, second = &garbage;
    }
  }
  if (!first || !combinable(*first) || !combinable(*second) ||
      first->datagrams.size() + second->datagrams.size() > kMaxCombinedDatagrams)
    return fresh;
  *from_queue = true;
  return followed_by(*first, *second);
}

// ---- transcripts ----

std::string transcript_text(const WireInput& in, const std::string& header) {
  std::string out = header;
  out += "input " + in.kind + ": " + in.what + "\n";
  out += "ids " + std::to_string(in.ids) + "\n";
  for (const Command& c : in.reliable) out += "reliable " + print_command(c) + "\n";
  for (const WireDatagram& g : in.datagrams) {
    out += g.raw ? "datagram " + g.body + "\n" : fmt::format("packet {} {}\n", g.offset, g.body);
    for (const Command& c : g.applies) out += "applies " + print_command(c) + "\n";
  }
  return out;
}

bool parse_transcript(const std::string& text, WireInput* in, std::string* error) {
  std::istringstream lines(text);
  std::string line;
  int n = 0;
  auto command = [&](const std::string& s, std::vector<Command>* out) {
    std::vector<Command> cs;
    TextError e;
    if (!parse_commands(s + "\n", &cs, &e) || cs.size() != 1) {
      *error = fmt::format("line {}: not a command: {} ({})", n, escape_unprintable(s), escape_unprintable(e.message));
      return false;
    }
    out->push_back(cs[0]);
    return true;
  };
  while (std::getline(lines, line)) {
    ++n;
    if (line.empty() || line[0] == '#') continue;
    const auto sp = line.find(' ');
    const std::string key = line.substr(0, sp), rest = sp == std::string::npos ? "" : line.substr(sp + 1);
    if (key == "input") {
      in->kind = rest.substr(0, rest.find(':'));
      in->what = rest.find(": ") == std::string::npos ? "" : rest.substr(rest.find(": ") + 2);
    } else if (key == "ids") {
      const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), in->ids);
      if (rest.empty() || ec != std::errc() || end != rest.data() + rest.size()) {
        *error = fmt::format("line {}, column {}: expected ids N, a whole number below 2^32, got '{}'", n,
                             key.size() + 2, escape_unprintable(rest));
        return false;
      }
    } else if (key == "reliable") {
      if (!command(rest, &in->reliable)) return false;
    } else if (key == "applies") {  // what the packet before it does to a conforming host's node
      if (in->datagrams.empty() || in->datagrams.back().raw) {
        *error = fmt::format("line {}: 'applies' follows a packet line", n);
        return false;
      }
      if (!command(rest, &in->datagrams.back().applies)) return false;
    } else if (key == "datagram") {
      if (const auto bad = body_error(rest)) {
        *error = fmt::format("line {}, column {}: {}", n, key.size() + 1 + bad->first, bad->second);
        return false;
      }
      in->datagrams.push_back(raw_packet(rest));
    } else if (key == "packet") {
      const auto sp2 = rest.find(' ');
      std::int64_t off = 0;
      const char* last = rest.data() + (sp2 == std::string::npos ? rest.size() : sp2);
      const auto [end, ec] = std::from_chars(rest.data(), last, off);
      if (sp2 == std::string::npos || ec != std::errc() || end != last) {
        *error = fmt::format("line {}, column {}: expected packet OFFSET BODY, OFFSET a whole number of 64 bits", n,
                             key.size() + 2);
        return false;
      }
      if (const auto bad = body_error(std::string_view(rest).substr(sp2 + 1))) {
        *error = fmt::format("line {}, column {}: {}", n, key.size() + 1 + sp2 + 1 + bad->first, bad->second);
        return false;
      }
      in->datagrams.push_back(data_packet(off, rest.substr(sp2 + 1)));
    } else {
      *error = fmt::format("line {}, column 1: unknown line '{}' (input, ids, reliable, packet, datagram, applies)", n,
                           escape_unprintable(key));
      return false;
    }
  }
  if (in->kind.empty()) {
    *error = "no 'input' line: not a vgc fuzz wire transcript";
    return false;
  }
  return true;
}

// ---- running inputs against a host ----

// The base program: the node holds something before the hostile inputs.
std::vector<Command> base_program() {
  std::vector<Command> cs;
  TextError e;
  parse_commands(
      "vertex_set_xyz_real64 0 0 0 0 0\nvertex_set_xyz_real64 0 1 1 0 0\nvertex_set_xyz_real64 0 2 0 1 0\n"
      "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF\n",
      &cs, &e);
  return cs;
}

// One probe after every input: it needs the host to answer (the adapter's
// barrier) and shows the whole node (check_step's snapshot).
Command probe(std::uint64_t index) {
  cmd::VertexSetXyzReal64 v;
  v.vertex_id = static_cast<std::uint32_t>(100 + index % 64);
  v.x = static_cast<double>(index % 1000);
  v.y = 0.25;
  return v;
}

struct Session {
  std::unique_ptr<Implementation> owner;
  VerseImplementation* sut = nullptr;
  std::unique_ptr<verse::ClientSession> hostile;
  Node model;
  std::string host;
  std::uint16_t port = 0;
  std::string login;
  std::size_t hostile_logins = 0;
};

// A login's limit. The campaign bounds a login by --timeout (a host that
// died is found within it, not after certify's start limit); `vgc replay
// --wire` gives its --start-timeout, as replay of a command file does.
double login_limit(const WireFuzzOptions& o) { return o.login_timeout_s > 0 ? o.login_timeout_s : o.timeout_s; }

OpenOptions open_options(const WireFuzzOptions& o) {
  OpenOptions op;
  op.timeout_seconds = o.timeout_s;
  op.start_timeout_seconds = login_limit(o);
  if (!o.verse_bone_form.empty()) op.verse_bone_form = o.verse_bone_form;
  return op;
}

// The hostile session: a normal login, subscribed to the node (for its
// own barrier, which says the session is still known to the host).
bool login_hostile(Session* s, const WireFuzzOptions& o, std::string* why) {
  if (s->hostile) s->hostile->disconnect("");
  s->hostile = std::make_unique<verse::ClientSession>();
  verse::ClientOptions co;
  co.name = "vgc-wire";
  if (const char* pw = std::getenv("VERSE_PASSWORD")) co.password = pw;
  co.login_timeout_s = login_limit(o);
  co.bone_form = s->sut->bone_form();
  co.unacknowledged_limit_s = 1.0;
  if (const verse::Status st = s->hostile->connect(s->host, s->port, co); !st.ok()) {
    *why = "the hostile session could not log in: " + st.to_string();
    return false;
  }
  ++s->hostile_logins;
  (void)s->hostile->subscribe_node(s->sut->node_id());
  return true;
}

// Opens the host (a new VerseImplementation: a fresh node) and runs the
// base program through check_step. nullopt, or why it could not.
std::optional<std::string> open_session(Session* s, const WireFuzzOptions& o) {
  std::string error;
  s->sut = nullptr;
  if (o.impl.kind != RouteKind::Verse)
    return "'" + o.impl.spec + "' is not a Verse host (vgc fuzz wire takes verse:HOST[:PORT])";
  s->owner = open_route(o.impl, open_options(o), &error);
  if (!s->owner) return error;
  s->sut = dynamic_cast<VerseImplementation*>(s->owner.get());
  if (!s->sut) return "'" + o.impl.spec + "' is not a Verse host (vgc fuzz wire takes verse:HOST[:PORT])";
  s->login = o.impl.login;
  s->host = o.impl.host;
  s->port = o.impl.port;
  s->model = Node();
  for (const Command& c : base_program()) {
    Node after;
    const StepResult r = check_step(s->model, c, *s->sut, &after);
    if (r.failure)
      return "the host fails the base program (`" + print_command(c) + "`: " + r.failure->clause + " " +
             r.failure->message + "): certify it first (vgc certify --impl " + o.impl.spec + ")";
    s->model = std::move(after);
  }
  if (!login_hostile(s, o, &error)) return error;
  return std::nullopt;
}

// Sends one input on the hostile session. Returns the commands a
// conforming host applies from it, in order.
std::vector<Command> send_input(Session* s, const WireInput& in) {
  std::vector<Command> applied;
  const std::uint32_t node = s->sut->node_id();
  if (!in.reliable.empty()) {
    std::vector<verse::WireCommand> burst;
    for (const Command& c : in.reliable) burst.push_back(verse::wire::Geometry{node, c});
    (void)s->hostile->send_burst(burst);
  }
  bool data = false;
  for (const WireDatagram& g : in.datagrams) data = data || !g.raw;
  // The ids the input takes in order; an input that takes none but sends
  // data packets (ids out of the session's order) is placed relative to the
  // next id, which is then sent (empty) after it, so the session's ids stay
  // contiguous.
  std::vector<std::uint32_t> ids;
  for (std::uint32_t i = 0; i < in.ids; ++i) ids.push_back(s->hostile->take_packet_id());
  const bool reference_only = ids.empty() && data;
  const std::uint32_t first = !ids.empty() ? ids.front() : reference_only ? s->hostile->take_packet_id() : 0;
  applied = in.reliable;
  std::int64_t expected = first;  // the id the host expects next (the session's ids are contiguous so far)
  for (const WireDatagram& g : in.datagrams) {
    const std::string bytes = wire_bytes(g.body, node);
    if (g.raw) {
      (void)s->hostile->send_datagram(bytes);
      continue;
    }
    const std::int64_t id = static_cast<std::int64_t>(first) + g.offset;
    (void)s->hostile->send_raw(static_cast<std::uint32_t>(id), bytes);
    if (id >= expected) {  // acted on; an earlier id is a duplicate, dropped
      expected = id + 1;
      applied.insert(applied.end(), g.applies.begin(), g.applies.end());
    }
  }
  if (reference_only) (void)s->hostile->send_raw(first, "");
  return applied;
}

// The implementation as check_step sees it when the command judged was
// already sent by the hostile session: apply() sends a command that
// changes nothing through the adapter instead, which waits for the
// host's round trip and answers `done`; the state is then read and
// compared as for any command.
class AlreadySent final : public ForwardingImplementation {
 public:
  explicit AlreadySent(Implementation& sut) : ForwardingImplementation(&sut) {}
  Answer apply(const Command&) override { return ForwardingImplementation::apply(no_op()); }
};

struct Outcome {
  std::optional<Finding> finding;
  bool hostile_lost = false;  // the host ended or forgot the hostile session (not a finding)
};

// After an input: a round trip on the hostile session first (the host has
// taken in everything the input sent, in the session's order; no answer:
// the host ended or forgot the session, which a host may do to a client
// that sends garbage), then the probe on the certify adapter's session:
// the host answers, and its node is what the model says.
Outcome check_after(Session* s, const WireInput& in, const std::vector<Command>& applied, std::uint64_t index,
                    const WireFuzzOptions& o) {
  Outcome out;
  std::vector<verse::WireCommand> before;
  out.hostile_lost = !s->hostile->connected() ||
                     !s->hostile->barrier(s->sut->node_id(), std::min(1.0, o.timeout_s), &before).ok();
  auto found = [&](Finding f) {
    if (f.status != FindingStatus::Fail) {
      // The command was only there to see the host answer: a host that
      // stops answering (any session, a login) after an input breaks
      // STABLE-1, whatever the command's own clause.
      f.clause = "STABLE-1";
      f.rules.clear();
      f.message = "the host stopped answering: " + f.message;
    }
    f.message = fmt::format("after hostile input {} ({}: {}): {}", index, in.kind, in.what, f.message);
    out.finding = std::move(f);
    return out;
  };
  // The input's own effect, judged as certify judges a command: the last
  // command it should have applied (the model takes the others first), or
  // one that changes nothing when it should have applied none.
  Node model = s->model, after;
  for (std::size_t i = 0; i + 1 < applied.size(); ++i) model.apply(applied[i]);
  AlreadySent sent(*s->sut);
  const StepResult judged = check_step(model, applied.empty() ? no_op() : applied.back(), sent, &after);
  if (judged.failure && applied.empty() && judged.failure->status == FindingStatus::Fail) {
    // The input held no command a conforming host applies, yet the node
    // changed: the host acted on malformed bytes (ATOMIC-1: what is not
    // applied changes nothing). What changed is the snapshot's difference.
    Finding f = *judged.failure;
    f.clause = "ATOMIC-1";
    f.rules.clear();
    const Document snap = s->sut->snapshot();
    const auto d = diff_documents(without_subscriptions(print_snapshot(model)), without_subscriptions(snap.text));
    f.message = "the input holds no command a conforming host applies, yet the node changed: " +
                (d ? d->describe() : f.message);
    return found(f);
  }
  if (judged.failure) return found(*judged.failure);
  s->model = std::move(after);
  // Then a probe: the host still applies a command sent the normal way.
  const StepResult r = check_step(s->model, probe(index), *s->sut, &after);
  if (r.failure) return found(*r.failure);
  s->model = std::move(after);
  return out;
}

// The kind a finding is grouped under: the input's own kind, or "joined"
// for every input the guided queue made by joining two (followed_by). Each
// join has a kind name of its own ("burst+raw-datagram"); grouped by it, the
// same clause and status were confirmed again, on a restarted host, for
// every new join: against r6 (seed 1, 10 minutes) 22 groups against the
// unguided arm's 5, and 305 inputs against 461 (docs/fuzzing.md).
std::string group_kind(const WireInput& in) {
  return in.kind.find('+') == std::string::npos ? in.kind : "joined";
}

struct WireFindingGroup {
  std::string key;  // group_kind + clause + status
  std::string clause, status, first_message, transcript_file, confirmation;
  std::uint64_t first_input = 0;
  std::size_t count = 0;
  double first_seen_s = 0;
};

bool write_text(const fs::path& p, const std::string& s) {
  std::ofstream out(p, std::ios::binary);
  out << s;
  return static_cast<bool>(out);
}

// Replays a finding's input on a fresh instance (the restart command, then
// a new session and node): whether it fails again with the same clause.
std::string confirm_wire_finding(const WireFuzzOptions& o, const WireInput& in, std::uint64_t index,
                                 const Finding& f, LaunchedHost* host) {
  const bool down = f.status != FindingStatus::Fail;
  const bool fresh_host = host || !o.restart.empty();
  if (down && !fresh_host)
    return "not confirmed: the host stopped answering and is not restarted without --restart CMD or --host-cmd CMD";
  if (host) {
    std::string why;
    if (!host->start(open_options(o), nullptr, &why)) return "not confirmed: " + why;
  } else if (!o.restart.empty()) {
    std::string why;
    if (!run_restart_command(o.restart, 60, &why)) return "not confirmed: " + why;
  }
  Session fresh;
  std::optional<std::string> error;
  for (int attempt = 0; attempt < 30; ++attempt) {  // a restarted host takes a moment to listen
    error = open_session(&fresh, o);
    if (!error) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  if (error) return "not confirmed: " + *error;
  const std::vector<Command> applied = send_input(&fresh, in);
  const Outcome again = check_after(&fresh, in, applied, index, o);
  if (again.finding && again.finding->clause == f.clause && again.finding->status == f.status)
    return std::string("confirmed: the input alone fails a fresh ") + (fresh_host ? "host" : "node") +
           " the same way";
  return "not confirmed: the input alone does not fail a fresh " + std::string(fresh_host ? "host" : "node") +
         " (it depends on what came before it)";
}

}  // namespace

std::string wire_bytes(const std::string& body, std::uint32_t node) {
  std::string out;
  for (std::size_t i = 0; i < body.size();) {
    if (body.compare(i, 6, kNodeToken) == 0) {
      out += static_cast<char>(node >> 24);
      out += static_cast<char>(node >> 16);
      out += static_cast<char>(node >> 8);
      out += static_cast<char>(node);
      i += 6;
    } else {
      unsigned byte = 0;  // a body is checked before it gets here (body_error); a bad pair reads as 0
      std::from_chars(body.data() + i, body.data() + std::min(body.size(), i + 2), byte, 16);
      out += static_cast<char>(byte);
      i += 2;
    }
  }
  return out;
}

WireInput make_wire_input(std::uint64_t seed, std::uint64_t index) {
  Draw d(seed, index);
  switch (d.below(8)) {
    case 0: return truncated(d);
    case 1: return over_long(d);
    case 2: return unknown_command(d);
    case 3: return long_string(d);
    case 4: return id_magnitude(d);
    case 5: return packet_order(d);
    case 6: return burst(d);
    default: return raw_datagram(d);
  }
}

std::vector<std::string> wire_input_packets(const WireInput& in) {
  std::vector<std::string> out;
  for (const WireDatagram& g : in.datagrams) {
    const std::string bytes = wire_bytes(g.body, 1);
    if (g.raw) out.push_back(bytes);
    else out.push_back(verse::build_packet(static_cast<std::uint32_t>(2 + std::max<std::int64_t>(0, g.offset)), bytes));
  }
  return out;
}

std::size_t write_wire_seeds(std::uint64_t seed, std::uint64_t count, const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  // `count` inputs of every kind, at most two packets of each: the seeds
  // cover every kind without a burst's hundred packets.
  std::map<std::string, std::uint64_t> per_kind;
  std::size_t written = 0;
  for (std::uint64_t i = 0; i < count * 64; ++i) {
    const WireInput in = make_wire_input(seed, i);
    if (per_kind[in.kind] >= count) continue;
    ++per_kind[in.kind];
    const std::vector<std::string> packets = wire_input_packets(in);
    for (std::size_t k = 0; k < packets.size() && k < 2; ++k)
      if (write_text(fs::path(dir) / fmt::format("wire-{}-{}-{}.bin", in.kind, i, k), packets[k])) ++written;
  }
  return written;
}

int run_wire_campaign(const WireFuzzOptions& o) {
  if (o.impl.kind != RouteKind::Verse) {
    fmt::print(stderr, "vgc fuzz wire: --impl takes verse:[NAME@]HOST[:PORT] (a running Verse host)\n");
    return 2;
  }
  if (o.impl_coverage != "guide" && o.impl_coverage != "observe" && o.impl_coverage != "off") {
    fmt::print(stderr, "vgc fuzz wire: --impl-coverage takes guide, observe or off (edges only), not '{}'\n",
               o.impl_coverage);
    return 2;
  }
  const auto t0 = Clock::now();
  const auto deadline = t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.time_s));
  // The run's directory (first when vgc starts the host: its output goes
  // there; else once the host answered).
  fs::path src = o.source_dir.empty() ? fs::path(std::getenv("VGC_SOURCE_DIR") ? std::getenv("VGC_SOURCE_DIR") : ".")
                                      : fs::path(o.source_dir);
  std::error_code ec;
  std::string run;
  fs::path dir;
  const auto make_run_dir = [&] {
    const fs::path runs = src / "reports" / "fuzz" / "wire";
    fs::create_directories(runs, ec);
    run = utc_stamp() + "-seed" + std::to_string(o.seed);
    for (int k = 2; !ec && !fs::create_directory(runs / run, ec) && !ec; ++k)
      run = utc_stamp() + "-seed" + std::to_string(o.seed) + "-" + std::to_string(k);
    dir = runs / run;
    fs::create_directories(dir / "transcripts", ec);
    if (ec) fmt::print(stderr, "vgc fuzz wire: cannot create {}: {}\n", dir.string(), ec.message());
    return !ec;
  };
  // A host vgc starts (--host-cmd), with the shared memory of its coverage
  // in its environment (coverage_region.h: the region sets VGC_COVERAGE_SHM).
  std::unique_ptr<CoverageRegion> region;
  std::unique_ptr<LaunchedHost> host;
  if (!o.host_cmd.empty()) {
    if (!make_run_dir()) return 2;
    if (o.impl_coverage != "off") {
      std::string error;
      region = CoverageRegion::create(std::size_t{1} << 20, &error);
      if (!region) fmt::print(stderr, "vgc fuzz wire: the host's coverage is not seen: {}\n", error);
    }
    host = std::make_unique<LaunchedHost>(o.impl, o.host_cmd, (dir / "host.log").string(),
                                          o.login_timeout_s > 0 ? o.login_timeout_s : 60);
    std::string why;
    if (!host->start(open_options(o), nullptr, &why)) {
      fmt::print(stderr, "vgc fuzz wire: {}: {}\n", o.impl.spec, escape_unprintable(why));
      return 2;
    }
  }
  Session s;
  if (auto error = open_session(&s, o)) {
    fmt::print(stderr, "vgc fuzz wire: {}: {}\n", o.impl.spec, escape_unprintable(*error));
    return 2;
  }
  if (dir.empty() && !make_run_dir()) return 2;
  if (!o.quiet)
    fmt::print(stderr, "vgc fuzz wire: {} for {} s, seed {}; host: {}\n  run: {}\n", o.impl.spec, o.time_s, o.seed,
               s.sut->identity(), dir.string());
  if (region && region->attached() && !o.quiet)
    fmt::print(stderr, "vgc fuzz wire: the host's coverage is seen: {} counters ({} function entries) in shared "
                       "memory {}, {}\n",
               region->counters(), region->function_entries(), region->name(),
               o.impl_coverage == "guide" ? "guiding the inputs (a queue of the inputs that reached new code of it)"
                                          : "counted only (observe)");
  else if (region && !o.quiet)
    fmt::print(stderr, "vgc fuzz wire: the host's coverage is not seen (it was not built with "
                       "-fsanitize-coverage=inline-8bit-counters and -lvgc_coverage): every input is drawn afresh\n");

  std::map<std::string, WireFindingGroup> groups;
  std::map<std::string, std::size_t> kinds;
  std::uint64_t index = 0, hostile_lost = 0;
  std::string stopped_because;
  auto last_print = t0;
  // Guided (--host-cmd, the host's coverage seen): the inputs that reached
  // new code of the host, and how many inputs were made from them.
  constexpr std::size_t kMaxQueue = 4096;
  // The replay line's implementation: with --host-cmd, the replay starts a fresh host itself.
  const std::string replay_impl =
      o.impl.spec + (o.host_cmd.empty() ? std::string() : " --host-cmd " + shell_quote(o.host_cmd));
  std::vector<WireInput> queue;
  std::uint64_t from_queue = 0;
  std::vector<std::pair<double, std::size_t>> reached_over_time;  // seconds since the start, counters reached
  for (; Clock::now() < deadline && (o.max_inputs == 0 || index < o.max_inputs); ++index) {
    const bool guiding = region && o.impl_coverage == "guide" && region->attached();
    bool queued = false;
    const WireInput in = guiding ? next_wire_input(o.seed, index, queue, &queued) : make_wire_input(o.seed, index);
    if (queued) ++from_queue;
    ++kinds[queued ? "(from the queue)" : in.kind];
    if (!o.seeds_out.empty()) {
      const std::vector<std::string> packets = wire_input_packets(in);
      for (std::size_t k = 0; k < packets.size() && k < 4; ++k)
        write_text(fs::path(o.seeds_out) / fmt::format("wire-{}-{}-{}.bin", in.kind, index, k), packets[k]);
    }
    if (region) region->clear();
    const std::vector<Command> applied = send_input(&s, in);
    const Outcome out = check_after(&s, in, applied, index, o);
    if (region && region->collect(nullptr, 0)) {
      // A counter of the host no input set before: kept (not an input that
      // failed: it would fail again and again; nor one after which the host
      // ended the hostile session: every join with it would end one again,
      // and each costs a new login; against r6, seed 1, the guided arm lost
      // 78 sessions where the unguided one lost 51).
      if (guiding && !out.finding && !out.hostile_lost && queue.size() < kMaxQueue) queue.push_back(in);
      const double t = std::chrono::duration<double>(Clock::now() - t0).count();
      if (!reached_over_time.empty() && t - reached_over_time.back().first < 1)
        reached_over_time.back().second = region->reached();
      else if (reached_over_time.size() < 200)
        reached_over_time.emplace_back(t, region->reached());
      else
        reached_over_time.back() = {t, region->reached()};
    }
    if (out.hostile_lost) ++hostile_lost;
    if (out.finding) {
      const Finding& f = *out.finding;
      const std::string status = finding_status_name(f.status);
      const std::string key = group_kind(in) + " " + f.clause + " " + status;
      WireFindingGroup& g = groups[key];
      ++g.count;
      if (g.count == 1) {
        g.key = key;
        g.clause = f.clause;
        g.status = status;
        g.first_message = f.message;
        g.first_input = index;
        g.first_seen_s = std::chrono::duration<double>(Clock::now() - t0).count();
        g.transcript_file = (dir / "transcripts" / fmt::format("wire-{}-{}-{}.txt", groups.size(), in.kind, f.clause)).string();
        const std::string header = fmt::format(
            "# vgc fuzz wire transcript: {} ({}, {}) after input {} of seed {}\n# {}\n# replay: vgc replay --wire {} "
            "--impl {}\n",
            f.clause, status, in.kind, index, o.seed, f.message, g.transcript_file, replay_impl);
        write_text(g.transcript_file, transcript_text(in, header));
        g.confirmation = confirm_wire_finding(o, in, index, f, host.get());
        if (!o.quiet) fmt::print(stderr, "vgc fuzz wire: finding after input {}: {} ({}): {}\n", index, f.clause, status,
                                 escape_unprintable(f.message));
      }
      if (o.stop_at_first) {
        stopped_because = "--stop-at-first";
        ++index;
        break;
      }
      // Go on: a fresh node, on the host if it still answers (the
      // confirmation may have restarted it already), else on a restarted one.
      std::optional<std::string> error = open_session(&s, o);
      if (error && o.restart.empty() && !host) {
        stopped_because = f.status != FindingStatus::Fail
                              ? "the host stopped answering and there is no --restart CMD to start it again"
                              : "could not go on: " + *error;
        ++index;
        break;
      }
      if (error) {
        std::string why;
        if (host ? !host->start(open_options(o), nullptr, &why) : !run_restart_command(o.restart, 60, &why)) {
          stopped_because = why;
          ++index;
          break;
        }
        for (int attempt = 0; attempt < 30 && error; ++attempt) {
          std::this_thread::sleep_for(std::chrono::milliseconds(200));
          error = open_session(&s, o);
        }
      }
      if (error) {
        stopped_because = "could not go on: " + *error;
        ++index;
        break;
      }
    } else if (out.hostile_lost || in.kind == "packet-id") {
      if (std::string why; !login_hostile(&s, o, &why)) {
        stopped_because = why;
        ++index;
        break;
      }
    }
    if (!o.quiet && Clock::now() - last_print >= std::chrono::seconds(10)) {
      last_print = Clock::now();
      fmt::print(stderr, "[{:5.0f}/{:.0f} s] inputs {}  findings {}  hostile sessions ended by the host {}{}\n",
                 std::chrono::duration<double>(last_print - t0).count(), o.time_s, index + 1, groups.size(),
                 hostile_lost,
                 region && region->attached()
                     ? fmt::format("  host counters {}  queue {}", region->reached(), queue.size())
                     : std::string());
    }
  }
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();

  // The summary, written whole (temporary file, then renamed).
  nlohmann::json findings = nlohmann::json::array();
  std::string md = fmt::format(
      "# vgc fuzz wire — {}\n\n| | |\n|---|---|\n| host | {} |\n| seed, time | {}, {} s (wall {:.0f} s) |\n"
      "| inputs | {} ({:.1f}/s) |\n| hostile sessions the host ended or forgot | {} (logged in again) |\n"
      "| findings | {} |\n",
      run, escape_unprintable(s.sut ? s.sut->identity() : o.impl.spec), o.seed, o.time_s, wall, index,
      wall > 0 ? static_cast<double>(index) / wall : 0.0, hostile_lost, groups.size());
  if (!stopped_because.empty()) md += "| stopped early | " + stopped_because + " |\n";
  // The host's own coverage (--host-cmd).
  const bool seen = region && (region->attached() || region->reached() > 0);
  std::string coverage_line;
  if (o.host_cmd.empty())
    coverage_line = "not seen: a host vgc did not start is not given the shared memory (start it with --host-cmd CMD); "
                    "every input drawn afresh";
  else if (o.impl_coverage == "off")
    coverage_line = "off (--impl-coverage off)";
  else if (!seen)
    coverage_line = "not seen: the host was not built with -fsanitize-coverage=inline-8bit-counters and "
                    "-lvgc_coverage (docs/fuzzing.md \"Coverage of the implementation\"); every input drawn afresh";
  else {
    coverage_line = fmt::format("{} of {} counters reached ({:.1f} %)", region->reached(), region->counters(),
                                region->counters() ? 100.0 * region->reached() / region->counters() : 0.0);
    if (region->function_entries())
      coverage_line += fmt::format(", {} of {} functions entered", region->functions_entered(),
                                   region->function_entries());
    coverage_line += o.impl_coverage == "guide"
                         ? fmt::format("; guiding: {} inputs kept in the queue, {} inputs made from it", queue.size(),
                                       from_queue)
                         : std::string("; counted only (--impl-coverage observe)");
  }
  md += "| host coverage | " + coverage_line + " |\n";
  md += "\nInputs by kind: ";
  for (const auto& [k, n] : kinds) md += fmt::format("{} {}; ", k, n);
  md += "\n\n";
  for (const auto& [key, g] : groups) {
    const Clause* c = find_clause(g.clause);
    md += fmt::format("- **{} ({}, {})** on {} inputs, first input {} after {:.1f} s: {}\n  - transcript: `{}`\n"
                      "  - replay: `vgc replay --wire {} --impl {}`\n  - {}\n",
                      g.clause, c ? clause_level_name(c->level) : "?", g.status, g.count, g.first_input,
                      g.first_seen_s, g.first_message, g.transcript_file, g.transcript_file, replay_impl,
                      g.confirmation);
    findings.push_back({{"clause", g.clause}, {"status", g.status}, {"key", g.key}, {"count", g.count},
                        {"first_input", g.first_input}, {"first_seen_s", g.first_seen_s},
                        {"message", g.first_message}, {"transcript", g.transcript_file},
                        {"confirmation", g.confirmation}});
  }
  nlohmann::json by_kind = kinds;
  nlohmann::json over_time = nlohmann::json::array();
  for (const auto& [t, n] : reached_over_time) over_time.push_back({t, n});
  const nlohmann::json coverage = {
      {"mode", o.host_cmd.empty() ? std::string("wire") : o.impl_coverage},
      {"seen", seen},
      {"counters", seen ? region->counters() : 0},
      {"counters_reached", seen ? region->reached() : 0},
      {"function_entries", seen ? region->function_entries() : 0},
      {"functions_entered", seen ? region->functions_entered() : 0},
      {"queued", queue.size()},
      {"inputs_from_queue", from_queue},
      {"over_time", over_time},
      {"line", coverage_line}};
  // The host's counters as a coverage record (coverage_record.h), as the
  // differential target writes one: which counters and function entries
  // were reached, for a table per source file.
  if (seen) {
    CoverageRecord rec;
    rec.mode = o.impl_coverage;
    rec.seen = true;
    rec.counters = std::min(region->counters(), region->reached_map().size());
    rec.reached.assign(region->reached_map().begin(), region->reached_map().begin() + rec.counters);
    rec.entries = region->entry_map();
    rec.entries.resize(rec.counters, 0);
    for (const FunctionEntry& f : region->function_entry_list())
      if (f.index < rec.counters) rec.functions.push_back({f.index, f.module, f.offset});
    rec.dropped = region->dropped_counters();
    rec.function_entries = region->function_entries();
    rec.modules = region->modules();
    const double epoch_t0 =
        std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count() - wall;
    for (const auto& [t, n] : reached_over_time) rec.timeline.emplace_back(epoch_t0 + t, n);
    fs::create_directories(dir / "implementation_coverage", ec);
    write_coverage_record((dir / "implementation_coverage" / "wire.txt").string(), rec);
  }
  const nlohmann::json j = {{"implementation", o.impl.spec}, {"seed", o.seed}, {"time_s", o.time_s}, {"wall_s", wall},
                            {"inputs", index}, {"inputs_by_kind", by_kind}, {"hostile_sessions_lost", hostile_lost},
                            {"stopped_because", stopped_because}, {"findings", findings},
                            {"host_command", o.host_cmd}, {"implementation_coverage", coverage}};
  for (const auto& [file, text] :
       {std::pair{dir / "summary.json", j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n"},
        std::pair{dir / "summary.md", escape_unprintable(md)}}) {
    fs::path tmp = file;
    tmp += ".tmp";
    if (!write_text(tmp, text)) {
      fmt::print(stderr, "vgc fuzz wire: cannot write {}\n", file.string());
      return 2;
    }
    fs::rename(tmp, file, ec);
  }
  if (!o.quiet) {
    fmt::print("{}", escape_unprintable(md));
    fmt::print("summary: {}\n", (dir / "summary.json").string());
  }
  return groups.empty() ? 0 : 1;
}

int replay_wire_transcript(const std::string& file, const WireFuzzOptions& o) {
  std::ifstream f(file, std::ios::binary);
  if (!f) {
    fmt::print(stderr, "vgc replay --wire: cannot read {}\n", file);
    return 2;
  }
  const std::string text{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
  WireInput in;
  std::string error;
  if (!parse_transcript(text, &in, &error)) {
    fmt::print(stderr, "{}: {}\n", file, error);
    return 2;
  }
  // --host-cmd: a fresh host of its own, ended when the replay ends.
  std::unique_ptr<LaunchedHost> host;
  if (!o.host_cmd.empty()) {
    host = std::make_unique<LaunchedHost>(o.impl, o.host_cmd, "", o.login_timeout_s > 0 ? o.login_timeout_s : 60);
    std::string why;
    if (!host->start(open_options(o), nullptr, &why)) {
      fmt::print(stderr, "vgc replay --wire: {}: {}\n", o.impl.spec, escape_unprintable(why));
      return 2;
    }
  }
  Session s;
  if (auto e = open_session(&s, o)) {
    fmt::print(stderr, "vgc replay --wire: {}: {}\n", o.impl.spec, escape_unprintable(*e));
    return 2;
  }
  const std::vector<Command> applied = send_input(&s, in);
  const Outcome out = check_after(&s, in, applied, 0, o);
  if (!out.finding) {
    fmt::print("{}: the host answered after the transcript's input ({}: {}) and its node holds what the reference "
               "says\n",
               o.impl.spec, in.kind, in.what);
    return 0;
  }
  const Clause* c = find_clause(out.finding->clause);
  fmt::print("{} {} ({}): {}\n", finding_status_name(out.finding->status), out.finding->clause,
             c ? clause_level_name(c->level) : "?", escape_unprintable(out.finding->message));
  return 1;
}

}  // namespace vgc::fuzz
