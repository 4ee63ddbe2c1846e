// implementation.h — the adapter boundary as the suite sees it.
//
// Spec: every command of docs/spec_facts.md, judged by the clauses of
// conformance/clauses (docs/clauses.md). docs/adapters.md is the contract for
// the two ways in from outside: exec:CMD (a program speaking the text
// command language on stdin/stdout) and plugin:PATH (the C ABI of
// vgc_plugin.h). "reference" is our own node, in process.
//
// Rationale: properties talk to an implementation only through this
// interface, so one property certifies every route the same way. Every
// call reports how the call itself went (CallStatus) separately from what
// the implementation answered, so a crash or a hang of the implementation
// under test is a result the suite records, never an exception or an abort.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "command.h"
#include "document_digest.h"

namespace vgc {

enum class CallStatus {
  Ok,             // the implementation answered
  Crash,          // it died (signal or exit) while answering
  Timeout,        // it did not answer within the time limit
  ProtocolError,  // it answered something the contract does not allow
};
const char* call_status_name(CallStatus s);

struct Answer {
  CallStatus status = CallStatus::Ok;
  bool applied = false;  // meaningful when status == Ok
  std::string reason;    // the reason name it gave for a rejection ("NO_SUCH_LAYER", ...)
  std::string detail;    // for a non-Ok status: what happened, for the report
  // status == Ok and the implementation said it could not parse the line
  // (exec: "error <message>", plugin: VGC_MALFORMED); applied is false,
  // reason is empty and detail holds its message. The suite only sends
  // canonical text, so this is a finding against the implementation.
  bool malformed = false;
  // false when status == Ok and the implementation answered `done` (exec) /
  // VGC_DONE (plugin): it processed the command but does not say whether it
  // applied or dropped it, as a host on the Verse wire, which sends no
  // acknowledgement and no error (README). applied is then false and reason
  // empty; check_step decides applied or not from the state.
  bool verdict_reported = true;
  // true when status == Ok and the route cannot carry the command at all
  // (the Verse wire cannot send a name with a NUL inside): nothing was sent,
  // the implementation's state is unchanged, and the step is not judged
  // (check_step.h); detail says why.
  bool not_sent = false;
  // For an answer `done` from a route that sees what the implementation
  // told others about the command (the Verse wire: what the host sent its
  // subscribers for it): the first such message, printed; empty when it
  // sent nothing. A host's broadcasts are its verdict: a command whose
  // effect it announced was applied, even when the state shows no change
  // (a delete of an element the watching session never saw). check_step.h.
  std::string broadcast;
  // For a route that watches what the implementation sends back (the Verse
  // wire): every message the host sent for the node after the command,
  // printed as a command, in the order the route's mirror applied them (the
  // first kHostSentKept; host_sent_count counts all). A finding on the step
  // carries them (Finding::host_sent), so a person reading it sees what the
  // host said, not only what vgc concluded. Empty when the host sent
  // nothing, and on routes that answer for themselves (exec, plugin).
  bool host_sent_seen = false;  // the route watched (host_sent is meaningful, empty or not)
  std::vector<std::string> host_sent;
  std::size_t host_sent_count = 0;
};
// How many of the messages a host sent for one command an Answer and a
// Finding keep (Answer::host_sent): a command writes at most a few slots;
// a host that floods is bounded.
inline constexpr std::size_t kHostSentKept = 16;

// The text documents of snapshot.h and derived_document.h, as the
// implementation printed them.
struct Document {
  Document() = default;
  Document(CallStatus s, std::string t, std::string d = {}) : status(s), text(std::move(t)), detail(std::move(d)) {}
  CallStatus status = CallStatus::Ok;
  std::string text;      // whole document including the final "end\n"
  std::string detail;
  // Set when the call stopped at a limit of vgc's (time, answer size), not
  // at anything the implementation did wrong: what to raise, e.g.
  // "--timeout". A finding then is a timeout, never a fail (issue 28).
  std::string limit;
};

// The answer to `?digest` (docs/adapters.md, document_digest.h): the digests
// of the two documents the implementation would print now.
struct DigestAnswer {
  CallStatus status = CallStatus::Ok;
  DocumentDigests digests;
  std::string detail;  // for a non-Ok status
};

// A limit of a route, said in the route's words: what it does not carry.
// Which clauses each keeps from being judged is said in one place, beside
// the rules' clauses (conformance/route_limit_clauses.h), so an adapter
// names no clause.
enum class RouteLimit {
  NoVerdicts,           // it acknowledges no command and reports no error: no verdicts, no reason codes
  SubscriptionsUnseen,  // a subscription is the subscriber's own state, and the route shows none
  NoRequests,           // it carries no optional capability request (docs/adapters.md section 5)
  BoneRotationUnsent,   // its bone_create carries no rotation (r6's form, docs/verse_wire.md section 4)
};

// What a route to an implementation cannot show, so that what it cannot
// show is reported as not judgeable (status `not-applicable`, with why)
// rather than passed or left unchecked. The exec, plugin and reference
// routes show everything (the default); the Verse wire route
// (verse_implementation.h) sees only what a host broadcasts to subscribers.
struct RouteLimits {
  std::string route;  // names the route in every note ("the Verse wire"); empty: no limits
  // false: the route carries no derived document (effective creases, bone
  // world poses); derived() is not called and what only it would show is
  // not judged. `why_no_derived` says why, for the notes.
  bool derived = true;
  std::string why_no_derived;
  // false: the snapshot's subscription column (a layer's real format, the
  // state of the connection that sent layer_subscribe) is not observable;
  // it is compared as "-" on both sides.
  bool subscriptions = true;
  // false: the route carries a command per packet exchange (the Verse
  // wire), so the properties at scale (10^4 to 10^5 commands a case) are
  // not run on it, and a property's cost is its cases. A profile an exec
  // program declares (declared_profile.h) leaves it true.
  bool at_scale = true;
  // The route's limits -> why, in the route's words (for the notes). The
  // clauses they keep from being judged (route_limit_clauses.h) are
  // reported `not-applicable` with the route and the why, unless a finding
  // was made in them.
  std::map<RouteLimit, std::string> cannot;
  // Clauses the route names itself -> why, reported alike: for a route
  // made in a test; the adapters say limits instead.
  std::map<std::string, std::string> clauses;
};

class Implementation {
 public:
  virtual ~Implementation() = default;
  // "reference", "exec:./my-host --serve", "plugin:/path/libx.so".
  virtual std::string name() const = 0;
  // Starts over with a fresh node (restarting a crashed process if need be).
  virtual Answer reset() = 0;
  virtual Answer apply(const Command& c) = 0;
  virtual Document snapshot() = 0;
  virtual Document derived() = 0;
  // What the implementation says it is: the free text of its ?hello answer
  // (exec), the table's name (plugin), or name(). For reports only.
  virtual std::string identity() const { return name(); }
  // What makes two runs runs of the same implementation, for `vgc merge`:
  // name() by default; for a host on the Verse wire its release and bone
  // form, not the address it listens on (one host per CI job, each on its
  // own port, is still one implementation).
  virtual std::string merge_identity() const { return name(); }
  // Starts a new instance (a new process for exec:) with a fresh node, so
  // that nothing the previous instance went through can matter: how a
  // finding is confirmed (confirm_finding.h). Default: reset(), for an
  // implementation that has no instance to restart.
  virtual Answer restart() { return reset(); }
  // Which instance is running: changes whenever a new one starts (exec: a
  // crashed or killed program is started again). Default 0: always one.
  virtual std::uint64_t instance() const { return 0; }
  // What this route cannot show (RouteLimits). Default: nothing hidden.
  virtual RouteLimits limits() const { return {}; }
  // One optional capability request (docs/adapters.md "Optional
  // capabilities"): "?capabilities", "?classify", "?subdivide <level>",
  // "?normals", ... (reference/geometry/capability_documents.h).
  // Ok with the whole document (ending in "end\n"), or Ok with one line
  // "error <message>\n" when the implementation refused the request (an
  // implementation that predates the requests answers so). The default
  // implements none: ProtocolError with detail "not supported".
  virtual Document request(const std::string& line) {
    (void)line;
    return {CallStatus::ProtocolError, {}, "not supported"};
  }
  // Whether the implementation answers `?digest` (exec: it claims the word
  // `digest` in ?capabilities, asked once). With it, checking a command
  // costs what the command changed (check_step.h ProgramChecker); without
  // it, both documents are read after every command. Default: no.
  virtual bool offers_digest() { return false; }
  // The next request()'s document is expected to be about `bytes` long
  // (certify --mesh: a derived answer on a mesh of 10^5 faces): an
  // out-of-process route scales its size and time limits to fit. Default:
  // nothing to scale.
  virtual void expect_answer_bytes(std::size_t bytes) { (void)bytes; }
  // The digests of its two documents now; only called when offers_digest().
  virtual DigestAnswer digest() { return {CallStatus::ProtocolError, {}, "not supported"}; }
  // The commands the next apply() calls will most likely ask for, in
  // order, the next one first (the runner's case: what is left of it);
  // replaces the previous list, and an empty list says nothing is known. A
  // route whose every command costs a round trip (the Verse wire) may send
  // several of them before one round trip and answer each apply() from
  // what came back; apply() of another command than the one sent next
  // puts the implementation back in the state the answered commands made
  // (docs/verse_wire.md "Several commands before one barrier"). Default:
  // ignored.
  virtual void expect_commands(std::vector<Command> next) { (void)next; }
  // Whether the last apply() was answered from such a batch: a step judged
  // wrong on it is judged again with the command sent on its own
  // (ProgramChecker), so a batch never changes a verdict or its blame.
  virtual bool last_apply_batched() const { return false; }
  // Whether the route can show what a party that starts watching the node
  // now would be sent (the Verse wire: a session that subscribes late),
  // which can differ from what was sent to those that watched it all along
  // (the snapshot). Default: no (the route shows the stored state itself).
  virtual bool offers_late_view() { return false; }
  // While on, snapshot() answers that late view (program_checker.h judges
  // it at the end of every case and localizes a difference). Only called
  // when offers_late_view().
  virtual void use_late_view(bool on) { (void)on; }
  // Read with the late view: what a party that subscribed to the node's
  // base vertex layer at REAL32 and then at REAL64, before the case, was
  // sent during it in the format it left (a REAL32 value: the host kept
  // both subscriptions, as r6 does), printed; empty when nothing.
  virtual std::string late_view_wrong_format() { return {}; }
};

struct OpenOptions {
  // Per call, for out-of-process implementations (the --timeout option).
  double timeout_seconds = 5.0;
  // Starting one (the --start-timeout option): an exec program or an
  // isolated plugin's child until its ?hello answer, a Verse host's login;
  // each start, restarts included. Separate from the per-call limit and
  // generous: a Python program or a JVM on a loaded CI runner takes seconds
  // to start, and a start that is cut short is no finding, only a run that
  // cannot begin (issue 31, item 3).
  double start_timeout_seconds = 60.0;
  bool isolate_plugin = true;    // plugin: run it in a child process (vgc serve)
  // The vgc executable that serves an isolated plugin (`vgc serve --impl
  // plugin:PATH`). Empty: the running program (/proc/self/exe), which is
  // right inside vgc itself; tests and other programs set it.
  std::string vgc_binary;
  // Longest answer line or document accepted from an out-of-process
  // implementation; a longer one is a ProtocolError (bounds our memory).
  std::size_t max_answer_bytes = std::size_t{64} << 20;
  // verse: the bone_create form to speak (docs/verse_wire.md section 4):
  // "auto" (the form the host answers a probe in), "spec" or "r6".
  std::string verse_bone_form = "auto";
};

// Opens "reference", "exec:CMD", "plugin:PATH" or "verse:[NAME@]HOST[:PORT]"
// (parse_route, then open_route: route.h). Returns nullptr and sets
// *error for a malformed spec or one that cannot be started: a program that
// does not answer ?hello correctly within the timeout, a plugin that cannot
// be loaded (missing file, missing vgc_plugin_v1, other ABI version).
// An exec or isolated-plugin implementation is started here and restarted
// by reset() after a Crash, Timeout or ProtocolError.
std::unique_ptr<Implementation> open_implementation(const std::string& spec, const OpenOptions& options,
                                                    std::string* error);

}  // namespace vgc
