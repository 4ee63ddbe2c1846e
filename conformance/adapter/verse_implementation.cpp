// verse_implementation.cpp — see verse_implementation.h.
#include "verse_implementation.h"

#include <charconv>
#include <chrono>
#include <map>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/core.h>

#include "cancel.h"
#include "command_text.h"
#include "verse_client.h"
#include "wire_commands.h"

namespace vgc {
namespace {

using Clock = std::chrono::steady_clock;

// While waiting for a round trip: how often the driver's session is
// checked, and how long a packet may stay unacknowledged on loopback-speed
// hosts before the session counts as dropped (a host acks on receipt).
constexpr double kSessionCheckSeconds = 0.1;
constexpr double kDeadSessionSeconds = 1.0;
// reset()'s node_create on a session in use: a host that acknowledges but
// does not answer (r6 after running a node_index_subscribe decoded from
// garbage) gets a fresh login after this, not the whole --timeout.
constexpr double kFirstCreateSeconds = 1.0;
// Nodes made per batch for the pool (verse_node_pool.h): three round trips
// per batch. 16 node_creates fit one packet, and the host's answers to the
// observer's 16 subscriptions (five commands each) a few.
constexpr std::size_t kPoolBatch = 16;
// The cells a judged node's mirror keeps (VerseNodeMirror's default).
constexpr std::size_t kMirrorCells = std::size_t{1} << 22;

// "5 s (--timeout)": a limit as the message that reports it names it.
std::string limit_text(double seconds, const char* option) {
  return fmt::format("{:g} s ({})", seconds, option);
}

double seconds_left(Clock::time_point deadline) {
  return std::max(0.0, std::chrono::duration<double>(deadline - Clock::now()).count());
}

// Whether r6 may misread the packet that carries `c`: a string of 16 bytes
// or more in one of its 16-byte fields (docs/verse_wire.md section 1),
// after which r6 runs whatever the rest of the packet decodes to, which may
// end the session (connect_terminate). r6 runs that packet to its end and
// the barrier's packet after it before it forgets the session, so the
// command itself is judged; the next call finds the session gone.
bool may_desynchronise_r6(const Command& c) {
  const auto long_name = [](const std::string& s) { return s.size() > kMaxNameBytes; };
  if (const auto* l = std::get_if<cmd::LayerCreate>(&c)) return long_name(l->name);
  if (const auto* v = std::get_if<cmd::CreaseSetVertex>(&c)) return long_name(v->layer);
  if (const auto* e = std::get_if<cmd::CreaseSetEdge>(&c)) return long_name(e->layer);
  if (const auto* b = std::get_if<cmd::BoneCreate>(&c))
    return long_name(b->weight) || long_name(b->reference) || long_name(b->pos_label) || long_name(b->rot_label);
  return false;
}

// Commands sent before one round trip at most (each in a packet of its own).
constexpr std::size_t kMaxBatch = 16;

// The slot (layer, element) a command writes, as the host's message to a
// subscriber addresses it: r6 addresses every element command by its
// command number, node, layer and element (`v_cmd_buf_set_address_size`,
// 11 bytes), and a subscriber of one format gets one command number per
// layer, a delete sharing its set's address. nullopt for every other
// command (layers, creases, bones, subscriptions).
using WireSlot = std::pair<std::uint16_t, std::uint32_t>;

template <typename T>
struct HasLayerAndVertex {
  template <typename U>
  static auto test(int) -> decltype(std::declval<U>().layer_id, std::declval<U>().vertex_id, std::true_type{});
  template <typename>
  static std::false_type test(...);
  static constexpr bool value = decltype(test<T>(0))::value;
};
template <typename T>
struct HasLayerAndPolygon {
  template <typename U>
  static auto test(int) -> decltype(std::declval<U>().layer_id, std::declval<U>().polygon_id, std::true_type{});
  template <typename>
  static std::false_type test(...);
  static constexpr bool value = decltype(test<T>(0))::value;
};

std::optional<WireSlot> slot_of(const Command& c) {
  return std::visit(
      [](const auto& x) -> std::optional<WireSlot> {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, cmd::VertexDelete>) return WireSlot{0, x.vertex_id};
        else if constexpr (std::is_same_v<T, cmd::PolygonDelete>) return WireSlot{1, x.polygon_id};
        else if constexpr (HasLayerAndVertex<T>::value) return WireSlot{x.layer_id, x.vertex_id};
        else if constexpr (HasLayerAndPolygon<T>::value) return WireSlot{x.layer_id, x.polygon_id};
        else return std::nullopt;
      },
      c);
}

// The slots a slot write may make the host send a message for: its own,
// and its element's base slot (layer 0 for a vertex, layer 1 for a
// polygon), since a write for an element that is not live may create it:
// r6 takes a VERTEX_XYZ write on any layer for a vertex that is not live as
// the vertex's creation, writes it into every XYZ layer and sends it as a
// write of layer 0 (`vs_node_geometry.c` callback_send_g_vertex_set_xyz_*).
// A later write of that base slot in the same flush replaces r6's unsent
// message, so two commands of a batch may not share any of these slots.
std::vector<WireSlot> footprint_of(const Command& c) {
  const auto own = slot_of(c);
  if (!own) return {};
  std::vector<WireSlot> out{*own};
  const bool vertex = std::visit([](const auto& x) { return HasLayerAndVertex<std::decay_t<decltype(x)>>::value; }, c) ||
                      std::holds_alternative<cmd::VertexDelete>(c);
  const WireSlot base{static_cast<std::uint16_t>(vertex ? 0 : 1), own->second};
  if (base != *own) out.push_back(base);
  return out;
}

// Whether a command may share a round trip with others: it writes one
// slot and, by the spec, nothing else (a delete also removes its element's
// slots, and a vertex's polygons: it keeps its own round trip), it is no
// alias of a delete as the wire carries it, and r6 does not misread it.
bool batchable(const Command& c) {
  if (std::holds_alternative<cmd::VertexDelete>(c) || std::holds_alternative<cmd::PolygonDelete>(c)) return false;
  const auto slot = slot_of(c);
  // An element id of 0xFFFFFFFF asks the host to pick one: which slot its
  // message writes is the host's choice, so it keeps its own round trip.
  if (!slot || slot->second == 0xFFFFFFFFu || may_desynchronise_r6(c)) return false;
  return verse::wire_canonical(c).index() == c.index();
}

// Whether `t` may end a batch of slot writes (`slots`, one per command
// before it): every message the host sends for the node that is not a
// write of one of those slots is then `t`'s. So `t` writes none of them
// (a delete's own slot), and nothing it may cause by the spec lands on
// them: a layer, crease or bone command sends messages of their own kinds
// (and the observer's subscription to a new layer, made after the round
// trip, is `t`'s too, as on its own); a vertex_delete may delete polygons
// (layer 1 slots), so it ends only a batch that writes none. A command
// r6 misreads keeps its own round trip; so does an element id the host
// picks (0xFFFFFFFF: which slot it writes is the host's choice).
bool may_end_batch(const Command& t, const std::set<WireSlot>& slots) {
  if (may_desynchronise_r6(t)) return false;
  const Command c = verse::wire_canonical(t);
  if (std::holds_alternative<cmd::LayerCreate>(c) || std::holds_alternative<cmd::LayerDestroy>(c) ||
      std::holds_alternative<cmd::LayerSubscribe>(c) || std::holds_alternative<cmd::LayerUnsubscribe>(c) ||
      std::holds_alternative<cmd::CreaseSetVertex>(c) || std::holds_alternative<cmd::CreaseSetEdge>(c) ||
      std::holds_alternative<cmd::BoneCreate>(c) || std::holds_alternative<cmd::BoneDestroy>(c))
    return true;
  if (const auto* p = std::get_if<cmd::PolygonDelete>(&c))
    return p->polygon_id != 0xFFFFFFFFu && !slots.count(WireSlot{1, p->polygon_id});
  if (const auto* v = std::get_if<cmd::VertexDelete>(&c)) {
    if (v->vertex_id == 0xFFFFFFFFu || slots.count(WireSlot{0, v->vertex_id})) return false;
    for (const WireSlot& s : slots)
      if (s.first == 1) return false;
    return true;
  }
  return false;
}

// The bytes the wire carries for `c` (on node 0): what apply() is matched
// with what was sent ahead by. false when the wire cannot carry it.
bool wire_key(const Command& c, verse::BoneForm form, std::string* key) {
  verse::wire::Geometry g;
  g.node_id = 0;
  g.command = c;
  key->clear();
  return verse::encode_command(g, key, form).ok();
}

// Whether `host` names this machine (then /proc/net/udp shows whether a
// process still holds the port).
bool is_local_host(const std::string& host) {
  return host == "localhost" || host.rfind("127.", 0) == 0 || host == "::1" || host == "[::1]";
}

// Whether some socket of this machine is bound to UDP `port`
// (/proc/net/udp and udp6: "sl local_address:PORT ..." in hex). A Verse
// host that stopped answering still holds its port; one whose process
// ended (a crash) holds nothing.
bool local_udp_port_bound(std::uint16_t port) {
  for (const char* table : {"/proc/net/udp", "/proc/net/udp6"}) {
    std::ifstream f(table);
    std::string line;
    std::getline(f, line);  // the header
    while (std::getline(f, line)) {
      std::istringstream words(line);
      std::string slot, local;
      if (!(words >> slot >> local)) continue;
      const auto colon = local.rfind(':');
      if (colon == std::string::npos) continue;
      unsigned value = 0;
      const char* first = local.data() + colon + 1;
      if (std::from_chars(first, local.data() + local.size(), value, 16).ec == std::errc() && value == port)
        return true;
    }
  }
  return false;
}

CallStatus call_status_of(const verse::Status& s) {
  switch (s.code) {
    case verse::Status::Code::Ok: return CallStatus::Ok;
    case verse::Status::Code::Timeout: return CallStatus::Timeout;
    case verse::Status::Code::ProtocolError: return CallStatus::ProtocolError;
    case verse::Status::Code::Closed:
    case verse::Status::Code::Dropped:
    case verse::Status::Code::NetworkError: return CallStatus::Crash;  // the session is gone
  }
  return CallStatus::Crash;
}

}  // namespace

bool parse_verse_address(const std::string& text, std::string* name, std::string* host, std::uint16_t* port,
                         std::string* error) {
  std::string rest = text;
  *name = "vgc";
  if (const auto at = rest.find('@'); at != std::string::npos) {
    *name = rest.substr(0, at);
    rest = rest.substr(at + 1);
    if (name->empty() || name->size() > 31) {
      *error = "the login name before '@' must be 1 to 31 bytes";
      return false;
    }
  }
  *port = verse::kDefaultPort;
  if (const auto colon = rest.rfind(':'); colon != std::string::npos) {
    const std::string digits = rest.substr(colon + 1);
    rest = rest.substr(0, colon);
    unsigned long v = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || v == 0 || v > 65535) {
      *error = "'" + digits + "' is not a port (1 to 65535; the Verse default is 4950)";
      return false;
    }
    *port = static_cast<std::uint16_t>(v);
  }
  if (rest.empty()) {
    *error = "no host named (verse:HOST[:PORT], e.g. verse:localhost or verse:127.0.0.1:4950)";
    return false;
  }
  *host = rest;
  return true;
}

RouteLimits verse_route_limits() {
  RouteLimits l;
  l.route = "the Verse wire";
  l.derived = false;
  l.why_no_derived = "the Verse wire carries only stored state (no effective creases, no bone world poses)";
  l.subscriptions = false;
  l.at_scale = false;
  l.cannot[RouteLimit::NoVerdicts] =
      "a Verse host acknowledges nothing and reports no error, so it gives no reason codes (docs/spec_facts.md "
      "section 8)";
  l.cannot[RouteLimit::SubscriptionsUnseen] =
      "a subscription is the subscriber's own state; a host broadcasts none, and what it sends the subscriber "
      "is not compared";
  l.cannot[RouteLimit::NoRequests] =
      "an optional capability asked with a request (docs/adapters.md section 5); the Verse wire has no such "
      "request (no subdivision, classification or normals)";
  return l;
}

VerseImplementation::VerseImplementation(const std::string& spec, const std::string& login_name,
                                         const std::string& host, std::uint16_t port, const OpenOptions& options)
    : spec_(spec), login_(login_name), host_(host), port_(port), options_(options) {
  if (options.verse_bone_form == "spec" || options.verse_bone_form == "r6") {
    bone_form_ = options.verse_bone_form == "r6" ? verse::BoneForm::R6 : verse::BoneForm::Spec;
    bone_form_known_ = true;
    bone_form_why_ = "as --verse-bone-form " + options.verse_bone_form + " asks";
  }
}

void VerseImplementation::use_bone_form(verse::BoneForm f) {
  bone_form_ = f;
  if (driver_) driver_->set_bone_form(f);
  if (observer_) observer_->set_bone_form(f);
  if (late_) late_->set_bone_form(f);
}

Answer VerseImplementation::probe_bone_form() {
  // The weight layer a bone needs (BONE-WEIGHT-1), then the bone with the
  // identity rotation: a host of r6's form reads the rotation's first two
  // (zero) bytes as empty rotation and scale labels, then stops at the next
  // zero byte (command 0 does not decode there), so nothing else is run.
  use_bone_form(verse::BoneForm::Spec);
  cmd::LayerCreate layer{2, "vgc_probe_w", static_cast<std::uint8_t>(LayerType::VertexUint32), 0, 0};
  cmd::BoneCreate bone{0xFFFF, "vgc_probe_w", "", 0xFFFF, {0, 0, 0}, "", {0, 0, 0, 1}, ""};
  const std::size_t other_before = observer_->counters().other_bone_form;
  for (const Command& c : {Command(layer), Command(bone)}) {
    if (const verse::Status st = driver_->send(verse::wire::Geometry{node_, c}, true); !st.ok())
      return failed(call_status_of(st), "probing the host's bone_create form: " + st.to_string());
  }
  Answer a = settle("probing the host's bone_create form");
  if (a.status != CallStatus::Ok) return a;
  const bool r6 = observer_->counters().other_bone_form != other_before;
  const bool bone_seen = !mirror_.bones().empty();
  use_bone_form(r6 ? verse::BoneForm::R6 : verse::BoneForm::Spec);
  bone_form_known_ = true;
  bone_form_why_ = r6 ? "the host answered a spec-form probe in r6's form"
                      : bone_seen ? "the host answered a spec-form probe in the spec's form"
                                  : "the host did not answer a bone_create probe; the spec's form by default";
  return make_node();  // a fresh node again
}

VerseImplementation::~VerseImplementation() {
  if (std::getenv("VGC_VERSE_STATS"))
    fmt::print(stderr, "verse route: {} commands sent, {} round trips ({:.2f} per command), {} driver logins, {} driver "
                       "sessions ended by the host ({} after a command r6 misreads)\n",
               commands_sent_, round_trips_,
               commands_sent_ ? static_cast<double>(round_trips_) / static_cast<double>(commands_sent_) : 0.0,
               driver_logins_, driver_drops_, driver_drops_known_);
  if (std::getenv("VGC_VERSE_STATS"))
    fmt::print(stderr, "verse route: {} batches of {} commands in all, {} sent again one per round trip, {} rebuilt nodes\n",
               batches_, batched_commands_, batch_fallbacks_, rebuilds_);
  if (driver_ && !broken_) {
    std::vector<std::uint32_t> ids = pool_.clear();
    if (have_node_) ids.push_back(node_);
    (void)destroy_nodes(ids);
  }
  if (late_) late_->disconnect();
  if (observer_) observer_->disconnect();
  if (driver_) driver_->disconnect();
}

RouteLimits VerseImplementation::limits() const {
  RouteLimits l = verse_route_limits();
  if (bone_form_known_ && bone_form_ == verse::BoneForm::R6)
    l.cannot[RouteLimit::BoneRotationUnsent] =
        "in r6's form of bone_create (the host's; docs/verse_wire.md section 4) a bone carries no rotation, so a "
        "non-finite or zero rotation cannot be sent";
  return l;
}

std::string VerseImplementation::identity() const {
  std::string id = identity_.empty() ? spec_ : identity_;
  if (bone_form_known_)
    id += "; bone_create in the " + std::string(bone_form_ == verse::BoneForm::R6 ? "r6 form" : "spec 2.6.3 form") +
          " (" + bone_form_why_ + ")";
  return id;
}

std::string VerseImplementation::merge_identity() const {
  std::string id = "verse: a Verse host of release " + std::to_string(release_);
  if (bone_form_known_)
    id += ", bone_create in the " + std::string(bone_form_ == verse::BoneForm::R6 ? "r6 form" : "spec 2.6.3 form");
  return id;
}

Answer VerseImplementation::failed(CallStatus s, const std::string& detail) {
  broken_ = true;
  Answer a;
  a.status = s;
  a.detail = detail;
  return a;
}

verse::ClientOptions VerseImplementation::session_options(verse::ClientSession* nudger) const {
  verse::ClientOptions o;
  o.name = login_;
  if (const char* pw = std::getenv("VERSE_PASSWORD")) o.password = pw;
  o.login_timeout_s = options_.start_timeout_seconds;  // a login is a start (OpenOptions)
  o.stop = [] { return cancel_signal() != 0; };          // a cancelled run waits for nothing (cancel.h)
  o.bone_form = bone_form_;
  // The client's own backstop; the route decides sooner, and by asking
  // the observer, whether an unacknowledged driver was forgotten (settle).
  o.unacknowledged_limit_s = options_.timeout_seconds;
  if (nudger && nudger->connected()) o.while_awaiting_accept = [nudger] { (void)nudger->nudge(); };
  return o;
}

Answer VerseImplementation::connect() {
  if (!silent_since_.empty())
    return failed(CallStatus::Timeout, "the Verse host stopped answering (" + silent_since_ +
                                           "); vgc does not wait for it again in this run");
  // Only the driver's session was dropped (the host forgot it: section 7 of
  // docs/adapters.md): the observer stays, after a round trip on the old
  // node that takes in everything still under way for it.
  const bool keep_observer = driver_lost_ && observer_ && observer_->connected() && [&] {
    std::vector<verse::WireCommand> stale;
    ++round_trips_;
    return observer_->barrier(node_, std::min(kDeadSessionSeconds, options_.timeout_seconds), &stale).ok();
  }();
  driver_lost_ = false;
  if (observer_ && !keep_observer) observer_->disconnect();
  if (driver_) driver_->disconnect();
  driver_ = std::make_unique<verse::ClientSession>();
  // The pool's nodes are left behind with the sessions that knew them; the
  // new driver destroys them below.
  const std::vector<std::uint32_t> old_pool = pool_.clear();
  if (!keep_observer) {
    observer_ = std::make_unique<verse::ClientSession>();
    have_node_ = false;  // the old node is left to the host
  }  // else make_node() destroys the old node, if it still has one, through the new driver
  const std::string where = host_ + ":" + std::to_string(port_);
  for (auto* session : {driver_.get(), observer_.get()}) {
    if (session == observer_.get() && keep_observer) continue;
    // The other session, when it is up, wakes the host for this login.
    verse::ClientSession* other = session == driver_.get() ? (keep_observer ? observer_.get() : nullptr)
                                                           : driver_.get();
    const verse::Status st = session->connect(host_, port_, session_options(other));
    // A host that answered before and no longer answers a login has gone
    // silent: waiting for it again at every test case would only turn a
    // dead host into a run as long as cases x --timeout.
    if (st.code == verse::Status::Code::Timeout && ever_connected_)
      silent_since_ = "no answer to a login within " + limit_text(options_.start_timeout_seconds, "--start-timeout");
    if (!st.ok())
      return failed(call_status_of(st), "logging in to the Verse host at " + where + " as \"" + login_ +
                                            "\": " + st.to_string() +
                                            (st.code == verse::Status::Code::Timeout ? " (--start-timeout)" : ""));
  }
  ++driver_logins_;
  driver_avatar_ = driver_->avatar();
  driver_announced_ = driver_dropped_ = desync_risk_ = false;
  // The observer follows the index of avatars (the driver's being destroyed
  // is the host ending its session) and of geometry nodes (the pool's).
  if (!keep_observer) {
    const verse::Status st = observer_->send(
        verse::wire::NodeIndexSubscribe{(1u << verse::kNodeTypeObject) | (1u << verse::kNodeTypeGeometry)});
    if (!st.ok()) return failed(call_status_of(st), "subscribing to the node index: " + st.to_string());
  }
  release_ = driver_->host_release();
  identity_ = "Verse host at " + where + " (release " + std::to_string(release_) + ")";
  broken_ = false;
  ever_connected_ = true;
  return destroy_nodes(old_pool);
}

Answer VerseImplementation::destroy_nodes(const std::vector<std::uint32_t>& ids) {
  for (std::uint32_t id : ids) {
    verse::wire::NodeDestroy destroy;
    destroy.node_id = id;
    if (const verse::Status st = driver_->send(destroy); !st.ok())
      return failed(call_status_of(st), "destroying geometry node " + std::to_string(id) + ": " + st.to_string());
  }
  return {};
}

Answer VerseImplementation::make_node(double create_timeout_s) {
  if (have_node_) {
    if (Answer a = destroy_nodes({node_}); a.status != CallStatus::Ok) return a;
    have_node_ = false;
  }
  for (int batch = 0; batch < 2; ++batch) {
    if (pool_.empty())
      if (Answer a = refill_pool(create_timeout_s); a.status != CallStatus::Ok) return a;
    std::vector<std::uint32_t> spoilt;
    std::optional<VerseNodePool::Taken> t = pool_.take(&spoilt);
    if (Answer a = destroy_nodes(spoilt); a.status != CallStatus::Ok) return a;
    if (!t) continue;  // the whole batch was spoilt: one more
    node_ = t->node_id;
    have_node_ = true;
    mirror_ = std::move(t->mirror);
    mirror_.set_max_cells(kMirrorCells);
    return {};
  }
  return failed(CallStatus::ProtocolError,
                "two batches of new geometry nodes were each changed or destroyed before any was used: the host "
                "does not keep a node fresh while nothing is sent to it");
}

Answer VerseImplementation::refill_pool(double create_timeout_s) {
  const double wait =
      create_timeout_s > 0 ? std::min(create_timeout_s, options_.timeout_seconds) : options_.timeout_seconds;
  std::vector<std::uint32_t> ids;
  ++round_trips_;
  if (const verse::Status st = driver_->create_geometry_nodes(kPoolBatch, &ids, wait); !st.ok())
    return failed(call_status_of(st), "creating geometry nodes (node_create): " + st.to_string());
  for (std::uint32_t id : ids) {
    pool_.add(id);
    if (const verse::Status st = observer_->subscribe_node(id); !st.ok())
      return failed(call_status_of(st), "subscribing to geometry node " + std::to_string(id) + ": " + st.to_string());
  }
  // The late subscriber watches layer 0 of each, REAL32 then REAL64. (An
  // id may be a destroyed node's: r6 reuses ids.)
  for (std::uint32_t id : ids) late_watching_.erase(id);
  bool late_ok = ensure_late();
  for (std::uint32_t id : ids) {
    if (!late_ok) break;
    late_ok = late_->subscribe_node(id).ok() && late_->subscribe_layer(id, 0, RealFormat::Real32).ok() &&
              late_->subscribe_layer(id, 0, RealFormat::Real64).ok();
  }
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(options_.timeout_seconds));
  const std::string what = "creating geometry nodes " + std::to_string(ids.front()) + " to " +
                           std::to_string(ids.back()) + " and subscribing to them";
  new_layers_.clear();
  Answer a = observer_round_trip(ids.back(), deadline, what);
  if (a.status == CallStatus::Ok) a = subscribe_new_layers(ids.back(), deadline, what);
  if (a.status != CallStatus::Ok) return a;
  pool_.settle_all();
  drain_driver();
  // Its subscriptions settled too (what they were sent: empty fresh nodes).
  if (late_ok) {
    std::vector<verse::WireCommand> dump;
    ++round_trips_;
    if (late_->barrier(ids.back(), seconds_left(deadline), &dump).ok()) {
      verse::WireCommand w;
      for (int i = 0; i < 100000 && late_->receive(&w, 0).ok(); ++i) {
      }
      late_watching_.insert(ids.begin(), ids.end());
    } else {
      late_->disconnect();  // logs in again at its next use
    }
  }
  return {};
}

bool VerseImplementation::ensure_late() {
  if (late_ && late_->connected()) return true;
  if (late_) late_->disconnect();
  late_ = std::make_unique<verse::ClientSession>();
  late_node_ = 0;
  late_watching_.clear();
  // The observer wakes the host for this login (r6 answers a login only on
  // its one-second tick otherwise): once per run, not per case.
  // It idles between cases: an ack it has not read yet is no sign of a host
  // that forgot it (only its own time-out ends its waits).
  verse::ClientOptions o = session_options(observer_.get());
  o.unacknowledged_limit_s = 0;
  if (!observer_ || !silent_since_.empty()) return false;  // a silent host is not waited for again
  const verse::Status st = late_->connect(host_, port_, o);
  if (st.code == verse::Status::Code::Timeout && ever_connected_)
    silent_since_ = "no answer to a login within " + limit_text(options_.start_timeout_seconds, "--start-timeout");
  return st.ok();
}

Answer VerseImplementation::start() {
  Answer a = connect();
  if (a.status != CallStatus::Ok) return a;
  a = make_node();
  if (a.status != CallStatus::Ok || bone_form_known_) return a;
  return probe_bone_form();
}

Answer VerseImplementation::reset() {
  pending_.clear();  // sent ahead to the node being left
  since_fresh_.clear();
  batch_off_ = false;
  last_batched_ = false;
  if (driver_dropped_ && !broken_) {  // seen after the command that caused it was judged
    broken_ = true;
    driver_lost_ = true;
    ++driver_drops_;
    if (desync_risk_) ++driver_drops_known_;
  }
  if (broken_ || !driver_ || !driver_->connected() || !observer_->connected()) return start();
  Answer a = make_node(kFirstCreateSeconds);
  // A reset takes a node made ahead, with no round trip through the
  // driver's session: after a command that may have ended it, one round
  // trip on the new node tells (a dropped session is the next command's
  // crash otherwise, in a case it has nothing to do with).
  if (a.status == CallStatus::Ok && desync_risk_) a = settle("checking the session after a misread command");
  desync_risk_ = false;
  if (a.status == CallStatus::Crash && !driver_->connected() && observer_->connected()) driver_lost_ = true;
  // A host may end a session without a word (r6 runs a connect_terminate
  // it decoded from the rest of a desynchronised packet and forgets the
  // session): then nothing it is sent is answered. One fresh login tells
  // that apart from a host that no longer answers at all.
  if ((a.status == CallStatus::Timeout || a.status == CallStatus::Crash) && silent_since_.empty()) a = start();
  return a;
}

void VerseImplementation::drain_driver() {
  // The driver subscribes to nothing of its own, but the suite's
  // layer_subscribe makes the host send it layer data, and it hears about
  // nodes: read and drop it, so that its queue stays small (receive() also
  // acknowledges and resends).
  verse::WireCommand w;
  for (int i = 0; i < 100000 && driver_->receive(&w, 0).ok(); ++i) {
  }
}

bool VerseImplementation::absorb(const verse::WireCommand& w, std::string* error) {
  if (const auto* n = std::get_if<verse::wire::NodeCreate>(&w)) {
    if (n->type == verse::kNodeTypeObject && n->node_id == driver_avatar_) driver_announced_ = true;
    if (n->type == verse::kNodeTypeGeometry) pool_.on_index_create(n->node_id);
    return true;
  }
  if (const auto* d = std::get_if<verse::wire::NodeDestroy>(&w)) {
    if (d->node_id == driver_avatar_ && driver_announced_) driver_dropped_ = true;
    pool_.on_index_destroy(d->node_id);
    return true;
  }
  const auto* g = std::get_if<verse::wire::Geometry>(&w);
  if (!g) return true;  // not geometry
  // A pool node first: it may have the id of the current node, destroyed
  // by reset() (r6 reuses ids).
  const bool pooled = pool_.holds(g->node_id);
  if (!pooled && !(have_node_ && g->node_id == node_)) return true;  // another node
  VerseNodeMirror& m = pooled ? *pool_.mirror(g->node_id) : mirror_;
  if (!pooled && counting_broadcasts_) {
    if (first_broadcast_.empty()) first_broadcast_ = print_command(g->command);
    if (host_sent_.size() < kHostSentKept) host_sent_.push_back(print_command(g->command));
    ++host_sent_count_;
  }
  const bool follow_layers = !pooled || !pool_.settled(g->node_id);
  if (const auto* lc = std::get_if<cmd::LayerCreate>(&g->command); lc && !lc->name.empty() && follow_layers) {
    // (While a batch settles, mirror_ lacks only the slot writes of the
    // batch's commands, so its layers are the node's before the batch.)
    const auto it = m.layers().find(lc->layer_id);
    if (it == m.layers().end() || static_cast<std::uint8_t>(it->second.type) != lc->type)
      new_layers_.insert({g->node_id, lc->layer_id});  // new, or re-typed (an r6 host then drops its subscribers)
  }
  if (!pooled && capturing_) {  // a batch settling: sorted by command afterwards (apply_batch)
    captured_.push_back(w);
    return true;
  }
  if (m.apply(g->command, error)) return true;
  if (!pooled) return false;
  pool_.spoil(g->node_id);  // more than a fresh node holds
  return true;
}

Answer VerseImplementation::absorb_arrived(const std::string& what) {
  verse::WireCommand w;
  for (int i = 0; i < 100000 && observer_->receive(&w, 0).ok(); ++i) {
    std::string error;
    if (!absorb(w, &error)) return failed(CallStatus::ProtocolError, what + ": " + error);
  }
  return {};
}

Answer VerseImplementation::observer_round_trip(std::uint32_t node, Clock::time_point deadline,
                                                const std::string& what) {
  std::vector<verse::WireCommand> seen;
  ++round_trips_;
  const verse::Status st = observer_->barrier(node, seconds_left(deadline), &seen);
  for (const auto& w : seen) {
    std::string error;
    if (!absorb(w, &error)) return failed(CallStatus::ProtocolError, what + ": " + error);
  }
  if (st.ok()) return absorb_arrived(what);
  if (st.code == verse::Status::Code::Timeout)
    return failed(CallStatus::Timeout, what + ": the host did not echo the observer's round-trip node_name_set "
                                              "within " + limit_text(options_.timeout_seconds, "--timeout"));
  return failed(call_status_of(st), what + ": " + st.to_string());
}

Answer VerseImplementation::subscribe_new_layers(std::uint32_t node, Clock::time_point deadline,
                                                 const std::string& what) {
  for (int round = 0; !new_layers_.empty(); ++round) {
    if (round == 8)
      return failed(CallStatus::ProtocolError, what + ": the host kept announcing new layers after 8 rounds");
    for (const auto& [n, layer] : new_layers_)
      if (const verse::Status st = observer_->subscribe_layer(n, layer, RealFormat::Real64); !st.ok())
        return failed(call_status_of(st), what + ": subscribing to layer " + std::to_string(layer) + " of node " +
                                              std::to_string(n) + ": " + st.to_string());
    new_layers_.clear();
    if (Answer a = observer_round_trip(node, deadline, what); a.status != CallStatus::Ok) return a;
  }
  return {};
}

bool VerseImplementation::observer_answers(double seconds, const std::function<bool(const verse::WireCommand&)>& is_echo,
                                           bool* echoed) {
  if (!observer_ || !observer_->connected()) return false;
  std::vector<verse::WireCommand> seen;
  ++round_trips_;
  if (!observer_->barrier(node_, seconds, &seen).ok()) return false;
  std::string error;
  for (const auto& w : seen) {
    if (is_echo(w)) *echoed = true;  // the round trip being waited for came with it
    else (void)absorb(w, &error);    // the mirror keeps up; a protocol error shows at the next read
  }
  return true;
}

Answer VerseImplementation::settle(const std::string& what) {
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(options_.timeout_seconds));
  new_layers_.clear();
  const auto lost = [&](const std::string& why) {
    Answer a = failed(CallStatus::Crash, what + ": " + why +
                                             ": it dropped the session (r6 does so silently when the rest of a "
                                             "packet it could not decode reads as connect_terminate)");
    driver_lost_ = true;
    ++driver_drops_;
    if (desync_risk_) ++driver_drops_known_;
    return a;
  };
  // The round trip: the driver's name change after its command(s).
  const std::string name = "vgc-barrier-" + std::to_string(++barrier_count_);
  verse::wire::NodeNameSet mark;
  mark.node_id = node_;
  mark.name = name;
  if (const verse::Status st = driver_->send(mark); !st.ok())
    return failed(call_status_of(st), what + ": sending the round-trip node_name_set: " + st.to_string());
  ++round_trips_;
  const auto is_echo = [&](const verse::WireCommand& w) {
    const auto* n = std::get_if<verse::wire::NodeNameSet>(&w);
    return n && n->node_id == node_ && n->name == name;
  };
  for (;;) {
    if (cancel_signal())  // a Timeout to the runner, which drops what a cancel cut short
      return failed(CallStatus::Timeout, what + ": not answered: the run was cancelled by " +
                                             std::string(cancel_signal_name()));
    if (driver_dropped_) {
      // r6 runs what it had received of a session before it forgets it, so
      // the echo still comes when the barrier came in with the command that
      // ended the session (the command is then judged, as before the
      // drop could be seen). The observer's own round trip tells.
      std::vector<verse::WireCommand> seen;
      ++round_trips_;
      const verse::Status st = observer_->barrier(node_, seconds_left(deadline), &seen);
      bool echoed = false;
      for (const auto& w : seen) {
        std::string error;
        if (is_echo(w)) echoed = true;
        else if (!absorb(w, &error)) return failed(CallStatus::ProtocolError, what + ": " + error);
      }
      if (!st.ok() && !echoed) return failed(call_status_of(st), what + ": " + st.to_string());
      if (!echoed) return lost("the host destroyed the driver's avatar node");
      break;
    }
    verse::WireCommand w;
    const double left = seconds_left(deadline);
    const verse::Status st = observer_->receive(&w, std::min(left, kSessionCheckSeconds));
    if (st.code == verse::Status::Code::Timeout && left > kSessionCheckSeconds) {
      drain_driver();  // reads the host's acks of the driver's packets
      if (driver_->unacknowledged_for() > kDeadSessionSeconds) {
        const std::string unacked = "the host has not acknowledged the driver's packets for " +
                                    limit_text(kDeadSessionSeconds, "vgc's limit for an unacknowledged packet");
        // A host that forgot the driver's session still answers the
        // observer; one that answers neither has stopped answering (a
        // stopped or overloaded process): a time-out, not a crash.
        const double probe_s = std::max(seconds_left(deadline), std::min(kDeadSessionSeconds, options_.timeout_seconds));
        bool echoed = false;
        const bool answered = observer_answers(probe_s, is_echo, &echoed);
        if (!answered && is_local_host(host_) && !local_udp_port_bound(port_))
          return failed(CallStatus::Crash, what + ": the host's process ended: " + unacked +
                                               ", and nothing on this machine holds UDP port " +
                                               std::to_string(port_) + " any more");
        if (!answered)
          return failed(CallStatus::Timeout, what + ": the host stopped answering: " + unacked +
                                                 ", and the observer's round trip was not answered within " +
                                                 limit_text(probe_s, "the rest of --timeout"));
        // The host has now read what the driver sent before the observer's
        // round trip, and acknowledged it if it still knows the session: a
        // host slow on a loaded machine is not one that forgot it.
        drain_driver();
        if (driver_->connected() && driver_->unacknowledged_for() <= kDeadSessionSeconds) {
          if (echoed) break;
          continue;
        }
        return lost(unacked + " (and not after the observer's round trip)");
      }
      continue;
    }
    if (!st.ok()) {
      if (st.code == verse::Status::Code::Timeout)
        return failed(CallStatus::Timeout,
                      what + ": the host did not echo the round-trip node_name_set \"" + name + "\" to a subscriber "
                      "within " + limit_text(options_.timeout_seconds, "--timeout"));
      return failed(call_status_of(st), what + ": " + st.to_string());
    }
    if (is_echo(w)) break;
    std::string error;
    if (!absorb(w, &error)) return failed(CallStatus::ProtocolError, what + ": " + error);
  }
  if (Answer a = absorb_arrived(what); a.status != CallStatus::Ok) return a;
  counting_broadcasts_ = false;  // what follows answers the observer's own subscriptions
  capture_mark_ = captured_.size();
  // Layers announced: the observer subscribes and waits for their contents.
  if (Answer a = subscribe_new_layers(node_, deadline, what); a.status != CallStatus::Ok) return a;
  drain_driver();
  return {};
}

void VerseImplementation::expect_commands(std::vector<Command> next) {
  expected_.clear();
  for (auto& c : next) {
    Expected e{{}, std::move(c)};
    if (!wire_key(e.command, bone_form_, &e.key)) e.key.clear();  // not sent: never batched
    expected_.push_back(std::move(e));
  }
}

Answer VerseImplementation::apply(const Command& c) {
  last_batched_ = false;
  if (broken_ || !have_node_)
    return failed(CallStatus::Crash, "the session with the Verse host was lost earlier; reset() logs in again");
  std::string key;
  {
    // What the wire cannot carry (a name with a NUL inside: Verse strings
    // end at their first NUL) is not sent, and the step is not judged.
    verse::wire::Geometry g;
    g.node_id = node_;
    g.command = c;
    std::string bytes;
    if (const verse::Status st = verse::encode_command(g, &bytes, bone_form_); !st.ok()) {
      if (!expected_.empty() && expected_.front().key.empty()) expected_.pop_front();
      Answer a;
      a.not_sent = true;
      a.verdict_reported = false;
      a.detail = "the Verse wire cannot carry it (" + st.detail + ")";
      return a;
    }
    (void)wire_key(c, bone_form_, &key);
  }
  const bool hinted = !expected_.empty() && expected_.front().key == key;
  if (hinted) expected_.pop_front();
  if (!pending_.empty()) {
    if (pending_.front().key == key) {  // sent ahead: answered from what came back for it
      Prepared p = std::move(pending_.front());
      pending_.pop_front();
      return answer_from_batch(p.command, p.received, p.counted);
    }
    // Another command than the one sent next: the node holds commands
    // nobody asked for; a fresh one is brought to the answered state.
    if (Answer a = rebuild(); a.status != CallStatus::Ok) return a;
  }
  if (hinted && !batch_off_ && batchable(c)) {
    std::vector<Command> batch{c};
    std::set<WireSlot> slots;
    for (const WireSlot& w : footprint_of(c)) slots.insert(w);
    // The commands that follow, while each one's slots are its own (r6
    // sends a subscriber one message per address, the last: two commands
    // that may write one slot could not be told apart).
    const auto own_slots = [&slots](const Command& x) {
      for (const WireSlot& w : footprint_of(x))
        if (slots.count(w)) return false;
      return true;
    };
    while (batch.size() < kMaxBatch && !expected_.empty() && !expected_.front().key.empty() &&
           batchable(expected_.front().command) && own_slots(expected_.front().command)) {
      for (const WireSlot& w : footprint_of(expected_.front().command)) slots.insert(w);
      batch.push_back(expected_.front().command);
      expected_.pop_front();
    }
    bool tail = false;
    if (batch.size() < kMaxBatch && !expected_.empty() && !expected_.front().key.empty() &&
        !batchable(expected_.front().command) && may_end_batch(expected_.front().command, slots)) {
      batch.push_back(expected_.front().command);
      expected_.pop_front();
      tail = true;
    }
    if (batch.size() > 1) return apply_batch(batch, tail);
  }
  return apply_one(c);
}

Answer VerseImplementation::apply_one(const Command& c) {
  const std::string what = "after `" + print_command(c) + "`";
  if (const verse::Status st = driver_->send_geometry(node_, c); !st.ok())
    return failed(call_status_of(st), "sending `" + print_command(c) + "`: " + st.to_string());
  ++commands_sent_;
  if (may_desynchronise_r6(c)) desync_risk_ = true;
  first_broadcast_.clear();
  host_sent_.clear();
  host_sent_count_ = 0;
  counting_broadcasts_ = true;
  Answer a = settle(what);
  counting_broadcasts_ = false;
  if (a.status != CallStatus::Ok) return a;
  a.verdict_reported = false;  // `done`: a host acknowledges nothing
  a.broadcast = first_broadcast_;  // ... but what it tells its subscribers is its verdict
  a.host_sent_seen = true;
  a.host_sent = std::move(host_sent_);
  a.host_sent_count = host_sent_count_;
  host_sent_.clear();
  since_fresh_.push_back(c);
  return a;
}

Answer VerseImplementation::apply_batch(const std::vector<Command>& batch, bool tail) {
  for (const Command& c : batch) {
    if (const verse::Status st = driver_->send_geometry(node_, c); !st.ok())
      return failed(call_status_of(st), "sending `" + print_command(c) + "`: " + st.to_string());
    ++commands_sent_;
  }
  captured_.clear();
  capture_mark_ = 0;
  capturing_ = true;
  const Answer settled = settle("after `" + print_command(batch.front()) + "` and the " +
                                std::to_string(batch.size() - 1) + " commands sent after it before one round trip");
  capturing_ = false;
  // What the host sent for the node, sorted by the slot each message
  // writes: each slot is one command's.
  std::vector<std::vector<verse::WireCommand>> received(batch.size());
  std::size_t tail_counted = 0;  // the tail's messages before the observer's own subscriptions
  bool told_apart = settled.status == CallStatus::Ok;
  if (told_apart) {
    std::map<WireSlot, std::size_t> by_slot;
    const std::size_t slotted = tail ? batch.size() - 1 : batch.size();
    for (std::size_t i = 0; i < slotted; ++i)
      for (const WireSlot& w : footprint_of(batch[i])) by_slot[w] = i;
    for (std::size_t k = 0; k < captured_.size(); ++k) {
      auto& w = captured_[k];
      const auto* g = std::get_if<verse::wire::Geometry>(&w);
      const auto slot = g ? slot_of(g->command) : std::nullopt;
      auto it = slot && k < capture_mark_ ? by_slot.find(*slot) : by_slot.end();
      if (it == by_slot.end() && tail) {  // the last command's, whatever it is
        if (k < capture_mark_) ++tail_counted;
        received.back().push_back(std::move(w));
        continue;
      }
      if (it == by_slot.end()) {
        told_apart = false;
        break;
      }
      received[it->second].push_back(std::move(w));
    }
  }
  captured_.clear();
  if (!told_apart) {
    // A message no command of the batch explains (a host that writes other
    // slots than the one asked), or a round trip that failed: the batch is
    // sent again one command per round trip, on a fresh node brought to the
    // state before it, so each command is answered as on its own.
    ++batch_fallbacks_;
    if (Answer a = rebuild(); a.status != CallStatus::Ok) {
      last_batched_ = true;  // judged again on its own, if the route comes back
      return settled.status != CallStatus::Ok ? settled : a;
    }
    batch_off_ = true;
    return apply_one(batch.front());
  }
  ++batches_;
  batched_commands_ += batch.size();
  for (std::size_t i = 1; i < batch.size(); ++i) {
    const bool last = tail && i + 1 == batch.size();
    Prepared p{{}, batch[i], std::move(received[i]), 0};
    p.counted = last ? tail_counted : p.received.size();
    (void)wire_key(batch[i], bone_form_, &p.key);
    pending_.push_back(std::move(p));
  }
  return answer_from_batch(batch.front(), received.front(), received.front().size());
}

Answer VerseImplementation::answer_from_batch(const Command& c, const std::vector<verse::WireCommand>& received,
                                              std::size_t counted) {
  Answer a;
  a.host_sent_seen = true;
  for (std::size_t k = 0; k < received.size(); ++k) {
    const auto& g = std::get<verse::wire::Geometry>(received[k]);
    if (a.broadcast.empty() && k < counted) a.broadcast = print_command(g.command);
    if (a.host_sent.size() < kHostSentKept) a.host_sent.push_back(print_command(g.command));
    ++a.host_sent_count;
    std::string error;
    if (!mirror_.apply(g.command, &error))
      return failed(CallStatus::ProtocolError, "after `" + print_command(c) + "`: " + error);
  }
  a.verdict_reported = false;  // `done`, as apply_one answers
  since_fresh_.push_back(c);
  last_batched_ = true;
  return a;
}

Answer VerseImplementation::rebuild() {
  const std::vector<Command> answered = std::move(since_fresh_);
  const bool off = batch_off_;
  ++rebuilds_;
  Answer a = reset();  // drops pending_
  batch_off_ = off;
  if (a.status != CallStatus::Ok) return a;
  for (const Command& c : answered) {
    Answer r = apply_one(c);
    if (r.status != CallStatus::Ok) {
      r.detail = "sending the commands answered so far again, to a fresh node: " + r.detail;
      return r;
    }
  }
  return {};
}

Document VerseImplementation::snapshot() {
  if (broken_) return {CallStatus::Crash, {}, "the session with the Verse host was lost"};
  if (late_view_) return late_snapshot();
  return {CallStatus::Ok, mirror_.snapshot(), {}};
}

Document VerseImplementation::late_snapshot() {
  if (!have_node_) return {CallStatus::Crash, {}, "no node to subscribe to"};
  if (!pending_.empty()) {  // the host holds commands sent ahead and never asked for
    if (Answer a = rebuild(); a.status != CallStatus::Ok) return {a.status, {}, a.detail};
  }
  late_wrong_format_.clear();
  for (int attempt = 0;; ++attempt) {
    if (!ensure_late()) return {CallStatus::Crash, {}, "the late subscriber could not log in"};
    Document d = late_snapshot_once();
    // A session the host forgot (r6 drops one silent for 30 s, as this one
    // is between cases) logs in again, once.
    if (d.status == CallStatus::Ok || attempt == 1) return d;
    late_->disconnect();
  }
}

Document VerseImplementation::late_snapshot_once() {
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(options_.timeout_seconds));
  // What it was sent while watching the node (a pool node's layer 0, from
  // REAL32 then REAL64 subscriptions): a round trip of its own first, since
  // a host sends each session's share of a change in its own time (r6
  // flushes this session after the observer's echo). Then what an earlier
  // node sent it is dropped.
  const bool watched = late_watching_.erase(node_) > 0;
  std::vector<verse::WireCommand> stream;
  if (watched) {
    ++round_trips_;
    if (const verse::Status st = late_->barrier(node_, options_.timeout_seconds, &stream); !st.ok())
      return Document{call_status_of(st), {}, "the late subscriber's round trip: " + st.to_string()};
  }
  verse::WireCommand w;
  for (int i = 0; i < 100000 && late_->receive(&w, 0).ok(); ++i) stream.push_back(w);
  for (const auto& x : stream) {
    const auto* g = std::get_if<verse::wire::Geometry>(&x);
    if (!watched || !g || g->node_id != node_ || !late_wrong_format_.empty()) continue;
    if (const auto* v = std::get_if<cmd::VertexSetXyzReal32>(&g->command); v && v->layer_id == 0)
      late_wrong_format_ = print_command(g->command);
  }
  // Subscribed again below, from nothing. (Only the node's own id: an
  // earlier node's may be a pool node's by now, r6 reusing ids.)
  if (watched || late_node_ == node_) (void)late_->unsubscribe_node(node_);
  late_node_ = node_;
  const auto fail = [&](CallStatus s, const std::string& why) {
    return Document{s, {}, "the late subscriber of node " + std::to_string(node_) + ": " + why};
  };
  if (const verse::Status st = late_->subscribe_node(node_); !st.ok()) return fail(call_status_of(st), st.to_string());
  // Every layer the observer knows, in each format a layer of its type has
  // (a REAL32 and a REAL64 subscription of a real layer, one of any other);
  // layers only the late subscriber is told of get a round of their own.
  const auto is_real = [](LayerType t) {
    return t == LayerType::VertexXyz || t == LayerType::VertexReal || t == LayerType::PolygonCornerReal ||
           t == LayerType::PolygonFaceReal;
  };
  std::map<std::uint16_t, LayerType> asked;
  std::vector<verse::WireCommand> seen;
  std::map<std::uint16_t, LayerType> to_ask;
  for (const auto& [lid, layer] : mirror_.layers()) to_ask[lid] = layer.type;
  for (int round = 0;; ++round) {
    for (const auto& [lid, type] : to_ask) {
      for (RealFormat f : {RealFormat::Real32, RealFormat::Real64}) {
        if (f == RealFormat::Real64 && !is_real(type)) continue;
        if (const verse::Status st = late_->subscribe_layer(node_, lid, f); !st.ok())
          return fail(call_status_of(st), "subscribing to layer " + std::to_string(lid) + ": " + st.to_string());
      }
      asked[lid] = type;
    }
    std::vector<verse::WireCommand> before;
    ++round_trips_;
    const verse::Status st = late_->barrier(node_, seconds_left(deadline), &before);
    if (!st.ok()) return fail(call_status_of(st), "its round trip: " + st.to_string());
    for (int i = 0; i < 100000 && late_->receive(&w, 0).ok(); ++i) before.push_back(w);  // the echo's datagram
    seen.insert(seen.end(), before.begin(), before.end());
    // Layers announced to it (layer_create with a name) that it has not
    // asked for in that type.
    to_ask.clear();
    for (const auto& x : before)
      if (const auto* g = std::get_if<verse::wire::Geometry>(&x); g && g->node_id == node_)
        if (const auto* lc = std::get_if<cmd::LayerCreate>(&g->command); lc && !lc->name.empty() && is_layer_type(lc->type)) {
          const auto it = asked.find(lc->layer_id);
          if (it == asked.end() || it->second != static_cast<LayerType>(lc->type))
            to_ask[lc->layer_id] = static_cast<LayerType>(lc->type);
        }
    if (to_ask.empty()) break;
    if (round == 8) return fail(CallStatus::ProtocolError, "the host kept announcing new layers after 8 rounds");
  }
  // Everything it was sent comes from one state (nothing ran meanwhile), so
  // the layers, creases and bones go first (r6 sends a flush in the hash
  // order of addresses: a layer's values may come before the layer), then
  // the values, REAL32 ones to one view and REAL64 ones to the other.
  // A dump holds live elements only, so a vertex_delete in it is the alias
  // a REAL32 write of FLT_MAX reads as (the REAL32 subscriber's loss,
  // VerseNodeMirror::take_real32_differences).
  const auto real32_only = [](const Command& c) {
    return std::holds_alternative<cmd::VertexDelete>(c) || std::holds_alternative<cmd::VertexSetXyzReal32>(c) || std::holds_alternative<cmd::VertexSetReal32>(c) ||
           std::holds_alternative<cmd::PolygonSetCornerReal32>(c) || std::holds_alternative<cmd::PolygonSetFaceReal32>(c);
  };
  const auto real64_only = [](const Command& c) {
    return std::holds_alternative<cmd::VertexSetXyzReal64>(c) || std::holds_alternative<cmd::VertexSetReal64>(c) ||
           std::holds_alternative<cmd::PolygonSetCornerReal64>(c) || std::holds_alternative<cmd::PolygonSetFaceReal64>(c);
  };
  const auto node_level = [](const Command& c) {
    return std::holds_alternative<cmd::LayerCreate>(c) || std::holds_alternative<cmd::LayerDestroy>(c) ||
           std::holds_alternative<cmd::CreaseSetVertex>(c) || std::holds_alternative<cmd::CreaseSetEdge>(c) ||
           std::holds_alternative<cmd::BoneCreate>(c) || std::holds_alternative<cmd::BoneDestroy>(c);
  };
  VerseNodeMirror v32(kMirrorCells), v64(kMirrorCells);
  std::string error;
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& x : seen) {
      const auto* g = std::get_if<verse::wire::Geometry>(&x);
      if (!g || g->node_id != node_ || node_level(g->command) != (pass == 0)) continue;
      if (!real64_only(g->command) && !v32.apply(g->command, &error)) return fail(CallStatus::ProtocolError, error);
      if (!real32_only(g->command) && !v64.apply(g->command, &error)) return fail(CallStatus::ProtocolError, error);
    }
  v64.take_real32_differences(v32);
  // Done with the node: nothing more is sent it for it, and a later node
  // with its id (r6 reuses ids) is not unsubscribed by mistake.
  (void)late_->unsubscribe_node(node_);
  late_node_ = 0;
  return {CallStatus::Ok, v64.snapshot(), {}};
}

Document VerseImplementation::derived() {
  return {CallStatus::ProtocolError, {}, verse_route_limits().why_no_derived};
}

}  // namespace vgc
