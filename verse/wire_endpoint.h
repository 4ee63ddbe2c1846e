// wire_endpoint.h — UDP with bounded waits, and the r6 acknowledgement and
// resend rules for one logged-in peer.
//
// Spec: docs/verse_wire.md sections 1 (packets), 2 (encryption) and 5
// (acks, naks, resends, the window), from r6 v_network.c,
// v_network_in_que.c, v_network_out_que.c, v_connection.c.
//
// Rationale: UdpSocket is a non-blocking socket whose only wait is poll()
// with the caller's time-out, so no call can hang. Channel is the
// reliability state of one peer, with no socket and no clock of its own
// (the caller passes "now"), shared by the client and the host so both
// sides follow the same rules, and testable without a network.
#pragma once

#include <netinet/in.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "wire_commands.h"
#include "wire_packet.h"
#include "wire_status.h"

namespace vgc::verse {

using Clock = std::chrono::steady_clock;

struct PeerAddress {
  sockaddr_in addr{};
  std::string to_string() const;  // "127.0.0.1:4950"
  bool operator<(const PeerAddress& o) const;
  bool operator==(const PeerAddress& o) const;
};
// IPv4 only (r6 is IPv4 only). "localhost" and dotted quads; other names via getaddrinfo.
Status resolve(const std::string& host, std::uint16_t port, PeerAddress* out);

class UdpSocket {
 public:
  UdpSocket() = default;
  ~UdpSocket();
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;

  Status open(const std::string& address, std::uint16_t port);  // bind; port 0: any free one
  bool is_open() const { return fd_ >= 0; }
  std::uint16_t port() const;
  Status send_to(const PeerAddress& to, const std::string& bytes);
  // Waits at most timeout_s for one datagram: Timeout when none came. A
  // datagram longer than kMaxPacketBytes is a ProtocolError (and dropped).
  Status receive(std::string* bytes, PeerAddress* from, double timeout_s);
  void close();
  // Gives up the socket without closing it: its descriptor (-1 if none).
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }

 private:
  int fd_ = -1;
};

// Our packets carry at most this many bytes (id included), below r6's
// 1500-byte receive buffer.
inline constexpr std::size_t kMaxSendPacketBytes = 1400;
// Bytes of sent, unacknowledged commands after which nothing new is sent
// until acks come (r6 V_NOQ_WINDOW_SIZE is 100000; ours is smaller so a
// burst cannot overflow a peer's socket buffer).
inline constexpr std::size_t kWindowBytes = 48 * 1024;
// A packet id up to this past the expected one: every id in between is
// naked, as r6 does (a burst the kernel dropped, 2,000 packets and more,
// resynchronises); further is a protocol error (a hostile id must not cost
// 4 * 10^9 naks) and the channel is out of step for good (out_of_step()):
// its owner ends the session and says so to the peer (connect_terminate),
// rather than leaving it stuck. It was 1,024, and a session that lost more
// was stuck for good, its peer never told (issue 28).
inline constexpr std::uint32_t kMaxPacketGap = 65536;

class Channel {
 public:
  Channel(const DataKey& key, double resend_interval_s);

  // Queues one encoded command (encode_command output). ProtocolError when
  // it cannot fit in one packet. own_packet: it goes in a packet of its own
  // (acks may go in front), so a peer that drops the rest of a packet after
  // a command it cannot decode (r6 v_fs_unpack) cannot drop it with that.
  Status queue(std::string encoded_command, bool own_packet = false);
  // The bone_create form packets are read in (wire_commands.h), and whether
  // a packet that parses only in the other form is taken in it
  // (parse_packet's either_bone_form; counted in other_bone_form).
  void set_bone_form(BoneForm form, bool either) {
    bone_form_ = form;
    either_bone_form_ = either;
  }
  // The datagrams to send now, encrypted: pending acks and naks, queued
  // commands (within the window) and resends of packets unacknowledged for
  // the resend interval (same id, same bytes).
  std::vector<std::string> take_datagrams(Clock::time_point now);
  // One encrypted datagram from the peer: acts on its acks and naks, plans
  // our ack (and naks for skipped ids), and appends its other commands to
  // *delivered unless it is a duplicate. A packet that does not parse is a
  // ProtocolError; the commands before the bad one are still delivered.
  Status on_datagram(const std::uint8_t* data, std::size_t size, Clock::time_point now,
                     std::vector<WireCommand>* delivered);

  // Hostile traffic (`vgc fuzz wire`, fuzz/wire/wire_fuzz.h): `clear` (any bytes,
  // parsed or not) as the body of one datagram under packet id `id`,
  // encrypted with the data key. Nothing is queued, remembered or resent;
  // the peer's ack or nak for it is ignored like any for an unknown id.
  // take_raw_id() hands out the next id in order, so that the ids this
  // channel sends stay contiguous however the caller orders its packets.
  std::string raw_datagram(std::uint32_t id, const std::string& clear) const;
  std::uint32_t take_raw_id() { return take_id(); }
  // A data packet holding only an ack of the last packet received (of id 1,
  // the login's, when none was): new id, not remembered, never resent; the
  // peer acts on nothing in it (an ack of a packet it no longer holds is
  // ignored, r6 callback_send_packet_ack). ClientSession::nudge.
  std::string ack_only_datagram();

  // Called with every datagram's clear bytes before it is parsed.
  void set_tap(std::function<void(const std::uint8_t*, std::size_t)> tap) { tap_ = std::move(tap); }

  bool all_acknowledged() const { return history_.empty() && queue_.empty(); }
  // A packet came more than kMaxPacketGap past the expected id: every later
  // one is refused too, so the session cannot go on. The detail says which.
  bool out_of_step() const { return !out_of_step_.empty(); }
  const std::string& out_of_step_detail() const { return out_of_step_; }
  Clock::time_point next_resend_due() const;  // max() when nothing is unacknowledged
  // When the oldest packet still unacknowledged was first sent; max() when none.
  Clock::time_point oldest_unacknowledged() const;
  Clock::time_point last_heard() const { return last_heard_; }

  struct Counters {
    std::size_t sent = 0, received = 0, resends = 0, naks_sent = 0, duplicates = 0;
    std::size_t naked_resent = 0;  // packets the peer naked, their commands queued again
    std::size_t other_bone_form = 0;  // packets parsed in the other bone_create form
  };
  const Counters& counters() const { return counters_; }

 private:
  struct Queued {
    std::string bytes;  // one encoded command
    bool own_packet = false;
  };
  struct Sent {
    std::vector<std::string> parts;  // its encoded commands, clear, one by one (a nak queues them again)
    std::string commands;  // the same, back to back
    std::string datagram;  // as sent, encrypted
    Clock::time_point sent_at;
    Clock::time_point first_sent;
  };
  std::uint32_t take_id();

  DataKey key_;
  Clock::duration resend_interval_;
  std::uint32_t next_out_id_ = kFirstDataPacketId;
  std::uint32_t expected_in_id_ = kFirstDataPacketId;
  std::deque<Queued> queue_;
  std::map<std::uint32_t, Sent> history_;
  std::size_t history_bytes_ = 0;
  std::deque<WireCommand> ack_nak_;  // to send, taken from the front
  // Ack-only packets of the peer, acknowledged only in a packet sent anyway
  // (take_datagrams): r6 keeps each packet it sent until it is acknowledged
  // and walks all it keeps for every ack it receives.
  std::deque<std::uint32_t> ack_only_seen_;
  Clock::time_point last_heard_;
  Counters counters_;
  std::function<void(const std::uint8_t*, std::size_t)> tap_;
  BoneForm bone_form_ = BoneForm::Spec;
  bool either_bone_form_ = false;
  std::string out_of_step_;
};

}  // namespace vgc::verse
