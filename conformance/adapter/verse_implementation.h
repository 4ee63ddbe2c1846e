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
// reset(): the driver destroys the current geometry node and creates a new
// one (node_create), the observer subscribes to it; the fresh node is
// whatever the host then sends.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "implementation.h"
#include "verse_node_mirror.h"
#include "wire_commands.h"

namespace vgc {

namespace verse {
class ClientSession;
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

  // The geometry node the commands go to now (changes at every reset()),
  // and the bone_create form spoken: for `vgc fuzz wire` (fuzz/wire_fuzz.h),
  // which sends its own traffic to the same node from a session of its own.
  std::uint32_t node_id() const { return node_; }
  verse::BoneForm bone_form() const { return bone_form_; }

 private:
  Answer connect();
  Answer make_node(double create_timeout_s = 0);  // 0: the call time-out
  // Sends node_name_set(node, "vgc-barrier-<n>") on the driver and applies
  // what the observer receives until that echo; then, while the host
  // announced new layers, subscribes the observer to them and waits for the
  // observer's own barrier (their contents come before its echo).
  Answer settle(const std::string& what);
  Answer failed(CallStatus s, const std::string& detail);
  // --verse-bone-form auto: on the fresh node, a bone_create in the spec's
  // form (after the weight layer it needs); the host's broadcast of the bone
  // parses in the form the host speaks (Channel's other_bone_form). Sets
  // bone_form_ and leaves a fresh node.
  Answer probe_bone_form();
  void use_bone_form(verse::BoneForm f);
  void drain_driver();

  std::string spec_, login_, host_;
  std::uint16_t port_ = 0;
  OpenOptions options_;
  std::unique_ptr<verse::ClientSession> driver_, observer_;
  std::uint32_t node_ = 0;
  bool have_node_ = false;
  bool broken_ = true;  // reset() must log in again
  bool driver_lost_ = false;  // only the driver's session is gone: connect() keeps the observer
  std::uint64_t barrier_count_ = 0;
  bool ever_connected_ = false;
  std::string silent_since_;  // set when a host that answered before no longer answers a login
  VerseNodeMirror mirror_;
  verse::BoneForm bone_form_ = verse::BoneForm::Spec;
  bool bone_form_known_ = false;  // given as an option, or probed
  std::string bone_form_why_;     // for identity(): how the form was chosen
  std::string identity_;
  int release_ = 0;               // the host's release, once logged in (merge_identity)
};

}  // namespace vgc
