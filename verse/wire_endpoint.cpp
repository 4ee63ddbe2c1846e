// wire_endpoint.cpp — see wire_endpoint.h.
#include "wire_endpoint.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace vgc::verse {

std::string PeerAddress::to_string() const {
  char buf[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &addr.sin_addr, buf, sizeof buf);
  return std::string(buf) + ":" + std::to_string(ntohs(addr.sin_port));
}
bool PeerAddress::operator<(const PeerAddress& o) const {
  if (addr.sin_addr.s_addr != o.addr.sin_addr.s_addr) return addr.sin_addr.s_addr < o.addr.sin_addr.s_addr;
  return addr.sin_port < o.addr.sin_port;
}
bool PeerAddress::operator==(const PeerAddress& o) const {
  return addr.sin_addr.s_addr == o.addr.sin_addr.s_addr && addr.sin_port == o.addr.sin_port;
}

Status resolve(const std::string& host, std::uint16_t port, PeerAddress* out) {
  out->addr = {};
  out->addr.sin_family = AF_INET;
  out->addr.sin_port = htons(port);
  const std::string h = host == "localhost" ? "127.0.0.1" : host;
  if (inet_pton(AF_INET, h.c_str(), &out->addr.sin_addr) == 1) return {};
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_DGRAM;
  addrinfo* res = nullptr;
  const int rc = getaddrinfo(h.c_str(), nullptr, &hints, &res);
  if (rc != 0 || res == nullptr)
    return Status::network_error("cannot resolve host '" + host + "': " + gai_strerror(rc));
  out->addr.sin_addr = reinterpret_cast<sockaddr_in*>(res->ai_addr)->sin_addr;
  freeaddrinfo(res);
  return {};
}

UdpSocket::~UdpSocket() { close(); }

void UdpSocket::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

Status UdpSocket::open(const std::string& address, std::uint16_t port) {
  close();
  PeerAddress local;
  Status st = resolve(address, port, &local);
  if (!st.ok()) return st;
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) return Status::network_error(std::string("socket: ") + std::strerror(errno));
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&local.addr), sizeof local.addr) != 0) {
    const int e = errno;
    close();
    return Status::network_error("cannot bind UDP " + local.to_string() + ": " + std::strerror(e));
  }
  return {};
}

std::uint16_t UdpSocket::port() const {
  sockaddr_in a{};
  socklen_t len = sizeof a;
  if (fd_ < 0 || getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &len) != 0) return 0;
  return ntohs(a.sin_port);
}

Status UdpSocket::send_to(const PeerAddress& to, const std::string& bytes) {
  if (fd_ < 0) return Status::network_error("socket is closed");
  for (int attempt = 0; attempt < 50; ++attempt) {
    const ssize_t n = ::sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&to.addr),
                               sizeof to.addr);
    if (n == static_cast<ssize_t>(bytes.size())) return {};
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == ENOBUFS)) {
      pollfd p{fd_, POLLOUT, 0};
      ::poll(&p, 1, 10);
      continue;
    }
    if (n < 0 && errno == ECONNREFUSED) return {};  // an earlier datagram found no listener; UDP goes on
    return Status::network_error("sendto " + to.to_string() + ": " + std::strerror(errno));
  }
  return {};  // the send buffer stayed full: the datagram is lost, as UDP may; resends cover it
}

Status UdpSocket::receive(std::string* bytes, PeerAddress* from, double timeout_s) {
  if (fd_ < 0) return Status::network_error("socket is closed");
  if (!(timeout_s >= 0)) timeout_s = 0;
  pollfd p{fd_, POLLIN, 0};
  const int ms = static_cast<int>(std::ceil(std::min(timeout_s, 3600.0) * 1000.0));
  const int rc = ::poll(&p, 1, ms);
  if (rc < 0 && errno != EINTR) return Status::network_error(std::string("poll: ") + std::strerror(errno));
  if (rc <= 0) return Status::timeout("no datagram");
  std::uint8_t buf[kMaxPacketBytes + 1];
  socklen_t len = sizeof from->addr;
  const ssize_t n = ::recvfrom(fd_, buf, sizeof buf, MSG_TRUNC, reinterpret_cast<sockaddr*>(&from->addr), &len);
  if (n < 0) {
    if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR || errno == ECONNREFUSED)
      return Status::timeout("no datagram");
    return Status::network_error(std::string("recvfrom: ") + std::strerror(errno));
  }
  if (static_cast<std::size_t>(n) > kMaxPacketBytes)
    return Status::protocol_error("datagram of " + std::to_string(n) + " bytes from " + from->to_string() +
                                  ": longer than " + std::to_string(kMaxPacketBytes));
  bytes->assign(reinterpret_cast<const char*>(buf), static_cast<std::size_t>(n));
  return {};
}

Channel::Channel(const DataKey& key, double resend_interval_s)
    : key_(key),
      resend_interval_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(resend_interval_s))),
      last_heard_(Clock::now()) {}

std::string Channel::raw_datagram(std::uint32_t id, const std::string& clear) const {
  std::string datagram = build_packet(id, clear);
  xor_packet(&datagram, key_);
  return datagram;
}

std::string Channel::ack_only_datagram() {
  const std::uint32_t last = expected_in_id_ == kFirstDataPacketId ? 1 : expected_in_id_ - 1;
  std::string ack;
  (void)encode_command(wire::PacketAck{last}, &ack);
  ++counters_.sent;
  return raw_datagram(take_id(), ack);
}

std::uint32_t Channel::take_id() {
  const std::uint32_t id = next_out_id_++;
  if (next_out_id_ == 0) next_out_id_ = kFirstDataPacketId;  // r6 skips 0 on wrap; 1 belongs to the login
  return id;
}

Status Channel::queue(std::string encoded_command, bool own_packet) {
  // Room for the id and a few acks in front.
  if (encoded_command.size() > kMaxSendPacketBytes - 4 - 5 * 8)
    return Status::protocol_error("command of " + std::to_string(encoded_command.size()) +
                                  " bytes does not fit in one packet");
  queue_.push_back(Queued{std::move(encoded_command), own_packet});
  return {};
}

Clock::time_point Channel::next_resend_due() const {
  Clock::time_point due = Clock::time_point::max();
  for (const auto& [id, s] : history_) due = std::min(due, s.sent_at + resend_interval_);
  return due;
}

Clock::time_point Channel::oldest_unacknowledged() const {
  Clock::time_point t = Clock::time_point::max();
  for (const auto& [id, s] : history_) t = std::min(t, s.first_sent);
  return t;
}

std::vector<std::string> Channel::take_datagrams(Clock::time_point now) {
  std::vector<std::string> out;
  // Resends first: same id, same bytes (the peer acks a duplicate without acting on it).
  for (auto& [id, s] : history_) {
    if (now - s.sent_at >= resend_interval_) {
      out.push_back(s.datagram);
      s.sent_at = now;
      ++counters_.resends;
    }
  }
  while (!ack_nak_.empty() || (!queue_.empty() && history_bytes_ < kWindowBytes)) {
    std::string acks, commands;
    std::vector<std::string> parts;
    std::size_t used = 4;
    while (!ack_nak_.empty() && used + 5 <= kMaxSendPacketBytes) {
      (void)encode_command(ack_nak_.front(), &acks);
      ack_nak_.pop_front();
      used += 5;
    }
    // The peer's ack-only packets ride along in a packet sent anyway (never
    // in one of their own: that would start an endless exchange), up to 64
    // a packet, leaving room for commands.
    const bool sending_anyway = !acks.empty() || (!queue_.empty() && history_bytes_ < kWindowBytes);
    for (int n = 0; sending_anyway && n < 64 && !ack_only_seen_.empty() && used + 5 <= kMaxSendPacketBytes / 2; ++n) {
      (void)encode_command(wire::PacketAck{ack_only_seen_.front()}, &acks);
      ack_only_seen_.pop_front();
      used += 5;
    }
    while (!queue_.empty() && history_bytes_ + commands.size() < kWindowBytes &&
           used + queue_.front().bytes.size() <= kMaxSendPacketBytes) {
      const bool alone = queue_.front().own_packet;
      if (alone && !commands.empty()) break;  // it starts the next packet
      used += queue_.front().bytes.size();
      commands += queue_.front().bytes;
      parts.push_back(std::move(queue_.front().bytes));
      queue_.pop_front();
      if (alone) break;
    }
    if (acks.empty() && commands.empty()) break;  // the window is full
    const std::uint32_t id = take_id();
    std::string datagram = build_packet(id, acks + commands);
    xor_packet(&datagram, key_);
    out.push_back(datagram);
    ++counters_.sent;
    if (!commands.empty()) {  // ack-only packets are neither acknowledged nor resent
      history_bytes_ += commands.size();
      history_[id] = Sent{std::move(parts), std::move(commands), std::move(datagram), now, now};
    }
  }
  return out;
}

Status Channel::on_datagram(const std::uint8_t* data, std::size_t size, Clock::time_point now,
                            std::vector<WireCommand>* delivered) {
  if (size < 4 || size > kMaxPacketBytes)
    return Status::protocol_error("datagram of " + std::to_string(size) + " bytes: not a packet");
  const std::uint32_t raw_id = (std::uint32_t{data[0]} << 24) | (std::uint32_t{data[1]} << 16) |
                               (std::uint32_t{data[2]} << 8) | std::uint32_t{data[3]};
  if (raw_id == 0 || raw_id == 1) return {};  // a late login packet (clear, not for this channel): ignored
  std::uint8_t clear[kMaxPacketBytes];
  std::memcpy(clear, data, size);
  xor_packet(clear, size, key_);
  if (tap_) tap_(clear, size);
  Packet p;
  Status st = parse_packet(clear, size, &p, bone_form_, either_bone_form_);
  last_heard_ = now;
  ++counters_.received;
  if (p.other_bone_form) ++counters_.other_bone_form;
  bool has_commands = false;
  for (const WireCommand& c : p.commands) {
    if (const auto* a = std::get_if<wire::PacketAck>(&c)) {
      auto it = history_.find(a->packet_id);
      if (it != history_.end()) {
        history_bytes_ -= it->second.commands.size();
        history_.erase(it);
      }
    } else if (const auto* n = std::get_if<wire::PacketNak>(&c)) {
      auto it = history_.find(n->packet_id);
      if (it != history_.end()) {  // its commands go out again, first, in a new packet
        ++counters_.naked_resent;
        history_bytes_ -= it->second.commands.size();
        std::vector<Queued> again;
        const bool alone = it->second.parts.size() == 1;  // a packet of one (a barrier) stays one
        for (std::string& part : it->second.parts) again.push_back(Queued{std::move(part), alone});
        history_.erase(it);
        for (auto r = again.rbegin(); r != again.rend(); ++r) queue_.push_front(*r);
      }
    } else {
      has_commands = true;
    }
  }
  const bool duplicate = static_cast<std::int32_t>(p.id - expected_in_id_) < 0;
  if (duplicate) {
    ++counters_.duplicates;
    if (has_commands) ack_nak_.push_back(wire::PacketAck{p.id});
    return st;
  }
  const std::uint32_t gap = p.id - expected_in_id_;
  if (gap > kMaxPacketGap) {
    const std::string why = "packet id " + std::to_string(p.id) + " is " + std::to_string(gap) + " past the expected " +
                            std::to_string(expected_in_id_) + " (more than " + std::to_string(kMaxPacketGap) +
                            " packets lost in a row)";
    // Only a packet that reads as one under the session's key (garbage
    // under a far id, from anyone, is only a protocol error).
    if (out_of_step_.empty() && st.ok()) out_of_step_ = why;
    return Status::protocol_error(why);
  }
  for (std::uint32_t id = expected_in_id_; id != p.id; ++id) {
    ack_nak_.push_back(wire::PacketNak{id});
    ++counters_.naks_sent;
  }
  expected_in_id_ = p.id + 1;
  if (expected_in_id_ == 0) expected_in_id_ = kFirstDataPacketId;
  if (has_commands) ack_nak_.push_back(wire::PacketAck{p.id});
  else if (ack_only_seen_.size() < 4096) ack_only_seen_.push_back(p.id);  // beyond: the peer keeps it
  for (WireCommand& c : p.commands)
    if (!std::holds_alternative<wire::PacketAck>(c) && !std::holds_alternative<wire::PacketNak>(c))
      delivered->push_back(std::move(c));
  return st;
}

}  // namespace vgc::verse
