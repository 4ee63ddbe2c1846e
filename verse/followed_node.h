// followed_node.h — the host's copy of one hosted node's stored state, kept
// up to date command by command at the cost of what each command changed,
// and the differences each command made (what the host broadcasts).
//
// Spec: docs/verse_wire.md section 7 (what a host sends its subscribers:
// every change of the stored state) and section 9 (`vgc serve --verse`);
// the snapshot digest of docs/adapters.md "?digest" (document_digest.h).
//
// Rationale (issue 28): the host serves any HostedNode (the reference, an
// exec child, a faulty plugin) and trusts none to say what it changed. It
// used to read and parse the node's whole snapshot after every command and
// compare it with the previous one: 0.5 ms a command at 3k vertices, 9.5 ms
// at 18k, hours for a real mesh. Now a reference node of the host's own (the
// model) is given every command too; its ChangeLog (node.h) names the
// snapshot lines the command may have changed, and its NodeDigest the
// snapshot's digest after it. When the hosted node answers a digest and it
// equals the model's, the two snapshots are equal (a 64-bit collision
// aside), so the changes are the model's lines of the ChangeLog: only those
// are compared and broadcast. Otherwise (no digest offered, another digest,
// a failed node, or the model out of step after an earlier difference) the
// whole snapshot is read and compared, as before; the host is back in step
// once a whole snapshot's digest equals the model's again. Trust is kept:
// a node whose state differs from what the model predicts is read whole,
// and even a node that answered the model's digest while holding something
// else (a lying digest) is read whole at least every max(verify_min_commands,
// its snapshot's lines) commands, which costs O(1) a command amortised and
// shows subscribers its real state within that many commands.
#pragma once

#include <cstddef>
#include <cstdint>

#include "document_digest.h"
#include "node.h"
#include "snapshot_state.h"
#include "verse_host.h"
#include "wire_status.h"

namespace vgc::verse {

// What one command changed: `before` and `after` hold the same identities
// (layers, slots, bones; the crease settings always), each as it was and as
// it is, absent where it does not exist. After a whole read they are the
// whole states.
struct StateChange {
  NodeState before, after;
  bool whole = false;  // read from the whole snapshot
};

class FollowedNode {
 public:
  // Reads `node`'s whole snapshot (a new node's). ProtocolError when it gives none.
  Status open(HostedNode& node, std::size_t verify_min_commands);
  const NodeState& state() const { return state_; }

  // After `command` was given to `node`. `node_failed`: the node itself
  // failed on it (its state is unknown; *out is left empty and the next
  // command reads the whole snapshot). ProtocolError when a whole snapshot
  // was needed and the node gave none (or one that does not parse).
  Status follow(HostedNode& node, const vgc::Command& command, bool node_failed, StateChange* out);

  struct Counters {
    std::size_t by_digest = 0;    // commands followed by the model, confirmed by the node's digest
    std::size_t whole_reads = 0;  // whole snapshots read (the first one included)
    std::size_t digest_differs = 0;  // the node's digest was not the model's
  };
  Counters counters() const { return counters_; }

 private:
  Status read_whole(HostedNode& node, StateChange* out);
  bool changed_lines(StateChange* out);  // false: read whole instead

  vgc::Node model_;
  vgc::NodeDigest model_digest_;
  vgc::ChangeLog changes_;
  NodeState state_;
  bool in_step_ = false;  // state_ is the model's
  std::size_t verify_min_ = 1024, since_whole_ = 0, verify_after_ = 1024;
  Counters counters_;
};

}  // namespace vgc::verse
