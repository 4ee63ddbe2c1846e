// verse_client.h — a Verse r6 client session: what a real client can do and
// see, which is what vgc certifies a host by.
//
// Spec: docs/verse_wire.md (login, commands, acknowledgements, what a host
// sends to subscribers); docs/spec_facts.md sections 3-4.
//
// Rationale: one object per UDP session, single-threaded, every call
// bounded by a time-out: nothing here blocks longer than the time it is
// given, and a host that stops answering is Status::Code::Timeout. The
// session acknowledges what it receives and resends what the host does not
// acknowledge (docs/verse_wire.md section 5) inside every call, so a caller
// only sends commands and reads what comes back. Incoming commands are
// decoded (wire_commands.h) and queued in arrival order; acks and naks are
// consumed here and never reach the caller.
//
// Typical use (the verse: adapter):
//   ClientSession s; s.connect("127.0.0.1", 4950, {}) ;
//   std::uint32_t node; s.create_geometry_node(&node, 5.0);
//   s.subscribe_node(node); s.subscribe_layer(node, 0, vgc::RealFormat::Real64);
//   s.send_geometry(node, command);
//   std::vector<WireCommand> seen; s.barrier(node, 5.0, &seen);  // everything the host sent first
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "command.h"
#include "wire_commands.h"
#include "wire_status.h"

namespace vgc::verse {

inline constexpr std::uint16_t kDefaultPort = 4950;  // r6 README

struct ClientOptions {
  std::string name = "vgc";       // login name, at most 31 bytes
  std::string password = "vgc";   // at most 31 bytes
  double login_timeout_s = 5.0;   // whole login, all resends included
  double resend_interval_s = 0.25;  // a login stage or an unacknowledged packet is resent after this
  // The bone_create form sent and first tried on what comes in; a packet
  // that parses only in the other form is read in it and counted
  // (Counters::other_bone_form). set_bone_form() changes it later.
  BoneForm bone_form = BoneForm::Spec;
  // > 0: a call that waits fails at once (Closed) when a packet has stayed
  // unacknowledged this long (see unacknowledged_for()); 0: only its own
  // time-out ends a wait.
  double unacknowledged_limit_s = 0;
  // Called right after the login packet (stage 2) is sent and then every
  // 10 ms until the host accepts or the login times out. r6 runs its
  // accept callback only when its loop's wait ends, which is after a whole
  // second unless a data packet of another session arrives (r6
  // v_connection.c verse_callback_update: the wait ends on a pending data
  // packet; a login packet is not one): a caller holding another session
  // with the host makes it send one (nudge()), so the login takes a round
  // trip instead of up to a second. Null: nothing.
  std::function<void()> while_awaiting_accept;
  // Called with every packet received from the host, clear (decrypted), the
  // login packets included: captures (the fuzz seeds of
  // corpora/fuzz/fuzz_verse_packet) and debugging. Null: nothing.
  std::function<void(const std::string& clear_packet)> on_packet;
  // Asked at least every 50 ms while a call waits (the login included):
  // true ends the wait at once with a Timeout "stopped" status. vgc's
  // certify stops so when its run is cancelled (SIGTERM, SIGINT), rather
  // than waiting out a login limit of a minute. Null: never.
  std::function<bool()> stop;
};

class ClientSession {
 public:
  ClientSession();
  ~ClientSession();  // disconnects (connect_terminate) if still connected
  ClientSession(const ClientSession&) = delete;
  ClientSession& operator=(const ClientSession&) = delete;

  // Resolves host ("127.0.0.1", "localhost", ...), logs in (RSA stage of
  // the r6 login). Timeout when the host does not answer a stage within
  // options.login_timeout_s; ProtocolError when it answers wrongly.
  Status connect(const std::string& host, std::uint16_t port, const ClientOptions& options);
  bool connected() const;
  std::uint32_t avatar() const;  // the avatar node id the host gave at login

  // The release number the host announced in its login challenge (6 for r6).
  std::uint8_t host_release() const;
  // The UDP port this session sends from (0 when not logged in).
  std::uint16_t local_port() const;
  BoneForm bone_form() const;
  void set_bone_form(BoneForm form);

  // node_index_subscribe(geometry) then
  // node_create(geometry): waits up to timeout_s for the host's node_create
  // of a geometry node owned by this session that is not live, and returns
  // its id. "Live" follows the index as it arrives: a node_create makes an
  // id live, a node_destroy (received, or sent by this session: r6 may
  // never send it back, see docs/verse_wire.md section 3) ends it; so an id the host reuses after a
  // destroy (r6 vs_add_new_node takes the lowest free slot) is accepted,
  // and an id announced again for a node that still exists is not.
  // Commands received meanwhile stay queued.
  Status create_geometry_node(std::uint32_t* node_id, double timeout_s);
  // The same for `count` nodes at once: one node_index_subscribe, `count`
  // node_creates in one packet, one wait for all their answers. *node_ids
  // gets them in arrival order.
  Status create_geometry_nodes(std::size_t count, std::vector<std::uint32_t>* node_ids, double timeout_s);

  // Queue and send at once (no waiting for anything to come back).
  Status subscribe_node(std::uint32_t node_id);
  Status unsubscribe_node(std::uint32_t node_id);
  Status subscribe_layer(std::uint32_t node_id, std::uint16_t layer_id, vgc::RealFormat format);
  Status send_geometry(std::uint32_t node_id, const vgc::Command& command);
  // Any other command (node_name_set, node_destroy, ...). own_packet: in a
  // packet of its own (Channel::queue).
  Status send(const WireCommand& command, bool own_packet = false);
  // All of them queued, then sent together: in one packet when they fit
  // (as r6's client sends a flush; tests of docs/verse_wire.md section 6).
  Status send_burst(const std::vector<WireCommand>& commands);

  // Hostile traffic (`vgc fuzz wire`): `clear` as one data packet under
  // packet id `id`, encrypted (Channel::raw_datagram); take_packet_id() is
  // the next id in order. Whatever the host makes of it, this session
  // stays usable only if every id taken is sent once (in any order).
  Status send_raw(std::uint32_t id, const std::string& clear);
  std::uint32_t take_packet_id();
  // One data packet holding only an ack (of the last packet received): the
  // host stores it as a packet of this session and acknowledges nothing
  // back; what it is for is waking a host that waits for data (see
  // ClientOptions::while_awaiting_accept).
  Status nudge();
  // A datagram exactly as given (no id, no encryption): packets of the
  // login's ids, or bytes that are no packet at all.
  Status send_datagram(const std::string& bytes);

  // The next decoded incoming command, waiting up to timeout_s (0: only
  // what has already arrived). Timeout when none came.
  Status receive(WireCommand* out, double timeout_s);

  // Round trip: sends node_name_set(node_id, "vgc-barrier-<n>") and waits up
  // to timeout_s for the host to send that name back to this subscriber
  // (node_id must be subscribed). Every command received before it is
  // appended to *before in arrival order (the queue is emptied); the echo
  // itself is not. So once barrier() returns ok, everything the host sent
  // in answer to commands sent before it has been seen, in the host's order
  // (docs/verse_wire.md section 6 says what this assumes). When a packet
  // was lost on the way meanwhile (naked, its commands sent again later)
  // the round trip is made again, so what they caused is seen too.
  Status barrier(std::uint32_t node_id, double timeout_s, std::vector<WireCommand>* before);

  // Seconds since the oldest packet the host has not acknowledged was first
  // sent (0 when all are). A host acknowledges on receipt, so a packet
  // unacknowledged for long means the host no longer knows this session
  // (r6 forgets one silently after a connect_terminate). Reads nothing: call
  // after receive() or barrier().
  double unacknowledged_for() const;

  // connect_terminate, then closes the socket. Safe to call twice.
  void disconnect(const std::string& bye = "vgc done");

  // Counters for reports and tests.
  struct Counters {
    std::size_t packets_sent = 0, packets_received = 0, resends = 0, naks_sent = 0;
    std::size_t protocol_errors = 0;  // packets (or parts) that did not parse; see last_protocol_error()
    std::size_t other_bone_form = 0;  // packets that parsed only in the other bone_create form
  };
  Counters counters() const;
  const std::string& last_protocol_error() const;

 private:
  Status barrier_once(std::uint32_t node_id, std::chrono::steady_clock::time_point deadline,
                      std::vector<WireCommand>* before);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vgc::verse
