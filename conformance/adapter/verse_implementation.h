// verse_implementation.h — `--impl verse:[NAME@]HOST[:PORT]`: a live Verse
// host certified over its own wire protocol, with no glue.
//
// Spec: docs/adapters.md "The Verse wire route" (what it can and cannot
// judge, what a host must do); docs/spec_facts.md sections 3-4 and 8 (the
// commands as the wire encodes them, their aliases, no acknowledgements);
// docs/verse_wire.md (the protocol itself, verse/).
//
// Rationale: the adapter is a Verse client and nothing more, so what vgc
// certifies is what every client of the host sees. It holds two sessions
// with the host: the *driver* sends the suite's commands as the wire
// encodes them (verse/wire_commands.h; an alias is the same bytes as its
// command), including layer_subscribe and its unsubscribe alias, which
// therefore change only the driver's own subscriptions; the *observer*
// subscribes to the node and to every layer at REAL64 (also each layer the
// host announces later) and rebuilds the node from what the host sends it
// (verse_node_mirror.h). The snapshot the adapter answers is printed from
// that rebuilt state alone.
//
// Every command is answered `done` (a host acknowledges nothing, spec_facts
// section 8) after a round-trip barrier: the driver sends node_name_set
// (the node, "vgc-barrier-<n>") after the command, and the adapter waits
// for the observer to receive that name. A host processes a connection's
// commands in order and sends each subscriber its changes in order, so
// when the echo arrives everything the command changed has arrived too; a
// command the host dropped changed nothing. Every wait is bounded by the
// call time-out (OpenOptions::timeout_seconds): a host that stops
// answering is a Timeout, bytes that do not parse a ProtocolError, a host
// that ends the session a Crash, and the next reset() logs in again.
//
// Several commands before one barrier (issue 31): when the caller says
// which commands come next (expect_commands: the runner's case, a replay),
// apply() sends the next slot writes (vertex and polygon values, each
// writing one (layer, element) slot, no two the same slot or the same
// element's base slot (a write may create its element: r6 sends that as a
// layer-0 write), none asking the host to pick an id, at most 16) each in a packet of its own, optionally
// ended by one command that is no slot write (a layer, crease or bone
// command, a delete that cannot touch the batch's slots: may_end_batch),
// and then one barrier. What the observer received for the node is sorted
// by the slot each message writes (a message that writes no slot of the
// others is the ending command's), and each apply() of the batch is
// answered from its own messages, applied to the mirror only then, so the
// snapshot after each command is the one a barrier of its own would show.
// r6 sends a subscriber one message per address (command, node, layer,
// element) in an order of its own, so this is what it allows: distinct
// slots keep every message, and the order of messages across slots does
// not matter. A message no command of the batch explains sends the batch
// again one command per round trip on a fresh node (and no batch until the
// next reset); a command r6 misreads (may_desynchronise_r6) always has its
// own barrier. A step judged wrong on a batched answer is judged again
// alone (ProgramChecker), so a batch changes no verdict and no blame.
//
// reset(): the driver destroys the current geometry node and the next one
// is taken from a pool of fresh nodes made ahead, in batches
// (verse_node_pool.h: the driver's node_creates, the observer's
// subscriptions, three round trips for a batch instead of three per node);
// a fresh node is whatever the host sent for it.
//
// A host's broadcasts are its verdicts: what the observer received for the
// node before the echo is the Answer's `broadcast`, so a command whose
// effect the host announced counts as applied even when the state the
// observer built did not change (check_step.h).
//
// The late view (Implementation::offers_late_view): a third session,
// logged in once for the run (and again only when the host forgot it),
// subscribes to the node and every layer, REAL32 and REAL64, in one batch
// and one round trip, and builds the node from what the host sends it.
// What a session that subscribes late is sent must be what the watching
// session built: a host that changes state without telling its
// subscribers (r6 writes a new vertex's position into every XYZ layer
// silently) is seen only so. The late view prints the REAL64 view, with a
// slot whose REAL32 value is not the REAL64 value rounded to float taken
// from the REAL32 view (so either difference shows against the model).
// The same session also watches the base vertex layer of every pool node
// from the pool's making, subscribed at REAL32 and then at REAL64: a
// REAL32 value it is sent during the case means the host kept both
// subscriptions (r6 puts it on both lists and sends every value twice);
// late_view_wrong_format() says so (LAYER-SUBSCRIBE-1). That costs one
// round trip per pool batch.
//
// Load: every round trip waits for the host to be scheduled (r6 polls its
// socket in a loop), so on a loaded machine the run's time is its number of
// round trips (docs/verse_wire.md "Where the time of a wire run goes"):
// besides the pool, the observer follows the node index so that a driver
// session the host ended (its avatar node destroyed) is seen at once
// rather than after a second without acknowledgements, and a login while
// the other session is up makes that one wake the host (r6 otherwise
// answers a login only on its next one-second tick).
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "implementation.h"
#include "verse_node_mirror.h"
#include "verse_node_pool.h"
#include "wire_commands.h"

namespace vgc {

namespace verse {
class ClientSession;
struct ClientOptions;
}

// Parses "HOST", "HOST:PORT", "NAME@HOST[:PORT]" (the part after "verse:").
// Port 4950 when absent; name "vgc" when absent. false with *error.
bool parse_verse_address(const std::string& text, std::string* name, std::string* host, std::uint16_t* port,
                         std::string* error);

// What the Verse wire route cannot show (docs/adapters.md).
RouteLimits verse_route_limits();

class VerseImplementation final : public Implementation {
 public:
  // `spec` is the whole "verse:..." text (its name()). The login password
  // is $VERSE_PASSWORD, or "vgc" when unset (docs/adapters.md).
  VerseImplementation(const std::string& spec, const std::string& login_name, const std::string& host,
                      std::uint16_t port, const OpenOptions& options);
  ~VerseImplementation() override;

  // Logs both sessions in and makes the first node. Not Ok: why, in detail.
  Answer start();

  std::string name() const override { return spec_; }
  std::string identity() const override;
  std::string merge_identity() const override;
  Answer reset() override;
  Answer apply(const Command& c) override;
  Document snapshot() override;
  Document derived() override;
  RouteLimits limits() const override;
  void expect_commands(std::vector<Command> next) override;
  bool last_apply_batched() const override { return last_batched_; }
  bool offers_late_view() override { return true; }
  void use_late_view(bool on) override { late_view_ = on; }
  std::string late_view_wrong_format() override { return late_wrong_format_; }

  // The geometry node the commands go to now (changes at every reset()),
  // and the bone_create form spoken: for `vgc fuzz wire` (fuzz/wire/wire_fuzz.h),
  // which sends its own traffic to the same node from a session of its own.
  std::uint32_t node_id() const { return node_; }
  verse::BoneForm bone_form() const { return bone_form_; }
  // How many times the adapter waited for the host to answer (a round trip
  // through it: a node_create, a barrier): what a wire run's time is made
  // of on a loaded machine (docs/verse_wire.md "Where the time of a wire
  // run goes"). For tests and profiles.
  std::uint64_t round_trips() const { return round_trips_; }
  // How many commands apply() sent to the host (not counting those the
  // wire cannot carry), and how many times a session of the driver was
  // lost (the host ended it) and logged in again. With round_trips(): the
  // route's cost per command. With $VGC_VERSE_STATS set, the adapter
  // prints these on stderr when it ends, one line starting "verse route:"
  // (docs/verse_wire.md "Where the time of a wire run goes").
  std::uint64_t commands_sent() const { return commands_sent_; }
  std::uint64_t driver_logins() const { return driver_logins_; }
  // Batches (class comment, "Several commands before one barrier"): how
  // many were sent, the commands they held, and how many could not be told
  // apart by what the host sent (sent again one per round trip).
  std::uint64_t batches() const { return batches_; }
  std::uint64_t batched_commands() const { return batched_commands_; }
  std::uint64_t batch_fallbacks() const { return batch_fallbacks_; }

 private:
  Answer connect();
  // apply() of one command, with its own round trip.
  Answer apply_one(const Command& c);
  // Sends `batch` (each command in a packet of its own) before one round
  // trip, and sorts what the observer received for the node by the slot
  // each message writes: the first command is answered, the others wait in
  // pending_. A message no command of the batch explains (or a round trip
  // that failed) makes the batch be sent again one command per round trip
  // on a fresh node, and no batch is sent again until the next reset.
  // `tail`: the last command is no slot write (may_end_batch): every
  // message that writes none of the others' slots is its.
  Answer apply_batch(const std::vector<Command>& batch, bool tail);
  // Answers a command sent in a batch from what the host sent for it; the
  // first `counted` of them are what it told its subscribers (the rest
  // answered the observer's subscriptions).
  Answer answer_from_batch(const Command& c, const std::vector<verse::WireCommand>& received, std::size_t counted);
  // A fresh node brought to the state the answered commands made (each sent
  // again on its own), dropping what was sent ahead and not asked for.
  Answer rebuild();
  // The sessions' options; `nudger` (may be null) is the other session,
  // made to wake the host while this one awaits its login's accept.
  verse::ClientOptions session_options(verse::ClientSession* nudger) const;
  // Destroys the current node (if any) and takes a fresh one from the pool,
  // refilling it first when it is empty.
  Answer make_node(double create_timeout_s = 0);  // 0: the call time-out
  // A batch of nodes: the driver's node_creates, the observer's
  // subscriptions to them and to their layers (verse_node_pool.h).
  Answer refill_pool(double create_timeout_s);
  // Destroys these nodes (given back by the pool), without waiting.
  Answer destroy_nodes(const std::vector<std::uint32_t>& ids);
  // One command the observer received: geometry for the current node goes
  // to mirror_, for a pool node to its mirror; the node index to the pool
  // and to the watch on the driver's avatar. New layers of the current node
  // and of unsettled pool nodes go to new_layers_. false with *error when
  // the current node's mirror refuses it (a protocol error).
  bool absorb(const verse::WireCommand& w, std::string* error);
  // Absorbs what the observer has already received: the rest of the
  // datagram that held a round trip's echo, and any datagram read with it.
  // r6 sends a subscriber the commands of one pass of its loop in the
  // order of their addresses' hash slots, not in the order it ran them
  // (docs/verse_wire.md section 6), so the echo of a round trip can come
  // before, in the same datagram, what the commands before it changed.
  Answer absorb_arrived(const std::string& what);
  // The observer's own round trip on `node` (subscribed): what came before
  // its echo is absorbed.
  Answer observer_round_trip(std::uint32_t node, std::chrono::steady_clock::time_point deadline,
                             const std::string& what);
  // While new_layers_ is not empty: the observer subscribes to them and
  // makes a round trip on `node` (their contents come before its echo).
  Answer subscribe_new_layers(std::uint32_t node, std::chrono::steady_clock::time_point deadline,
                              const std::string& what);
  // Sends node_name_set(node, "vgc-barrier-<n>") on the driver and absorbs
  // what the observer receives until that echo; then subscribe_new_layers.
  Answer settle(const std::string& what);
  // Whether the observer's round trip on the node comes back within
  // `seconds`: a host that dropped the driver's session still answers it,
  // a host that stopped answering does not.
  // Sets *echoed when `is_echo` matches a command that came before it.
  bool observer_answers(double seconds, const std::function<bool(const verse::WireCommand&)>& is_echo, bool* echoed);
  Answer failed(CallStatus s, const std::string& detail);
  // --verse-bone-form auto: on the fresh node, a bone_create in the spec's
  // form (after the weight layer it needs); the host's broadcast of the bone
  // parses in the form the host speaks (Channel's other_bone_form). Sets
  // bone_form_ and leaves a fresh node.
  Answer probe_bone_form();
  void use_bone_form(verse::BoneForm f);
  void drain_driver();
  // The late view of the current node (class comment): logs the late
  // session in when it is not, once more when its round trip fails.
  Document late_snapshot();
  Document late_snapshot_once();
  // Logs the late subscriber in when it is not; false when it cannot be.
  bool ensure_late();

  std::string spec_, login_, host_;
  std::uint16_t port_ = 0;
  OpenOptions options_;
  std::unique_ptr<verse::ClientSession> driver_, observer_;
  std::unique_ptr<verse::ClientSession> late_;  // the late subscriber, made at its first use
  std::uint32_t late_node_ = 0;                 // the node it subscribed to last (0: none)
  bool late_view_ = false;                      // snapshot() answers the late view
  // Pool nodes whose layer 0 the late subscriber watches, subscribed at
  // REAL32 and then at REAL64 when the pool was made (class comment).
  std::set<std::uint32_t> late_watching_;
  std::string late_wrong_format_;  // what it was sent in the format it left (late_view_wrong_format)
  // The broadcasts of the command under way (apply(), until its echo): the
  // first one the observer received for the current node, printed.
  bool counting_broadcasts_ = false;
  std::string first_broadcast_;
  // What the host sent for the node while the last command settled, in the
  // order the mirror applied it (Answer::host_sent).
  std::vector<std::string> host_sent_;
  std::size_t host_sent_count_ = 0;
  std::uint32_t node_ = 0;
  bool have_node_ = false;
  bool broken_ = true;  // reset() must log in again
  bool driver_lost_ = false;  // only the driver's session is gone: connect() keeps the observer
  std::uint64_t barrier_count_ = 0;
  std::uint64_t round_trips_ = 0;
  std::uint64_t commands_sent_ = 0;   // commands_sent()
  std::uint64_t driver_logins_ = 0;   // driver_logins(): every login of the driver, the first included
  std::uint64_t driver_drops_ = 0;    // driver sessions the host ended (seen as such)
  std::uint64_t driver_drops_known_ = 0;  // ... after a command may_desynchronise_r6 (desync_risk_)
  std::uint64_t batches_ = 0, batched_commands_ = 0, batch_fallbacks_ = 0, rebuilds_ = 0;
  // Several commands before one barrier (class comment). expected_: what
  // the caller said comes next (expect_commands), each with its wire bytes
  // as the key apply() is matched by. pending_: commands sent ahead in a
  // batch, already settled, with what the observer received for each, not
  // yet asked for. since_fresh_: the commands the node was sent since it
  // was fresh and that were answered (what rebuild() sends again).
  struct Expected {
    std::string key;
    Command command;
  };
  struct Prepared {
    std::string key;
    Command command;
    std::vector<verse::WireCommand> received;
    std::size_t counted = 0;  // answer_from_batch
  };
  std::deque<Expected> expected_;
  std::deque<Prepared> pending_;
  std::vector<Command> since_fresh_;
  bool batch_off_ = false;           // a batch could not be told apart: none until the next reset
  bool last_batched_ = false;        // last_apply_batched
  // While a batch settles: the observer's messages for the current node are
  // kept here instead of being applied to mirror_.
  bool capturing_ = false;
  std::vector<verse::WireCommand> captured_;
  std::size_t capture_mark_ = 0;  // captured_ from here on answered the observer's subscriptions
  bool ever_connected_ = false;
  std::string silent_since_;  // set when a host that answered before no longer answers a login
  VerseNodeMirror mirror_;
  VerseNodePool pool_;
  std::set<std::pair<std::uint32_t, std::uint16_t>> new_layers_;  // (node, layer) to subscribe to
  // The driver's avatar node, as the observer reads the object index: a
  // node_destroy of it read after its node_create means the host ended the
  // driver's session.
  std::uint32_t driver_avatar_ = 0;
  bool driver_announced_ = false, driver_dropped_ = false;
  // A command sent since the last reset may have made r6 end the driver's
  // session (may_desynchronise_r6): the next reset checks the session.
  bool desync_risk_ = false;
  verse::BoneForm bone_form_ = verse::BoneForm::Spec;
  bool bone_form_known_ = false;  // given as an option, or probed
  std::string bone_form_why_;     // for identity(): how the form was chosen
  std::string identity_;
  int release_ = 0;               // the host's release, once logged in (merge_identity)
};

}  // namespace vgc
