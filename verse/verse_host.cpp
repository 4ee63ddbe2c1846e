// verse_host.cpp — see verse_host.h. Login: docs/verse_wire.md section 2;
// node commands: section 3; what goes to subscribers: section 7 (from r6
// vs_node_storage.c, vs_node_head.c, vs_node_geometry.c).
#include "verse_host.h"

#include <charconv>
#include <algorithm>
#include <chrono>
#include <cfloat>
#include <cstdio>
#include <ctime>
#include <map>
#include <set>
#include <thread>

#include "document_digest.h"
#include "followed_node.h"
#include "node.h"
#include "packet_order.h"
#include "snapshot.h"
#include "snapshot_state.h"
#include "wire_endpoint.h"
#include "wire_login.h"

namespace vgc::verse {
namespace {

class ReferenceHostedNode : public HostedNode {
 public:
  bool apply(const vgc::Command& command, std::string*) override {
    node_.apply(command, nullptr, &changes_);
    digest_.update(node_, changes_);
    return true;
  }
  bool snapshot(std::string* text, std::string*) override {
    *text = print_snapshot(node_);
    return true;
  }
  bool offers_digest() override { return true; }
  bool snapshot_digest(std::uint64_t* digest, std::string*) override {
    *digest = digest_.digests().snapshot;
    return true;
  }

 private:
  vgc::Node node_;
  vgc::NodeDigest digest_;
  vgc::ChangeLog changes_;
};

struct Session {
  PeerAddress peer;
  bool connected = false;
  std::uint32_t avatar = 0;
  DataKey data_key{};
  std::string challenge_packet, accept_packet;  // resent on a repeated stage
  std::unique_ptr<Channel> channel;
  Clock::time_point last_heard;
  bool index_geometry = false;
  BoneForm bone_form = BoneForm::Spec;  // what it is sent in: the host's, until it sends the other one
  std::set<std::uint32_t> node_subs;
  std::map<std::pair<std::uint32_t, std::uint16_t>, RealFormat> layer_subs;
  // HostOptions::both_formats: the format a subscription had before the
  // session subscribed again in another one, still served (as r6 does).
  std::map<std::pair<std::uint32_t, std::uint16_t>, RealFormat> layer_subs_kept;
};

struct HostedGeometry {
  std::uint32_t id = 0;
  std::uint32_t owner = 0;  // avatar of the session that created it
  std::string name;
  std::unique_ptr<HostedNode> node;
  FollowedNode view;  // its stored state as the host knows it
};

bool is_real64(RealFormat f) { return f == RealFormat::Real64; }

// The set command that carries slot `s` of layer `lid` (type `type`) in
// format `f` (docs/verse_wire.md section 7).
vgc::Command slot_command(std::uint16_t lid, std::uint8_t type, std::uint32_t e, const vgc::Slot& s, RealFormat f) {
  switch (static_cast<LayerType>(type)) {
    case LayerType::VertexXyz:
      if (is_real64(f)) return cmd::VertexSetXyzReal64{lid, e, s.r[0], s.r[1], s.r[2]};
      return cmd::VertexSetXyzReal32{lid, e, static_cast<float>(s.r[0]), static_cast<float>(s.r[1]),
                                     static_cast<float>(s.r[2])};
    case LayerType::VertexUint32: return cmd::VertexSetUint32{lid, e, s.u[0]};
    case LayerType::VertexReal:
      if (is_real64(f)) return cmd::VertexSetReal64{lid, e, s.r[0]};
      return cmd::VertexSetReal32{lid, e, static_cast<float>(s.r[0])};
    case LayerType::PolygonCornerUint32: return cmd::PolygonSetCornerUint32{lid, e, s.u};
    case LayerType::PolygonCornerReal:
      if (is_real64(f)) return cmd::PolygonSetCornerReal64{lid, e, s.r};
      return cmd::PolygonSetCornerReal32{lid, e,
                                         {static_cast<float>(s.r[0]), static_cast<float>(s.r[1]),
                                          static_cast<float>(s.r[2]), static_cast<float>(s.r[3])}};
    case LayerType::PolygonFaceUint8: return cmd::PolygonSetFaceUint8{lid, e, static_cast<std::uint8_t>(s.u[0])};
    case LayerType::PolygonFaceUint32: return cmd::PolygonSetFaceUint32{lid, e, s.u[0]};
    case LayerType::PolygonFaceReal:
      if (is_real64(f)) return cmd::PolygonSetFaceReal64{lid, e, s.r[0]};
      return cmd::PolygonSetFaceReal32{lid, e, static_cast<float>(s.r[0])};
  }
  return cmd::VertexSetUint32{lid, e, s.u[0]};
}

cmd::BoneCreate bone_command(const vgc::Bone& b) {
  return cmd::BoneCreate{b.id, b.weight, b.reference, b.parent, b.pos, b.pos_label, b.rot, b.rot_label};
}

cmd::LayerCreate layer_command(std::uint16_t id, const LayerInfo& l) {
  return cmd::LayerCreate{id, l.name, l.type, l.def_uint, l.def_real};
}

}  // namespace

std::unique_ptr<HostedNode> make_reference_hosted_node() { return std::make_unique<ReferenceHostedNode>(); }

struct Host::Impl {
  HostOptions options;
  UdpSocket socket;
  RsaKey key;
  std::map<PeerAddress, Session> sessions;
  std::map<std::uint32_t, HostedGeometry> nodes;
  std::uint32_t next_node_id = 0;
  Counters counters;

  // Sessions the host ended on its own (out of step, silent): a peer still
  // sending gets connect_terminate again, at most once a resend interval,
  // for session_timeout_s (the first may have been lost). At most 256.
  struct Dropped {
    std::unique_ptr<Channel> channel;  // its key and next packet id
    std::string bye;
    Clock::time_point until, last_sent;
  };
  std::map<PeerAddress, Dropped> dropped;

  Clock::duration seconds(double s) const {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
  }

  void send_terminate(const PeerAddress& peer, Dropped& d, Clock::time_point now) {
    std::string clear;
    if (!encode_command(wire::ConnectTerminate{d.bye}, &clear).ok()) return;
    (void)socket.send_to(peer, d.channel->raw_datagram(d.channel->take_raw_id(), clear));
    ++counters.packets_sent;
    ++counters.terminates_sent;
    d.last_sent = now;
  }

  // Ends a session the host can no longer serve and tells its client, in
  // a data packet under the session's next id, as r6 sends
  // connect_terminate (v_connect.c v_send_hidden_connect_terminate).
  void terminate_session(const PeerAddress& peer, const std::string& why, Clock::time_point now) {
    auto it = sessions.find(peer);
    if (it == sessions.end()) return;
    Session& s = it->second;
    log("session " + peer.to_string() + " dropped: " + why);
    if (s.connected && s.channel) {
      flush(s, now);
      Dropped d;
      d.channel = std::move(s.channel);
      d.bye = "vgc serve --verse dropped this session: " + why;
      d.until = now + seconds(options.session_timeout_s);
      send_terminate(peer, d, now);
      if (dropped.size() >= 256 && !dropped.count(peer)) {
        auto oldest = dropped.begin();
        for (auto i = dropped.begin(); i != dropped.end(); ++i)
          if (i->second.until < oldest->second.until) oldest = i;
        dropped.erase(oldest);
      }
      dropped[peer] = std::move(d);
    }
    sessions.erase(it);
  }

  void log(const std::string& s) const {
    if (options.log) options.log(s);
  }

  void send_to(Session& s, const WireCommand& c) {
    std::string bytes;
    Status st = encode_command(c, &bytes, s.bone_form);
    if (st.code == Status::Code::ProtocolError && s.bone_form == BoneForm::R6) {
      // A rotation r6's form cannot carry: the bone goes without it, as an r6 host would hold it.
      if (const auto* g = std::get_if<wire::Geometry>(&c))
        if (const auto* b = std::get_if<cmd::BoneCreate>(&g->command)) {
          cmd::BoneCreate plain = *b;
          plain.rot = {0, 0, 0, 1};
          st = encode_command(wire::Geometry{g->node_id, plain}, &bytes, s.bone_form);
        }
    }
    if (st.ok()) st = s.channel->queue(std::move(bytes));
    if (!st.ok()) log("cannot send " + describe(c) + " to " + s.peer.to_string() + ": " + st.detail);
  }

  void flush(Session& s, Clock::time_point now) {
    if (!s.channel) return;
    for (const std::string& d : s.channel->take_datagrams(now)) {
      (void)socket.send_to(s.peer, d);
      ++counters.packets_sent;
    }
  }

  std::uint32_t new_node_id() {
    if (!options.reuse_node_ids) return next_node_id++;
    std::set<std::uint32_t> used;  // r6: one table for avatars and nodes, the lowest free slot
    for (const auto& [peer, s] : sessions) used.insert(s.avatar);
    for (const auto& [id, g] : nodes) used.insert(id);
    std::uint32_t id = 0;
    while (used.count(id)) ++id;
    return id;
  }

  // --- login (docs/verse_wire.md section 2) ---------------------------------
  void on_login_packet(const PeerAddress& from, const std::uint8_t* data, std::size_t size, Clock::time_point now) {
    LoginMessage m;
    Status st = parse_login_packet(data, size, &m);
    if (!st.ok()) {
      ++counters.protocol_errors;
      log("protocol-error from " + from.to_string() + ": " + st.detail);
      return;
    }
    auto it = sessions.find(from);
    if (it != sessions.end()) it->second.last_heard = now;
    if (const auto* c = std::get_if<login::Contact>(&m)) {
      if (it != sessions.end() && !it->second.connected) {  // repeated stage 0: same answer again
        (void)socket.send_to(from, it->second.challenge_packet);
        return;
      }
      if (it != sessions.end()) drop_session(from, "a new login from the same address");
      dropped.erase(from);
      Session s;
      s.peer = from;
      s.avatar = new_node_id();
      s.data_key = make_data_key();
      s.last_heard = now;
      login::Challenge ch;
      ch.seconds = static_cast<std::uint32_t>(std::time(nullptr));
      ch.e = key.e;
      ch.n = key.n;
      s.challenge_packet = build_login_packet(ch);
      // The client's key is needed for the accept: keep it in the accept slot until then.
      KeyBytes clear_key{};
      std::copy(s.data_key.begin(), s.data_key.end(), clear_key.begin());
      login::Accept a;
      a.avatar = s.avatar;
      st = rsa_apply(clear_key, c->e, c->n, &a.encrypted_data_key);
      if (!st.ok()) {
        ++counters.protocol_errors;
        log("login from " + from.to_string() + " refused: its key is unusable: " + st.detail);
        return;
      }
      s.accept_packet = build_login_packet(a);
      (void)socket.send_to(from, s.challenge_packet);
      sessions[from] = std::move(s);
      return;
    }
    if (std::holds_alternative<login::Login>(m)) {
      if (it == sessions.end()) return;  // no stage 0 seen: r6 ignores it too
      Session& s = it->second;
      if (!s.connected) {
        KeyBytes block{};
        st = rsa_apply(std::get<login::Login>(m).encrypted, key.d, key.n, &block);
        std::string name, password;
        if (st.ok()) st = read_login_block(block, &name, &password);
        if (!st.ok()) {
          ++counters.protocol_errors;
          log("login from " + from.to_string() + " refused: " + st.detail);
          sessions.erase(it);
          return;
        }
        s.connected = true;
        s.channel = std::make_unique<Channel>(s.data_key, options.resend_interval_s);
        s.channel->set_bone_form(options.bone_form, !options.strict_bone_form);
        s.bone_form = options.bone_form;
        ++counters.logins;
        log("login: " + from.to_string() + " as '" + name + "', avatar " + std::to_string(s.avatar));
      }
      (void)socket.send_to(from, s.accept_packet);  // first time, or the accept was lost
      return;
    }
    // Challenge, Accept, Terminate are a host's or a client's answers: not for a host.
  }

  void drop_session(const PeerAddress& peer, const std::string& why) {
    auto it = sessions.find(peer);
    if (it == sessions.end()) return;
    if (it->second.connected) log("session " + peer.to_string() + " ended: " + why);
    sessions.erase(it);
  }

  // --- node commands (section 3) --------------------------------------------
  void send_node_create_to_index(const HostedGeometry& g) {
    for (auto& [peer, s] : sessions)
      if (s.connected && s.index_geometry)
        send_to(s, wire::NodeCreate{g.id, kNodeTypeGeometry, s.avatar == g.owner ? kOwnerMine : kOwnerOther});
  }

  void send_node_content(Session& s, const HostedGeometry& g) {
    const NodeState& state = g.view.state();
    for (const auto& [lid, l] : state.layers) {
      cmd::LayerCreate c = layer_command(lid, l);
      if (options.xyz_no_default && c.type == static_cast<std::uint8_t>(LayerType::VertexXyz)) c.def_real = 0;
      send_to(s, wire::Geometry{g.id, c});
    }
    send_to(s, wire::Geometry{g.id, cmd::CreaseSetVertex{state.crease_vertex.layer, state.crease_vertex.def_crease}});
    send_to(s, wire::Geometry{g.id, cmd::CreaseSetEdge{state.crease_edge.layer, state.crease_edge.def_crease}});
    for (const auto& [bid, b] : state.bones) send_to(s, wire::Geometry{g.id, bone_command(b)});
    send_to(s, wire::NodeNameSet{g.id, g.name});
  }

  void send_layer_content(Session& s, const HostedGeometry& g, std::uint16_t lid, RealFormat f) {
    const NodeState& state = g.view.state();
    auto l = state.layers.find(lid);
    if (l == state.layers.end()) return;
    auto slots = state.slots.find(lid);
    if (slots == state.slots.end()) return;
    const vgc::Slot def = layer_default_slot(lid, l->second);
    for (const auto& [e, slot] : slots->second)
      if (lid <= 1 || !slot_equal(l->second.type, slot, def))
        send_to(s, wire::Geometry{g.id, slot_command(lid, l->second.type, e, slot, f)});
  }

  void on_command(Session& s, WireCommand&& c) {
    if (auto* x = std::get_if<wire::NodeIndexSubscribe>(&c)) {
      s.index_geometry = (x->mask >> kNodeTypeGeometry) & 1u;
      if (s.index_geometry)
        for (const auto& [id, g] : nodes)
          send_to(s, wire::NodeCreate{id, kNodeTypeGeometry, g.owner == s.avatar ? kOwnerMine : kOwnerOther});
    } else if (auto* x = std::get_if<wire::NodeCreate>(&c)) {
      if (x->type != kNodeTypeGeometry) {
        log("node_create of type " + std::to_string(x->type) + " ignored: this host serves geometry nodes only");
        return;
      }
      HostedGeometry g;
      std::string error;
      g.node = options.make_node ? options.make_node(&error) : make_reference_hosted_node();
      if (!g.node) {
        log("node_create failed: " + error);
        return;
      }
      Status st = g.view.open(*g.node, options.verify_min_commands);
      if (!st.ok()) {
        log("node_create failed: the new node's snapshot: " + st.detail);
        return;
      }
      counters.whole_snapshots += g.view.counters().whole_reads;
      g.id = new_node_id();
      g.owner = s.avatar;
      g.name = "Geometry_Node_" + std::to_string(g.id);
      ++counters.nodes;
      const std::uint32_t id = g.id;
      nodes[id] = std::move(g);
      log("node " + std::to_string(id) + " created by avatar " + std::to_string(s.avatar));
      send_node_create_to_index(nodes[id]);
    } else if (auto* x = std::get_if<wire::NodeDestroy>(&c)) {
      if (!nodes.erase(x->node_id)) return;
      for (auto& [peer, other] : sessions) {
        other.node_subs.erase(x->node_id);
        for (auto it = other.layer_subs.begin(); it != other.layer_subs.end();)
          it = it->first.first == x->node_id ? other.layer_subs.erase(it) : std::next(it);
        for (auto it = other.layer_subs_kept.begin(); it != other.layer_subs_kept.end();)
          it = it->first.first == x->node_id ? other.layer_subs_kept.erase(it) : std::next(it);
        if (other.connected && other.index_geometry) send_to(other, wire::NodeDestroy{x->node_id});
      }
    } else if (auto* x = std::get_if<wire::NodeSubscribe>(&c)) {
      auto g = nodes.find(x->node_id);
      if (g == nodes.end()) return;
      s.node_subs.insert(x->node_id);
      send_node_content(s, g->second);
    } else if (auto* x = std::get_if<wire::NodeUnsubscribe>(&c)) {
      s.node_subs.erase(x->node_id);
      for (auto it = s.layer_subs.begin(); it != s.layer_subs.end();)
        it = it->first.first == x->node_id ? s.layer_subs.erase(it) : std::next(it);
      for (auto it = s.layer_subs_kept.begin(); it != s.layer_subs_kept.end();)
        it = it->first.first == x->node_id ? s.layer_subs_kept.erase(it) : std::next(it);
    } else if (auto* x = std::get_if<wire::NodeNameSet>(&c)) {
      auto g = nodes.find(x->node_id);
      if (g == nodes.end() || x->name.empty()) return;
      g->second.name = x->name;
      for (auto& [peer, other] : sessions)
        if (other.connected && other.node_subs.count(x->node_id)) send_to(other, *x);
    } else if (auto* x = std::get_if<wire::Geometry>(&c)) {
      on_geometry(s, *x);
    } else if (std::holds_alternative<wire::ConnectTerminate>(c)) {
      terminated = true;
    }
    // tag_group_create: no tags here; acks and naks never reach this point.
  }

  bool terminated = false;

  void on_geometry(Session& s, const wire::Geometry& x) {
    auto it = nodes.find(x.node_id);
    if (it == nodes.end()) return;  // r6: a command for no node is dropped
    HostedGeometry& g = it->second;
    std::string error;
    const bool failed = !g.node->apply(x.command, &error);
    if (failed)
      log("node " + std::to_string(g.id) + " failed on " + std::string(command_verb(x.command)) + ": " + error);
    StateChange change;
    const FollowedNode::Counters was = g.view.counters();
    Status st = g.view.follow(*g.node, x.command, failed, &change);
    const FollowedNode::Counters now = g.view.counters();
    counters.followed_by_digest += now.by_digest - was.by_digest;
    counters.whole_snapshots += now.whole_reads - was.whole_reads;
    if (!st.ok()) {
      log("node " + std::to_string(g.id) + ": " + st.detail);
      return;
    }
    // Before `failed`: the r6 deviation announces a delete the node refused.
    if (const auto* del = std::get_if<cmd::VertexDelete>(&x.command); del && options.announce_missing_deletes) {
      const auto live_in = [&](const NodeState& st) {
        const auto base = st.slots.find(0);
        return base != st.slots.end() && base->second.count(del->vertex_id) > 0;
      };
      if (!live_in(change.before) && !live_in(g.view.state()))
        for (auto& [peer, other] : sessions)
          if (const auto f = other.layer_subs.find({g.id, 0}); other.connected && f != other.layer_subs.end())
            send_to(other, wire::Geometry{g.id, is_real64(f->second) ? vgc::Command(cmd::VertexSetXyzReal64{
                                                                           0, del->vertex_id, DBL_MAX, DBL_MAX, DBL_MAX})
                                                                     : vgc::Command(cmd::VertexDelete{del->vertex_id})});
    }
    if (failed) return;
    broadcast_changes(g, change.before, change.after);
    if (const auto* sub = std::get_if<cmd::LayerSubscribe>(&x.command)) {
      if (sub->real_format <= 1 && g.view.state().layers.count(sub->layer_id)) {
        const RealFormat f = static_cast<RealFormat>(sub->real_format);
        const auto old = s.layer_subs.find({g.id, sub->layer_id});
        if (options.both_formats && old != s.layer_subs.end() && old->second != f)
          s.layer_subs_kept[{g.id, sub->layer_id}] = old->second;
        s.layer_subs[{g.id, sub->layer_id}] = f;
        send_layer_content(s, g, sub->layer_id, f);
      }
    } else if (const auto* un = std::get_if<cmd::LayerUnsubscribe>(&x.command)) {
      s.layer_subs.erase({g.id, un->layer_id});
      s.layer_subs_kept.erase({g.id, un->layer_id});
    }
  }

  // Section 7: each difference between `before` and `after` (the whole
  // states, or the parts a command changed: followed_node.h), to the
  // sessions that subscribed to the node (layers, creases, bones) or to the
  // layer (data).
  void broadcast_changes(HostedGeometry& g, const NodeState& before, const NodeState& after) {
    std::vector<vgc::Command> node_level;
    std::set<std::uint16_t> reset_layers;  // created anew, re-typed or destroyed: their subscriptions end (r6)
    for (const auto& [lid, l] : after.layers) {
      auto b = before.layers.find(lid);
      if (b == before.layers.end() || !(b->second == l)) node_level.push_back(layer_command(lid, l));
      if (b == before.layers.end() || b->second.type != l.type) reset_layers.insert(lid);
    }
    for (const auto& [lid, l] : before.layers)
      if (!after.layers.count(lid)) {
        node_level.push_back(cmd::LayerDestroy{lid});
        reset_layers.insert(lid);
      }
    if (!(before.crease_vertex.layer == after.crease_vertex.layer &&
          before.crease_vertex.def_crease == after.crease_vertex.def_crease))
      node_level.push_back(cmd::CreaseSetVertex{after.crease_vertex.layer, after.crease_vertex.def_crease});
    if (!(before.crease_edge.layer == after.crease_edge.layer &&
          before.crease_edge.def_crease == after.crease_edge.def_crease))
      node_level.push_back(cmd::CreaseSetEdge{after.crease_edge.layer, after.crease_edge.def_crease});
    for (const auto& [bid, b] : after.bones) {
      auto old = before.bones.find(bid);
      const cmd::BoneCreate now = bone_command(b);
      if (old == before.bones.end() || !bit_equal(vgc::Command(bone_command(old->second)), vgc::Command(now)))
        node_level.push_back(now);
    }
    for (const auto& [bid, b] : before.bones)
      if (!after.bones.count(bid)) node_level.push_back(cmd::BoneDestroy{bid});

    for (auto& [peer, s] : sessions) {
      if (!s.connected) continue;
      if (s.node_subs.count(g.id))
        for (const vgc::Command& c : node_level) send_to(s, wire::Geometry{g.id, c});
      for (std::uint16_t lid : reset_layers) s.layer_subs.erase({g.id, lid}), s.layer_subs_kept.erase({g.id, lid});
    }

    static const std::map<std::uint32_t, vgc::Slot> kEmpty;
    for (const auto& [lid, l] : after.layers) {
      std::vector<std::pair<Session*, RealFormat>> subs;
      for (auto& [peer, s] : sessions) {
        auto f = s.layer_subs.find({g.id, lid});
        if (s.connected && f != s.layer_subs.end()) subs.emplace_back(&s, f->second);
        auto k = s.layer_subs_kept.find({g.id, lid});
        if (s.connected && k != s.layer_subs_kept.end()) subs.emplace_back(&s, k->second);
      }
      if (subs.empty()) continue;
      auto a_it = after.slots.find(lid);
      auto b_it = before.slots.find(lid);
      const auto& a_slots = a_it == after.slots.end() ? kEmpty : a_it->second;
      const auto& b_slots = b_it == before.slots.end() ? kEmpty : b_it->second;
      const vgc::Slot def = layer_default_slot(lid, l);
      for (const auto& [e, slot] : a_slots) {
        auto old = b_slots.find(e);
        const bool changed = old == b_slots.end() ? (lid <= 1 || !slot_equal(l.type, slot, def))
                                                  : !slot_equal(l.type, slot, old->second);
        if (!changed) continue;
        for (auto& [s, f] : subs) send_to(*s, wire::Geometry{g.id, slot_command(lid, l.type, e, slot, f)});
      }
      if (lid > 1) continue;  // an element's other slots go with it: the base delete says so
      for (const auto& [e, slot] : b_slots) {
        if (a_slots.count(e)) continue;
        for (auto& [s, f] : subs) {
          if (lid == 1) send_to(*s, wire::Geometry{g.id, cmd::PolygonDelete{e}});
          else if (is_real64(f)) send_to(*s, wire::Geometry{g.id, cmd::VertexSetXyzReal64{0, e, DBL_MAX, DBL_MAX, DBL_MAX}});
          else send_to(*s, wire::Geometry{g.id, cmd::VertexDelete{e}});
        }
      }
    }
  }

  // --- the loop -------------------------------------------------------------
  void on_datagram(const PeerAddress& from, const std::string& bytes, Clock::time_point now) {
    ++counters.packets_received;
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    const bool login_id = bytes.size() >= 4 && data[0] == 0 && data[1] == 0 && data[2] == 0 && data[3] <= 1;
    auto it = sessions.find(from);
    if (!login_id && it == sessions.end()) {
      if (auto d = dropped.find(from); d != dropped.end()) {  // a peer still sending after its session ended
        if (now - d->second.last_sent >= seconds(options.resend_interval_s)) send_terminate(from, d->second, now);
        return;
      }
    }
    if (login_id || it == sessions.end() || !it->second.connected) {
      on_login_packet(from, data, bytes.size(), now);
      return;
    }
    Session& s = it->second;
    s.last_heard = now;
    std::vector<WireCommand> got;
    const std::size_t other_before = s.channel->counters().other_bone_form;
    Status st = s.channel->on_datagram(data, bytes.size(), now, &got);
    if (s.channel->counters().other_bone_form != other_before && s.bone_form == options.bone_form) {
      s.bone_form = options.bone_form == BoneForm::Spec ? BoneForm::R6 : BoneForm::Spec;
      log("session " + from.to_string() + " sends bone_create in the " + bone_form_name(s.bone_form) +
          " form: it is answered in that form");
    }
    if (!st.ok()) {
      ++counters.protocol_errors;
      log("protocol-error from " + from.to_string() + ": " + st.detail);
    }
    if (s.channel->out_of_step()) {  // every later packet would be refused too: end it and say so
      terminate_session(from, s.channel->out_of_step_detail() + "; log in again", now);
      return;
    }
    terminated = false;
    order_packet(&got);  // one packet: creations before their uses (packet_order.h)
    for (WireCommand& c : got) {
      on_command(s, std::move(c));
      if (terminated) break;
    }
    if (terminated) drop_session(from, "connect_terminate");
  }

  void service(Clock::time_point now) {
    const auto limit = seconds(options.session_timeout_s);
    std::vector<PeerAddress> silent;
    for (auto& [peer, s] : sessions) {
      flush(s, now);
      const bool stuck = !s.connected || (s.channel && !s.channel->all_acknowledged());
      if (stuck && now - s.last_heard > limit) silent.push_back(peer);
    }
    for (const PeerAddress& peer : silent)  // told too, in case only its acks were lost
      terminate_session(peer, "silent for " + seconds_text(options.session_timeout_s), now);
    for (auto it = dropped.begin(); it != dropped.end();)
      it = now > it->second.until ? dropped.erase(it) : std::next(it);
  }

  Clock::time_point next_due() const {
    Clock::time_point due = Clock::time_point::max();
    for (const auto& [peer, s] : sessions)
      if (s.channel) due = std::min(due, s.channel->next_resend_due());
    return due;
  }
};

Host::Host() : impl_(std::make_unique<Impl>()) {}
Host::~Host() = default;

Status Host::open(const HostOptions& options) {
  impl_->options = options;
  Status st = impl_->socket.open(options.address, options.port);
  if (!st.ok()) return st;
  impl_->key = make_rsa_key();
  return {};
}

std::uint16_t Host::port() const { return impl_->socket.port(); }

Status Host::run_for(double timeout_s, const std::atomic<bool>* stop) {
  Impl& h = *impl_;
  if (!h.socket.is_open()) return Status::network_error("host is not open");
  if (!(timeout_s > 0)) timeout_s = 0;
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(std::min(timeout_s, 1e6)));
  for (;;) {
    Clock::time_point now = Clock::now();
    h.service(now);
    if (now >= deadline || (stop && stop->load())) return {};
    const Clock::time_point wake = std::min({deadline, h.next_due(), now + std::chrono::milliseconds(50)});
    std::string bytes;
    PeerAddress from;
    Status st = h.socket.receive(&bytes, &from, std::max(0.0, std::chrono::duration<double>(wake - now).count()));
    if (st.code == Status::Code::Timeout) continue;
    if (st.code == Status::Code::ProtocolError) {
      ++h.counters.protocol_errors;
      h.log(st.detail);
      continue;
    }
    if (!st.ok()) return st;
    h.on_datagram(from, bytes, Clock::now());
  }
}

Status Host::run(const std::atomic<bool>& stop) {
  while (!stop.load()) {
    Status st = run_for(0.2, &stop);
    if (!st.ok()) return st;
  }
  return {};
}

Host::Counters Host::counters() const { return impl_->counters; }

bool parse_listen_address(const std::string& text, std::string* address, std::uint16_t* port, std::string* error) {
  std::string addr = "127.0.0.1";
  std::string p = text;
  const std::size_t colon = text.rfind(':');
  if (colon != std::string::npos) {
    addr = text.substr(0, colon);
    p = text.substr(colon + 1);
    if (addr.empty()) {
      *error = "'" + text + "': empty address before ':' (write PORT or ADDR:PORT)";
      return false;
    }
  }
  unsigned long number = 0;
  const auto [end, ec] = std::from_chars(p.data(), p.data() + p.size(), number);
  if (p.empty() || ec != std::errc() || end != p.data() + p.size() || number > 65535) {
    *error = "'" + text + "': expected [ADDR:]PORT with PORT 0..65535 (0: any free port)";
    return false;
  }
  *address = addr;
  *port = static_cast<std::uint16_t>(number);
  return true;
}

}  // namespace vgc::verse
