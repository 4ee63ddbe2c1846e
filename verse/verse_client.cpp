// verse_client.cpp — see verse_client.h. Login: docs/verse_wire.md section 2;
// node creation and subscription: sections 3 and 7; the barrier: section 6.
#include "verse_client.h"

#include <algorithm>
#include <deque>
#include <functional>
#include <set>

#include "login_address_quarantine.h"
#include "wire_endpoint.h"
#include "wire_login.h"

namespace vgc::verse {

struct ClientSession::Impl {
  ClientOptions options;
  UdpSocket socket;
  PeerAddress host;
  bool connected = false;
  std::uint32_t avatar = 0;
  std::unique_ptr<Channel> channel;
  std::deque<WireCommand> inbox;
  std::set<std::uint32_t> live_mine;   // geometry nodes of this session the index says exist
  std::deque<std::uint32_t> new_mine;  // node_creates (mine) of ids that were not live, in arrival order
  bool index_subscribed = false;
  std::uint8_t host_release = 0;
  std::uint64_t barriers = 0;
  Counters counters;
  std::string last_protocol_error;
  std::string dropped;  // why the session ended without our asking: every later call says so

  // Not connected: why (Dropped when the session ended without our asking).
  Status not_connected() const {
    if (!dropped.empty()) return Status::dropped(dropped);
    return Status::closed("not connected");
  }

  // The session ends without our asking: the host dropped it, or it fell
  // out of step (then the host is told, as r6 tells a peer it ends).
  Status end_dropped(const std::string& why, bool tell_host) {
    if (tell_host && channel) {
      std::string clear;
      if (encode_command(wire::ConnectTerminate{"vgc client: out of step with the host"}, &clear).ok())
        (void)socket.send_to(host, channel->raw_datagram(channel->take_raw_id(), clear));
    }
    connected = false;
    dropped = why;
    return Status::dropped(why);
  }

  // The login's address stays bound for a while after it ends
  // (login_address_quarantine.h): no later login is given it.
  void retire_socket() { quarantine_login_socket(socket.release()); }

  void note_protocol_error(const Status& st) {
    ++counters.protocol_errors;
    last_protocol_error = st.detail;
  }

  Status flush() {
    if (!channel) return not_connected();
    for (const std::string& d : channel->take_datagrams(Clock::now())) {
      Status st = socket.send_to(host, d);
      if (!st.ok()) return st;
    }
    return {};
  }

  // Sends, receives and resends until done() or the deadline.
  Status pump(Clock::time_point deadline, const std::function<bool()>& done, const char* waiting_for) {
    if (!connected) return not_connected();
    std::size_t drained_late = 0;  // a host flooding us cannot keep a late call going
    // A packet unacknowledged past the limit ends the session only once
    // nothing more has arrived: the ack may be waiting, unread, in the
    // socket (a session idle for longer than the limit between two calls
    // was declared closed with its ack in the buffer).
    bool inbox_checked = false;
    for (;;) {
      Status st = flush();
      if (!st.ok()) return st;
      if (done()) return {};
      if (options.stop && options.stop()) return Status::timeout(std::string("stopped while waiting for ") + waiting_for);
      const Clock::time_point now = Clock::now();
      const bool overdue =
          options.unacknowledged_limit_s > 0 && channel->oldest_unacknowledged() != Clock::time_point::max() &&
          now - channel->oldest_unacknowledged() >
              std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.unacknowledged_limit_s));
      if (overdue && inbox_checked) {
        connected = false;
        return Status::closed("the host has not acknowledged a packet for " +
                              seconds_text(options.unacknowledged_limit_s) + ": it no longer knows this session");
      }
      const bool late = now >= deadline;  // then only what has already arrived is read
      Clock::time_point wake = std::min({deadline, channel->next_resend_due(), now + std::chrono::milliseconds(50)});
      const double wait = late || overdue ? 0.0 : std::chrono::duration<double>(wake - now).count();
      std::string bytes;
      PeerAddress from;
      st = socket.receive(&bytes, &from, wait > 0 ? wait : 0);
      if (st.code == Status::Code::Timeout) {
        if (overdue) {
          inbox_checked = true;
          continue;
        }
        if (late) return Status::timeout(std::string("the host did not send ") + waiting_for + " in time");
        continue;
      }
      inbox_checked = false;
      if (late && ++drained_late > 1024)
        return Status::timeout(std::string("the host did not send ") + waiting_for + " in time");
      if (st.code == Status::Code::ProtocolError) {
        note_protocol_error(st);
        continue;
      }
      if (!st.ok()) return st;
      if (!(from == host)) continue;  // not our host: ignored
      ++counters.packets_received;
      std::vector<WireCommand> got;
      st = channel->on_datagram(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), Clock::now(), &got);
      if (!st.ok()) note_protocol_error(st);
      if (channel->out_of_step())
        return end_dropped("this session fell out of step with the host, which can no longer be caught up: " +
                               channel->out_of_step_detail() + "; log in again",
                           true);
      for (WireCommand& c : got) {
        if (const auto* t = std::get_if<wire::ConnectTerminate>(&c))
          return end_dropped("the host dropped this session (connect_terminate \"" + t->bye + "\"); log in again",
                             false);
        track_index(c);
        inbox.push_back(std::move(c));
      }
    }
  }

  // The node index as it arrives (create_geometry_node).
  void track_index(const WireCommand& c) {
    if (const auto* n = std::get_if<wire::NodeCreate>(&c)) {
      if (n->type == kNodeTypeGeometry && n->owner == kOwnerMine && live_mine.insert(n->node_id).second)
        new_mine.push_back(n->node_id);
    } else if (const auto* d = std::get_if<wire::NodeDestroy>(&c)) {
      live_mine.erase(d->node_id);
    }
  }

  Status send(const WireCommand& c, bool own_packet = false) {
    if (!connected) return not_connected();
    std::string bytes;
    Status st = encode_command(c, &bytes, options.bone_form);
    if (!st.ok()) return st;
    st = channel->queue(std::move(bytes), own_packet);
    // Our own destroy ends the id at once: r6 does not always tell us (its
    // out-queue keeps one unsent command per address, so the node_create of
    // a node that reuses the id replaces the node_destroy before it is sent).
    if (const auto* d = std::get_if<wire::NodeDestroy>(&c)) live_mine.erase(d->node_id);
    if (!st.ok()) return st;
    return flush();
  }
};

ClientSession::ClientSession() : impl_(std::make_unique<Impl>()) {}
ClientSession::~ClientSession() { disconnect(); }

static Clock::time_point deadline_after(double seconds) {
  if (!(seconds > 0)) seconds = 0;
  seconds = std::min(seconds, 24.0 * 3600.0);
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

Status ClientSession::connect(const std::string& host, std::uint16_t port, const ClientOptions& options) {
  Impl& s = *impl_;
  disconnect();
  s.dropped.clear();
  s.options = options;
  KeyBytes block{};
  if (!make_login_block(options.name, options.password, &block))
    return Status::protocol_error("login name and password must be at most 31 bytes without NUL, the name ASCII");
  Status st = resolve(host, port, &s.host);
  if (!st.ok()) return st;
  st = s.socket.open("0.0.0.0", 0);
  if (!st.ok()) return st;
  RsaKey key = make_rsa_key();
  const Clock::time_point deadline = deadline_after(options.login_timeout_s);
  const auto resend = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(std::max(0.01, options.resend_interval_s)));
  std::string stage_packet = build_login_packet(login::Contact{key.e, key.n});
  const char* stage_name = "its key (login stage 1)";
  int restarts = 0;  // logins started again from a new address (below)
  Clock::time_point sent_at = Clock::now();
  bool send_now = true;  // a new stage packet, or the resend interval passed
  const auto nudge_every = std::chrono::milliseconds(10);
  bool login_sent = false;       // the stage packet is the login (stage 2)
  bool awaiting_accept = false;  // ... and it was sent
  Clock::time_point nudged_at{};
  for (;;) {
    Clock::time_point now = Clock::now();
    if (send_now || now - sent_at >= resend) {
      send_now = false;
      st = s.socket.send_to(s.host, stage_packet);
      if (!st.ok()) return st;
      sent_at = now;
      if (login_sent && !awaiting_accept) {  // the login went out: nudge at once
        awaiting_accept = true;
        nudged_at = now - nudge_every;
      }
    }
    if (options.while_awaiting_accept && awaiting_accept && now - nudged_at >= nudge_every) {
      options.while_awaiting_accept();
      nudged_at = now;
    }
    if (options.stop && options.stop()) {
      s.retire_socket();
      return Status::timeout(std::string("stopped while waiting for ") + stage_name);
    }
    if (now >= deadline) {
      s.retire_socket();
      return Status::timeout("no Verse host answered at " + s.host.to_string() + ": it did not send " + stage_name +
                             " within " + seconds_text(options.login_timeout_s));
    }
    Clock::time_point wake = std::min(deadline, sent_at + resend);
    if (options.while_awaiting_accept && awaiting_accept) wake = std::min(wake, nudged_at + nudge_every);
    const double wait = std::chrono::duration<double>(wake - now).count();
    std::string bytes;
    PeerAddress from;
    st = s.socket.receive(&bytes, &from, std::max(0.0, wait));
    if (st.code == Status::Code::Timeout) continue;
    if (!st.ok() && st.code != Status::Code::ProtocolError) return st;
    if (!st.ok() || !(from == s.host)) continue;
    if (options.on_packet) options.on_packet(bytes);
    LoginMessage m;
    st = parse_login_packet(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), &m);
    if (!st.ok()) {
      s.note_protocol_error(st);
      continue;
    }
    if (const auto* c = std::get_if<login::Challenge>(&m)) {
      s.host_release = c->version;
      if (c->version != kReleaseNumber) {
        s.retire_socket();
        return Status::protocol_error("the host speaks Verse release " + std::to_string(c->version) + ", vgc speaks r" +
                                      std::to_string(kReleaseNumber));
      }
      login::Login l;
      st = rsa_apply(block, c->e, c->n, &l.encrypted);
      if (!st.ok()) {
        s.retire_socket();
        return Status::protocol_error("the host's login key is unusable: " + st.detail);
      }
      stage_packet = build_login_packet(l);
      stage_name = "connect_accept (login stage 3)";
      login_sent = true;
      send_now = true;
    } else if (const auto* a = std::get_if<login::Accept>(&m)) {
      if (stage_name[0] == 'i') continue;  // an accept before our login: not ours
      KeyBytes clear{};
      st = rsa_apply(a->encrypted_data_key, key.d, key.n, &clear);
      if (!st.ok() && restarts < 3) {
        // Encrypted under another key: the host still holds an earlier
        // login from this address (login_address_quarantine.h says how it
        // can get one). Start again from a new address, within the limit.
        ++restarts;
        s.retire_socket();
        st = s.socket.open("0.0.0.0", 0);
        if (!st.ok()) return st;
        key = make_rsa_key();
        stage_packet = build_login_packet(login::Contact{key.e, key.n});
        stage_name = "its key (login stage 1)";
        login_sent = awaiting_accept = false;
        send_now = true;
        continue;
      }
      if (!st.ok()) {
        s.retire_socket();
        return Status::protocol_error("connect_accept: " + st.detail + ": " + std::to_string(restarts + 1) +
                                      " logins, each from a new address, were answered with an accept for another key");
      }
      DataKey data_key;
      std::copy(clear.begin(), clear.end(), data_key.begin());
      s.avatar = a->avatar;
      s.channel = std::make_unique<Channel>(data_key, options.resend_interval_s);
      s.channel->set_bone_form(options.bone_form, true);
      if (options.on_packet)
        s.channel->set_tap([f = options.on_packet](const std::uint8_t* d, std::size_t n) {
          f(std::string(reinterpret_cast<const char*>(d), n));
        });
      s.connected = true;
      s.inbox.clear();
      s.live_mine.clear();
      s.new_mine.clear();
      s.index_subscribed = false;
      return {};
    } else if (std::holds_alternative<login::Terminate>(m)) {
      s.retire_socket();
      return Status::closed("the host refused the login");
    }
  }
}

bool ClientSession::connected() const { return impl_->connected; }
std::uint32_t ClientSession::avatar() const { return impl_->avatar; }

std::uint8_t ClientSession::host_release() const { return impl_->host_release; }
std::uint16_t ClientSession::local_port() const { return impl_->connected ? impl_->socket.port() : 0; }
BoneForm ClientSession::bone_form() const { return impl_->options.bone_form; }
void ClientSession::set_bone_form(BoneForm form) {
  impl_->options.bone_form = form;
  if (impl_->channel) impl_->channel->set_bone_form(form, true);
}

Status ClientSession::create_geometry_node(std::uint32_t* node_id, double timeout_s) {
  std::vector<std::uint32_t> ids;
  Status st = create_geometry_nodes(1, &ids, timeout_s);
  if (st.ok()) *node_id = ids.front();
  return st;
}

Status ClientSession::create_geometry_nodes(std::size_t count, std::vector<std::uint32_t>* node_ids,
                                            double timeout_s) {
  Impl& s = *impl_;
  const Clock::time_point deadline = deadline_after(timeout_s);
  // Every time, not once: a host may have lost the subscription (r6 runs
  // whatever node_index_subscribe it decodes from the rest of a
  // desynchronised packet). Its answer re-announces live nodes, which are
  // not new.
  {
    Status st = s.send(wire::NodeIndexSubscribe{1u << kNodeTypeGeometry});
    if (!st.ok()) return st;
    s.index_subscribed = true;
  }
  // What the index announced before this request is not its answer; the
  // host answers in order, so the new nodes' node_creates come after.
  Status st = s.pump(Clock::now(), [] { return false; }, "nothing");  // reads what has already arrived
  if (st.code == Status::Code::Closed || st.code == Status::Code::Dropped || st.code == Status::Code::NetworkError)
    return st;
  s.new_mine.clear();
  for (std::size_t i = 0; i < count; ++i) {
    std::string bytes;
    st = encode_command(wire::NodeCreate{kAnyNodeId, kNodeTypeGeometry, kOwnerMine}, &bytes, s.options.bone_form);
    if (st.ok()) st = s.channel->queue(std::move(bytes));
    if (!st.ok()) return st;
  }
  st = s.pump(deadline, [&] { return s.new_mine.size() >= count; }, "node_create for the new geometry node");
  if (!st.ok()) return st;
  node_ids->assign(s.new_mine.begin(), s.new_mine.begin() + static_cast<std::ptrdiff_t>(count));
  s.new_mine.erase(s.new_mine.begin(), s.new_mine.begin() + static_cast<std::ptrdiff_t>(count));
  return {};
}

Status ClientSession::subscribe_node(std::uint32_t node_id) { return impl_->send(wire::NodeSubscribe{node_id}); }
Status ClientSession::unsubscribe_node(std::uint32_t node_id) { return impl_->send(wire::NodeUnsubscribe{node_id}); }
Status ClientSession::subscribe_layer(std::uint32_t node_id, std::uint16_t layer_id, vgc::RealFormat format) {
  return impl_->send(wire::Geometry{node_id, cmd::LayerSubscribe{layer_id, static_cast<std::uint8_t>(format)}});
}
Status ClientSession::send_geometry(std::uint32_t node_id, const vgc::Command& command) {
  return impl_->send(wire::Geometry{node_id, command});
}
Status ClientSession::send(const WireCommand& command, bool own_packet) { return impl_->send(command, own_packet); }
Status ClientSession::send_raw(std::uint32_t id, const std::string& clear) {
  Impl& s = *impl_;
  if (!s.connected || !s.channel) return s.not_connected();
  return s.socket.send_to(s.host, s.channel->raw_datagram(id, clear));
}
std::uint32_t ClientSession::take_packet_id() { return impl_->channel ? impl_->channel->take_raw_id() : 0; }
Status ClientSession::nudge() {
  Impl& s = *impl_;
  if (!s.connected || !s.channel) return s.not_connected();
  return s.socket.send_to(s.host, s.channel->ack_only_datagram());
}
Status ClientSession::send_datagram(const std::string& bytes) {
  Impl& s = *impl_;
  if (!s.connected) return s.not_connected();
  return s.socket.send_to(s.host, bytes);
}
Status ClientSession::send_burst(const std::vector<WireCommand>& commands) {
  Impl& s = *impl_;
  if (!s.connected) return s.not_connected();
  for (const WireCommand& c : commands) {
    std::string bytes;
    Status st = encode_command(c, &bytes, s.options.bone_form);
    if (st.ok()) st = s.channel->queue(std::move(bytes));
    if (!st.ok()) return st;
  }
  return s.flush();
}

Status ClientSession::receive(WireCommand* out, double timeout_s) {
  Impl& s = *impl_;
  if (s.inbox.empty()) {
    Status st = s.pump(deadline_after(timeout_s), [&] { return !s.inbox.empty(); }, "any command");
    if (!st.ok()) return st;
  }
  *out = std::move(s.inbox.front());
  s.inbox.pop_front();
  return {};
}

Status ClientSession::barrier(std::uint32_t node_id, double timeout_s, std::vector<WireCommand>* before) {
  Impl& s = *impl_;
  const Clock::time_point deadline = deadline_after(timeout_s);
  // A packet lost on the way (either way) is naked and its commands come
  // again under a later id, possibly after the echo: then the round is
  // made again, after them (docs/verse_wire.md section 6).
  for (;;) {
    if (!s.channel) return s.not_connected();
    const std::size_t naks = s.channel->counters().naks_sent, naked = s.channel->counters().naked_resent;
    Status st = barrier_once(node_id, deadline, before);
    if (!st.ok() || !s.channel) return st;
    if (s.channel->counters().naks_sent == naks && s.channel->counters().naked_resent == naked) return {};
  }
}

Status ClientSession::barrier_once(std::uint32_t node_id, std::chrono::steady_clock::time_point deadline,
                                   std::vector<WireCommand>* before) {
  Impl& s = *impl_;
  const std::string token = "vgc-barrier-" + std::to_string(s.avatar) + "-" + std::to_string(++s.barriers);
  Status st = s.send(wire::NodeNameSet{node_id, token}, true);
  if (!st.ok()) return st;
  std::size_t echo_at = 0;
  st = s.pump(
      deadline,
      [&] {
        for (std::size_t i = 0; i < s.inbox.size(); ++i) {
          const auto* n = std::get_if<wire::NodeNameSet>(&s.inbox[i]);
          if (n && n->node_id == node_id && n->name == token) {
            echo_at = i;
            return true;
          }
        }
        return false;
      },
      "the barrier's node_name_set back");
  if (!st.ok()) return st;
  for (std::size_t i = 0; i < echo_at; ++i) before->push_back(std::move(s.inbox[i]));
  s.inbox.erase(s.inbox.begin(), s.inbox.begin() + static_cast<std::ptrdiff_t>(echo_at) + 1);
  return {};
}

void ClientSession::disconnect(const std::string& bye) {
  Impl& s = *impl_;
  if (s.connected) {
    (void)s.send(wire::ConnectTerminate{bye});
    s.connected = false;
  }
  s.channel.reset();
  s.retire_socket();
}

ClientSession::Counters ClientSession::counters() const {
  Counters c = impl_->counters;
  if (impl_->channel) {
    const auto& k = impl_->channel->counters();
    c.packets_sent = k.sent;
    c.resends = k.resends;
    c.naks_sent = k.naks_sent;
    c.other_bone_form = k.other_bone_form;
  }
  return c;
}
double ClientSession::unacknowledged_for() const {
  if (!impl_->channel) return 0;
  const Clock::time_point t = impl_->channel->oldest_unacknowledged();
  if (t == Clock::time_point::max()) return 0;
  return std::chrono::duration<double>(Clock::now() - t).count();
}

const std::string& ClientSession::last_protocol_error() const { return impl_->last_protocol_error; }

}  // namespace vgc::verse
