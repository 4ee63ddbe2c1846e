// verse_host.h — a Verse r6 host serving geometry nodes over UDP: what
// `vgc serve --verse [ADDR:]PORT` runs.
//
// Spec: docs/verse_wire.md (login, commands, acknowledgements and section 7,
// what the host sends to subscribers); 000 section 2.6 for the node itself.
//
// Rationale: the node behind the wire is any HostedNode: the reference, or
// (from the command line) any vgc Implementation, a faulty plugin included.
// The host never trusts it to say what changed: after every geometry
// command it works out the node's snapshot (reference/node/snapshot.h)
// before and after and sends each subscriber the commands that carry the
// change, the way an r6 host sends what it applied. So a client sees
// exactly the stored state, whatever the node did. A command the node
// rejects changes nothing and sends nothing, as on r6 (no error on the
// wire). What changed is found at the cost of the command, not of the
// node's size, when the node offers a snapshot digest that confirms what
// the host's own reference predicts; otherwise by reading the whole
// snapshot (followed_node.h says how, and why that keeps the guarantee).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "command.h"
#include "wire_commands.h"
#include "wire_status.h"

namespace vgc::verse {

// One geometry node behind the host.
class HostedNode {
 public:
  virtual ~HostedNode() = default;
  // Applies (or drops) a command. false with *error when the node itself
  // failed (crashed plugin...): the host logs it and drops the node's session
  // traffic for that command.
  virtual bool apply(const vgc::Command& command, std::string* error) = 0;
  // The node's whole state as the snapshot document of reference/node/snapshot.h.
  virtual bool snapshot(std::string* text, std::string* error) = 0;
  // Whether snapshot_digest() answers: the digest of the snapshot it would
  // print now (document_digest.h; `?digest` of an exec program). A node
  // without one is read whole after every command (followed_node.h).
  virtual bool offers_digest() { return false; }
  virtual bool snapshot_digest(std::uint64_t* digest, std::string* error) {
    (void)digest;
    *error = "no digest offered";
    return false;
  }
};

// The reference node (reference/node/node.h) as a HostedNode.
std::unique_ptr<HostedNode> make_reference_hosted_node();

struct HostOptions {
  std::string address = "127.0.0.1";  // where to bind; "0.0.0.0" for every interface
  std::uint16_t port = 4950;           // 0: any free port (see Host::port())
  // Makes the node of each node_create(geometry); null: the reference.
  std::function<std::unique_ptr<HostedNode>(std::string* error)> make_node;
  // One line per event worth a person's eye (login, node created, protocol
  // error of a peer); null: silent.
  std::function<void(const std::string&)> log;
  // r6 behaviours a client must survive (docs/verse_wire.md section 7):
  // reuse_node_ids: a new node or avatar takes the lowest free id, so a
  // destroyed node's id comes back (r6 vs_add_new_node); otherwise ids are
  // never reused. bone_form: the bone_create form the host reads first and
  // sends a session until that session sends the other form. strict_bone_form:
  // as r6, a packet that does not parse in bone_form loses everything from
  // the command that did not decode (no second reading in the other form).
  bool reuse_node_ids = false;
  BoneForm bone_form = BoneForm::Spec;
  bool strict_bone_form = false;
  // r6 deviations from the spec, for tests of a client that must find them
  // (docs/verse_wire.md "Certifying r6"); none by default.
  // announce_missing_deletes: a vertex_delete of a vertex that is not live
  // is sent to layer 0's subscribers anyway, as r6 does (vs_node_geometry.c
  // callback_send_g_vertex_delete_real checks only its storage size).
  // xyz_no_default: a VERTEX_XYZ layer is announced to a new subscriber of
  // the node with def_real 0 (r6 keeps no default for one: its layer_create
  // sets def.real only for the other real types); those who watched the
  // layer's creation were sent the right one.
  // both_formats: a session that subscribes to a layer in one real format
  // and then in the other is served in both (r6 adds it to the second
  // list and never takes it off the first: every value comes twice).
  bool announce_missing_deletes = false;
  bool xyz_no_default = false;
  bool both_formats = false;
  // A session silent this long (while it owes acks or has not finished its
  // login) is dropped (r6: 30 s). A dropped session's client is told
  // (connect_terminate), and told again for this long if it keeps sending.
  double session_timeout_s = 30.0;
  double resend_interval_s = 0.25;
  // A node followed by its digest (followed_node.h) is still read whole at
  // least every max(this, its snapshot's lines) commands.
  std::size_t verify_min_commands = 1024;
};

class Host {
 public:
  Host();
  ~Host();
  Host(const Host&) = delete;
  Host& operator=(const Host&) = delete;

  // Binds the UDP socket and makes the host key. NetworkError when the
  // address does not resolve or the port is taken.
  Status open(const HostOptions& options);
  std::uint16_t port() const;  // the bound port (the chosen one for port 0)

  // Serves for up to timeout_s: receives, answers, resends. Returns ok
  // after the time (or earlier when stop becomes true); a peer's bad packet
  // is logged and counted, never returned.
  Status run_for(double timeout_s, const std::atomic<bool>* stop = nullptr);
  // Serves until *stop becomes true (checked at least every 50 ms).
  Status run(const std::atomic<bool>& stop);

  struct Counters {
    std::size_t logins = 0, nodes = 0, packets_received = 0, packets_sent = 0, protocol_errors = 0;
    // Geometry commands whose changes the node's digest confirmed, and
    // whole snapshots read (followed_node.h), over every node.
    std::size_t followed_by_digest = 0, whole_snapshots = 0;
    // connect_terminate packets sent to sessions the host dropped (out of
    // step: more than kMaxPacketGap packets lost in a row; silent).
    std::size_t terminates_sent = 0;
  };
  Counters counters() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Parses "[ADDR:]PORT" ("4950", "127.0.0.1:0", "localhost:4950"). false
// with *error for anything else.
bool parse_listen_address(const std::string& text, std::string* address, std::uint16_t* port, std::string* error);

}  // namespace vgc::verse
