// wire_fuzz.h — `vgc fuzz wire --impl verse:HOST[:PORT]`: hostile Verse
// traffic against a running host, after a normal login, with the host's
// liveness and its node's state checked after every input.
//
// Spec: docs/verse_wire.md sections 1 (packets, strings, sizes), 2 (data
// packets, encryption), 5 (packet ids, acks, naks, duplicates), 8 (hostile
// input); STABLE-1 (a host answers, whatever it was sent) and the clauses of
// the catalog check_step attributes (the node holds what was acknowledged).
// docs/fuzzing.md "Hostile wire traffic".
//
// Guided by the host's coverage (--host-cmd, a host built with vgc's
// coverage runtime): as AFL and AFLNet keep an input that reaches a new
// edge of the program under test, an input after which a counter of the
// host is set that no earlier input set is kept in a queue; then every
// other input is made from the queue: a queued input followed by a fresh
// one, a fresh one followed by a queued one, or two queued ones, always in
// the order that keeps the model exact (an input a conforming host applies
// commands from goes first, one that applies nothing after it: garbage
// after a state, never a command after garbage that may have ended the
// session). Without a host vgc starts, or with its coverage not seen, every
// input is drawn afresh, as before. docs/fuzzing.md "vgc fuzz wire, guided".
//
// Rationale: the differential route sends only well-formed commands; a
// host's packet parser, its id bookkeeping and its bounds are reached only
// by bytes no client library would send. As stateful network fuzzers do
// (AFLNet and its successors), each input is a short sequence of datagrams
// sent inside a logged-in session (its data key, its packet ids): truncated
// and over-long commands, unknown command numbers, long and unterminated
// strings, ids at every magnitude (nodes, layers, vertices, packets),
// packets out of order, duplicated and resent, bursts. Inputs are drawn
// from the seed alone (same seed, same inputs), so a campaign repeats
// (guided, the queue depends on the host's coverage too: the same seed
// repeats as far as the host behaves the same).
// After each input the adapter of `vgc certify` (verse_implementation.h)
// sends one probe command to the node and check_step compares the node
// with the reference model: a host that no longer answers is a `timeout`
// (or `crash`), a node that no longer holds what the model says (the
// commands a conforming host applies from the input, and everything
// before) is a `fail` at the clause check_step names. A finding is a
// transcript: the input's datagrams (the node id as {node}, since a fresh
// node has another), which `vgc replay --wire FILE --impl verse:HOST`
// sends again to a fresh node of a fresh session.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "command.h"
#include "route.h"

namespace vgc::fuzz {

// One datagram of an input. A data packet is encrypted with the session's
// key under the packet id `offset` past the first id the input takes (the
// input takes `ids` ids in order; offsets outside 0..ids-1 are ids out of
// the session's order, earlier or later); its body is the bytes after the
// id, with the node id written as the token {node}. A raw datagram goes as
// its bytes, unencrypted (a login-stage id, or no packet at all).
struct WireDatagram {
  bool raw = false;
  std::int64_t offset = 0;
  std::string body;  // hex pairs and {node} tokens (wire_bytes() makes the bytes)
  // The commands on the node a conforming host applies when it acts on
  // this packet. A host acts on a data packet whose id is the one it
  // expects or later, and then expects the id after it; an earlier id is
  // a duplicate, dropped (docs/verse_wire.md section 5). The model follows
  // that, packet by packet, in the order they are sent (loopback keeps it).
  std::vector<Command> applies;
};

struct WireInput {
  std::string kind;  // truncated, over-long, unknown-command, long-string, id-magnitude, packet-order, burst
  std::string what;  // one line: what it sends
  std::uint32_t ids = 0;
  std::vector<WireDatagram> datagrams;
  // Commands sent first through the session's reliable channel (bursts);
  // a conforming host applies them all, in order.
  std::vector<Command> reliable;
};

// The input `index` of the campaign of `seed` (deterministic).
WireInput make_wire_input(std::uint64_t seed, std::uint64_t index);

// A body's bytes for node `node` (hex pairs, {node} as 4 bytes big-endian).
std::string wire_bytes(const std::string& body, std::uint32_t node);

// The input's data packets as fuzz_verse_packet seeds: clear packets (id,
// then the body) for node 1, first id 2 (corpora/fuzz/fuzz_verse_packet).
std::vector<std::string> wire_input_packets(const WireInput& in);

struct WireFuzzOptions {
  Route impl;                   // --impl, read: verse:[NAME@]HOST[:PORT] (another route is refused)
  double time_s = 60;           // wall-clock limit of the inputs
  std::uint64_t seed = 1;
  std::uint64_t max_inputs = 0; // 0: until time_s
  double timeout_s = 5;         // per call (the probe's barrier, a login)
  double login_timeout_s = 0;   // a login's limit; 0: timeout_s (`vgc replay --wire` passes
                                // its --start-timeout, as certify and replay bound a start)
  std::string verse_bone_form;  // "" auto
  std::string restart;          // shell command starting a fresh host ("" none)
  // The command running the host in the foreground, which vgc starts itself
  // (--host-cmd; launched_host.h): started again for a fresh instance
  // (replaces `restart`), given the shared memory of its coverage, ended
  // with vgc. "" : the host runs already.
  std::string host_cmd;
  // With host_cmd, the host's own coverage (its counters, when it was built
  // with clang's inline 8-bit counters and vgc's coverage runtime):
  // "guide" (default: an input that reaches an edge of the host no input
  // reached before is kept in a queue, and later inputs are made from the
  // queue as well as drawn afresh), "observe" (counted for the summary,
  // every input drawn afresh: today's campaign, measured alike) or "off".
  std::string impl_coverage = "guide";
  std::string source_dir;       // reports/fuzz/wire/<run>/ under it ("" : $VGC_SOURCE_DIR or .)
  bool stop_at_first = false;
  std::string seeds_out;        // also write every input's packets here ("" none)
  bool quiet = false;
};

// Runs the campaign, writes reports/fuzz/wire/<run>/{summary.md,
// summary.json, transcripts/}. Exit code: 0 no finding, 1 findings, 2 the
// host cannot be reached or fails the base program, or a usage error.
int run_wire_campaign(const WireFuzzOptions& o);

// `vgc replay --wire FILE --impl verse:HOST`: sends the transcript's input
// to a fresh node of a fresh session and checks as the campaign did. Exit
// code: 0 the host answered and its node agrees, 1 it did not (said on
// stdout), 2 the file does not read or the host cannot be reached.
int replay_wire_transcript(const std::string& file, const WireFuzzOptions& o);

// Writes the first `count` inputs of every kind of `seed` (two packets of
// each at most) as fuzz_verse_packet seeds into `dir`
// (wire-<kind>-<index>-<k>.bin). Returns the number of files written.
std::size_t write_wire_seeds(std::uint64_t seed, std::uint64_t count, const std::string& dir);

}  // namespace vgc::fuzz
