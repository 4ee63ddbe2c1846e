// r6_exec.cpp — vgc_r6_exec: the exec protocol (docs/adapters.md section 1)
// in front of a running r6 host, reached through r6's own client library
// (an already-built libverse.a), so that
//
//   vgc certify --impl exec:'build/tests/verse/r6_interop/vgc_r6_exec 127.0.0.1:PORT'
//
// judges r6's geometry code through r6's codec, independent of vgc's wire
// codec. Spec: docs/verse_wire.md section 12 ("The exec wrapper"): what it
// sends for each command line, what it answers, and its limits.
//
// Rationale: a Verse host acknowledges nothing, so a command is answered
// `done` and vgc judges it from the state (docs/adapters.md, "done
// answers"), unless the host broadcast a command of its kind for the node
// while it was settled: a host's broadcasts are its verdict, as on the wire
// route, so it is answered `ok` (applied) even when the state shows no
// change. Its ?capabilities answer declares the profile of a host behind
// r6's library (declared_profile.h): no derived document, no subscription
// column of its own, no verdicts, no bone rotation, no requests, names as
// C strings; so vgc judges over exec what it judges over the wire. The state is a VerseNodeMirror (conformance/adapter) fed with
// what r6's library decoded from the host's broadcasts; the wrapper
// subscribes to every layer at REAL64. r6's library keeps one connection
// per host, so the suite's own layer_subscribe/layer_unsubscribe are not
// sent (they would end the wrapper's view of the layer): the wrapper
// records them itself, as the reference would, and the snapshot's
// subscription column is therefore not r6's. r6 computes no derived
// values; ?derived is the reference's derivation (reference/geometry) of
// the state r6 stores. After each command: the packet that carried it is
// acknowledged by the host (r6 acks after decoding it and sends the
// command's broadcasts with or after the ack), then a node_name_set round
// trip. Every wait is bounded (5 s); a host that stops answering ends the
// wrapper with a message on stderr.
#include <cfloat>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <variant>

#include <unistd.h>

extern "C" {
#include "verse.h"
}

#include "command_text.h"
#include "derived_document.h"
#include "node.h"
#include "r6_callbacks.h"
#include "r6_tap.h"
#include "snapshot.h"
#include "verse_node_mirror.h"

namespace {

struct State {
  bool accepted = false, terminated = false;
  std::uint32_t node = 0xFFFFFFFFu;
  std::string node_name;
  vgc::VerseNodeMirror mirror;
  std::string mirror_error;
  std::set<std::uint16_t> to_subscribe;                       // announced, not yet subscribed at REAL64
  std::map<std::uint16_t, vgc::RealFormat> suite_subs;        // the suite's layer_subscribe, kept here
  std::set<std::string> announced;  // the verbs the host broadcast for the node since the command was sent
} g;

// Whether the host announced `c` for the node: its own verb, or the delete
// an alias of one means (README: `polygon_set_corner_uint32` on layer 1
// with v0 = 0xFFFFFFFF is g_polygon_delete; a vertex_set_xyz with FLT_MAX,
// or DBL_MAX, is g_vertex_delete), which r6 announces as the delete, as
// the wire route reads it. Before, the alias's delete of a polygon that
// was not live (r6's grown polygon storage) was applied on the wire and
// `done` here (POLY-DELETE-1 fail on the wire, pass here at seed 3).
bool announced_verdict(const vgc::Command& c) {
  if (g.announced.count(std::string(vgc::command_verb(c)))) return true;
  if (const auto* p = std::get_if<vgc::cmd::PolygonSetCornerUint32>(&c); p && p->layer_id == 1 && p->v[0] == vgc::kNone32)
    return g.announced.count("polygon_delete") > 0;
  const auto vertex_alias = [](double x, double y, double z, double max) { return x == max || y == max || z == max; };
  if (const auto* v = std::get_if<vgc::cmd::VertexSetXyzReal32>(&c); v && vertex_alias(v->x, v->y, v->z, FLT_MAX))
    return g.announced.count("vertex_delete") > 0;
  if (const auto* v = std::get_if<vgc::cmd::VertexSetXyzReal64>(&c); v && vertex_alias(v->x, v->y, v->z, DBL_MAX))
    return g.announced.count("vertex_delete") > 0;
  return false;
}

void take(VNodeID node, const vgc::Command& c) {
  if (node != g.node) return;
  g.announced.insert(std::string(vgc::command_verb(c)));
  std::string error;
  if (!g.mirror.apply(c, &error) && g.mirror_error.empty()) g.mirror_error = error;
}

// ---- callbacks: r6's decoded arguments -> vgc::Command values ----
void cb_accept(void*, uint32, void*, void*, uint8*) { g.accepted = true; }
void cb_terminate(void*, char*, const char*) { g.terminated = true; }
void cb_node_create(void*, VNodeID node, VNodeType type, VNodeOwner owner) {
  if (type == V_NT_GEOMETRY && owner == VN_OWNER_MINE && g.node == 0xFFFFFFFFu) g.node = node;
}
void cb_node_name_set(void*, VNodeID node, const char* name) {
  if (node == g.node) g.node_name = name;
}
void cb_layer_create(void*, VNodeID node, VLayerID layer, const char* name, VNGLayerType type, uint32 def_uint,
                     real64 def_real) {
  if (node != g.node) return;
  const auto it = g.mirror.layers().find(layer);
  if (it == g.mirror.layers().end() || static_cast<unsigned>(it->second.type) != static_cast<unsigned>(type)) {
    g.to_subscribe.insert(layer);  // new, or re-typed: r6 ends its subscribers' subscriptions
    g.suite_subs.erase(layer);
  }
  take(node, vgc::cmd::LayerCreate{layer, name, static_cast<std::uint8_t>(type), def_uint, def_real});
}
void cb_layer_destroy(void*, VNodeID node, VLayerID layer) {
  if (node != g.node) return;
  g.suite_subs.erase(layer);
  take(node, vgc::cmd::LayerDestroy{layer});
}
void cb_xyz32(void*, VNodeID n, VLayerID l, uint32 v, real32 x, real32 y, real32 z) {
  take(n, vgc::cmd::VertexSetXyzReal32{l, v, x, y, z});
}
void cb_xyz64(void*, VNodeID n, VLayerID l, uint32 v, real64 x, real64 y, real64 z) {
  take(n, vgc::cmd::VertexSetXyzReal64{l, v, x, y, z});
}
void cb_vdel32(void*, VNodeID n, uint32 v) { take(n, vgc::cmd::VertexDelete{v}); }
void cb_vdel64(void*, VNodeID n, uint32 v) { take(n, vgc::cmd::VertexDelete{v}); }
void cb_vuint(void*, VNodeID n, VLayerID l, uint32 v, uint32 value) { take(n, vgc::cmd::VertexSetUint32{l, v, value}); }
void cb_vreal64(void*, VNodeID n, VLayerID l, uint32 v, real64 value) {
  take(n, vgc::cmd::VertexSetReal64{l, v, value});
}
void cb_vreal32(void*, VNodeID n, VLayerID l, uint32 v, real32 value) {
  take(n, vgc::cmd::VertexSetReal32{l, v, value});
}
void cb_corner_uint(void*, VNodeID n, VLayerID l, uint32 p, uint32 v0, uint32 v1, uint32 v2, uint32 v3) {
  take(n, vgc::cmd::PolygonSetCornerUint32{l, p, {v0, v1, v2, v3}});
}
void cb_pdel(void*, VNodeID n, uint32 p) { take(n, vgc::cmd::PolygonDelete{p}); }
void cb_corner64(void*, VNodeID n, VLayerID l, uint32 p, real64 v0, real64 v1, real64 v2, real64 v3) {
  take(n, vgc::cmd::PolygonSetCornerReal64{l, p, {v0, v1, v2, v3}});
}
void cb_corner32(void*, VNodeID n, VLayerID l, uint32 p, real32 v0, real32 v1, real32 v2, real32 v3) {
  take(n, vgc::cmd::PolygonSetCornerReal32{l, p, {v0, v1, v2, v3}});
}
void cb_face_u8(void*, VNodeID n, VLayerID l, uint32 p, uint8 v) { take(n, vgc::cmd::PolygonSetFaceUint8{l, p, v}); }
void cb_face_u32(void*, VNodeID n, VLayerID l, uint32 p, uint32 v) {
  take(n, vgc::cmd::PolygonSetFaceUint32{l, p, v});
}
void cb_face64(void*, VNodeID n, VLayerID l, uint32 p, real64 v) { take(n, vgc::cmd::PolygonSetFaceReal64{l, p, v}); }
void cb_face32(void*, VNodeID n, VLayerID l, uint32 p, real32 v) { take(n, vgc::cmd::PolygonSetFaceReal32{l, p, v}); }
void cb_crease_vertex(void*, VNodeID n, const char* layer, uint32 def) { take(n, vgc::cmd::CreaseSetVertex{layer, def}); }
void cb_crease_edge(void*, VNodeID n, const char* layer, uint32 def) { take(n, vgc::cmd::CreaseSetEdge{layer, def}); }
void cb_bone_create(void*, VNodeID n, uint16 bone, const char* weight, const char* reference, uint16 parent, real64 x,
                    real64 y, real64 z, const char* pos_label, const char* rot_label, const char*) {
  // r6's form has no rotation value: the bone's rotation is the identity.
  take(n, vgc::cmd::BoneCreate{bone, weight, reference, parent, {x, y, z}, pos_label, {0, 0, 0, 1}, rot_label});
}
void cb_bone_destroy(void*, VNodeID n, uint16 bone) { take(n, vgc::cmd::BoneDestroy{bone}); }

void register_callbacks() {
  VGC_R6_NODE_CALLBACKS(VGC_R6_REGISTER)
  VGC_R6_GEOMETRY_CALLBACKS(VGC_R6_REGISTER)
}

// ---- bounded waits ----
double now_s() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + t.tv_nsec / 1e9;
}
constexpr double kWait = 5.0;
[[noreturn]] void give_up(const std::string& what) {
  std::fprintf(stderr, "vgc_r6_exec: %s\n", what.c_str());
  std::exit(3);
}
void pump_until(const std::function<bool()>& done, const std::string& what) {
  const double end = now_s() + kWait;
  while (!done()) {
    if (g.terminated) give_up("the host ended the session while " + what);
    if (now_s() > end) give_up("no answer from the host within 5 s while " + what);
    verse_callback_update(2000);
  }
}

int g_barrier = 0;
// What was sent is acknowledged, its broadcasts are in, the new layers are
// subscribed at REAL64 (and their content is in).
void settle(const std::string& what) {
  for (int round = 0; round < 16; ++round) {
    verse_callback_update(0);  // sends the queued packet
    const std::uint32_t id = r6tap::last_command_packet();
    pump_until([&] { return id == 0 || r6tap::acknowledged(id); }, what + " (the host's ack)");
    const std::string name = "vgc-r6-exec-" + std::to_string(++g_barrier);
    verse_send_node_name_set(g.node, name.c_str());
    pump_until([&] { return g.node_name == name; }, what + " (the name round trip)");
    if (g.to_subscribe.empty()) return;
    for (std::uint16_t l : g.to_subscribe) verse_send_g_layer_subscribe(g.node, l, VN_FORMAT_REAL64);
    g.to_subscribe.clear();
  }
}

void reset_node() {
  if (g.node != 0xFFFFFFFFu) verse_send_node_destroy(g.node);
  r6tap::forget();
  g.node = 0xFFFFFFFFu;
  g.node_name.clear();
  g.mirror.clear();
  g.mirror_error.clear();
  g.to_subscribe.clear();
  g.suite_subs.clear();
  verse_send_node_create(~0u, V_NT_GEOMETRY, VN_OWNER_MINE);
  pump_until([] { return g.node != 0xFFFFFFFFu; }, "creating a geometry node");
  verse_send_node_subscribe(g.node);
  pump_until([] { return g.mirror.layers().count(0) && g.mirror.layers().count(1); }, "subscribing to the node");
  settle("subscribing to the base layers");
}

// One command line of the suite, sent through r6's API. false: not sent.
bool send(const vgc::Command& command) {
  const VNodeID n = g.node;
  auto name_ok = [](const std::string& s) { return s.find('\0') == std::string::npos; };
  return std::visit(
      [&](const auto& c) -> bool {
        using T = std::decay_t<decltype(c)>;
        namespace cmd = vgc::cmd;
        if constexpr (std::is_same_v<T, cmd::LayerCreate>) {
          if (!name_ok(c.name)) return false;
          verse_send_g_layer_create(n, c.layer_id, c.name.c_str(), static_cast<VNGLayerType>(c.type), c.def_uint,
                                    c.def_real);
        } else if constexpr (std::is_same_v<T, cmd::LayerDestroy>) {
          verse_send_g_layer_destroy(n, c.layer_id);
        } else if constexpr (std::is_same_v<T, cmd::LayerSubscribe>) {
          // Kept here, not sent (see the top comment): as the reference records it.
          if (c.real_format <= 1 && g.mirror.layers().count(c.layer_id))
            g.suite_subs[c.layer_id] = static_cast<vgc::RealFormat>(c.real_format);
          else if (c.real_format > 1)
            g.suite_subs.erase(c.layer_id);
          return false;
        } else if constexpr (std::is_same_v<T, cmd::LayerUnsubscribe>) {
          g.suite_subs.erase(c.layer_id);
          return false;
        } else if constexpr (std::is_same_v<T, cmd::VertexSetXyzReal32>) {
          verse_send_g_vertex_set_xyz_real32(n, c.layer_id, c.vertex_id, c.x, c.y, c.z);
        } else if constexpr (std::is_same_v<T, cmd::VertexSetXyzReal64>) {
          verse_send_g_vertex_set_xyz_real64(n, c.layer_id, c.vertex_id, c.x, c.y, c.z);
        } else if constexpr (std::is_same_v<T, cmd::VertexDelete>) {
          verse_send_g_vertex_delete_real64(n, c.vertex_id);
        } else if constexpr (std::is_same_v<T, cmd::VertexSetUint32>) {
          verse_send_g_vertex_set_uint32(n, c.layer_id, c.vertex_id, c.value);
        } else if constexpr (std::is_same_v<T, cmd::VertexSetReal64>) {
          verse_send_g_vertex_set_real64(n, c.layer_id, c.vertex_id, c.value);
        } else if constexpr (std::is_same_v<T, cmd::VertexSetReal32>) {
          verse_send_g_vertex_set_real32(n, c.layer_id, c.vertex_id, c.value);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetCornerUint32>) {
          verse_send_g_polygon_set_corner_uint32(n, c.layer_id, c.polygon_id, c.v[0], c.v[1], c.v[2], c.v[3]);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetCornerReal64>) {
          verse_send_g_polygon_set_corner_real64(n, c.layer_id, c.polygon_id, c.v[0], c.v[1], c.v[2], c.v[3]);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetCornerReal32>) {
          verse_send_g_polygon_set_corner_real32(n, c.layer_id, c.polygon_id, c.v[0], c.v[1], c.v[2], c.v[3]);
        } else if constexpr (std::is_same_v<T, cmd::PolygonDelete>) {
          verse_send_g_polygon_delete(n, c.polygon_id);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetFaceUint8>) {
          verse_send_g_polygon_set_face_uint8(n, c.layer_id, c.polygon_id, c.value);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetFaceUint32>) {
          verse_send_g_polygon_set_face_uint32(n, c.layer_id, c.polygon_id, c.value);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetFaceReal64>) {
          verse_send_g_polygon_set_face_real64(n, c.layer_id, c.polygon_id, c.value);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetFaceReal32>) {
          verse_send_g_polygon_set_face_real32(n, c.layer_id, c.polygon_id, c.value);
        } else if constexpr (std::is_same_v<T, cmd::CreaseSetVertex>) {
          if (!name_ok(c.layer)) return false;
          verse_send_g_crease_set_vertex(n, c.layer.c_str(), c.def_crease);
        } else if constexpr (std::is_same_v<T, cmd::CreaseSetEdge>) {
          if (!name_ok(c.layer)) return false;
          verse_send_g_crease_set_edge(n, c.layer.c_str(), c.def_crease);
        } else if constexpr (std::is_same_v<T, cmd::BoneCreate>) {
          if (!name_ok(c.weight) || !name_ok(c.reference) || !name_ok(c.pos_label) || !name_ok(c.rot_label))
            return false;
          // r6's bone_create (v_cmd_def_g.c) carries no rotation value: it is not sent.
          verse_send_g_bone_create(n, c.bone_id, c.weight.c_str(), c.reference.c_str(), c.parent, c.pos[0], c.pos[1],
                                   c.pos[2], c.pos_label.c_str(), c.rot_label.c_str(), "");
        } else {
          static_assert(std::is_same_v<T, cmd::BoneDestroy>);
          verse_send_g_bone_destroy(n, c.bone_id);
        }
        return true;
      },
      command);
}

std::string snapshot() {
  std::map<std::uint16_t, vgc::Layer> layers = g.mirror.layers();
  for (auto& [id, l] : layers) {
    auto it = g.suite_subs.find(id);
    l.subscription = it == g.suite_subs.end() ? std::nullopt : std::optional<vgc::RealFormat>(it->second);
  }
  return vgc::print_snapshot(
      vgc::SnapshotParts{layers, g.mirror.vertex_crease(), g.mirror.edge_crease(), g.mirror.bones()});
}

// The reference's derivation of the state r6 stores (r6 derives nothing).
std::string derived() {
  vgc::Node node;
  namespace cmd = vgc::cmd;
  const auto& layers = g.mirror.layers();
  for (const auto& [id, l] : layers)
    if (id >= 2) node.apply(cmd::LayerCreate{id, l.name, static_cast<std::uint8_t>(l.type), l.def_uint, l.def_real});
  if (layers.count(0))
    for (const auto& [v, s] : layers.at(0).slots) node.apply(cmd::VertexSetXyzReal64{0, v, s.r[0], s.r[1], s.r[2]});
  if (layers.count(1))
    for (const auto& [p, s] : layers.at(1).slots) node.apply(cmd::PolygonSetCornerUint32{1, p, s.u});
  for (const auto& [id, l] : layers) {
    if (id < 2) continue;
    for (const auto& [e, s] : l.slots) {
      switch (l.type) {
        case vgc::LayerType::VertexXyz: node.apply(cmd::VertexSetXyzReal64{id, e, s.r[0], s.r[1], s.r[2]}); break;
        case vgc::LayerType::VertexUint32: node.apply(cmd::VertexSetUint32{id, e, s.u[0]}); break;
        case vgc::LayerType::VertexReal: node.apply(cmd::VertexSetReal64{id, e, s.r[0]}); break;
        case vgc::LayerType::PolygonCornerUint32: node.apply(cmd::PolygonSetCornerUint32{id, e, s.u}); break;
        case vgc::LayerType::PolygonCornerReal: node.apply(cmd::PolygonSetCornerReal64{id, e, s.r}); break;
        case vgc::LayerType::PolygonFaceUint8:
          node.apply(cmd::PolygonSetFaceUint8{id, e, static_cast<std::uint8_t>(s.u[0])});
          break;
        case vgc::LayerType::PolygonFaceUint32: node.apply(cmd::PolygonSetFaceUint32{id, e, s.u[0]}); break;
        case vgc::LayerType::PolygonFaceReal: node.apply(cmd::PolygonSetFaceReal64{id, e, s.r[0]}); break;
      }
    }
  }
  node.apply(cmd::CreaseSetVertex{g.mirror.vertex_crease().layer, g.mirror.vertex_crease().def_crease});
  node.apply(cmd::CreaseSetEdge{g.mirror.edge_crease().layer, g.mirror.edge_crease().def_crease});
  // r6 keeps a bone whose weight or reference layer was destroyed or
  // renamed since (it checks no layer at all), and so does the reference
  // for a layer renamed after the bone; but the reference refuses to
  // *create* such a bone. So the bones are created while a stand-in layer
  // of each missing name exists, and the stand-ins are destroyed after:
  // the derivation then poses every bone r6 stores, as the model does.
  std::vector<std::uint16_t> stand_ins;
  for (const auto& [id, b] : g.mirror.bones())
    for (const std::string& name : {b.weight, b.reference})
      if (!name.empty() && !node.find_layer_by_name(name)) {
        node.apply(cmd::LayerCreate{vgc::kNone16, name, static_cast<std::uint8_t>(vgc::LayerType::VertexUint32), 0, 0});
        if (const vgc::Layer* l = node.find_layer_by_name(name)) stand_ins.push_back(l->id);
      }
  for (const auto& [id, b] : g.mirror.bones())
    node.apply(cmd::BoneCreate{id, b.weight, b.reference, b.parent, b.pos, b.pos_label, b.rot, b.rot_label});
  for (std::uint16_t id : stand_ins) node.apply(cmd::LayerDestroy{id});
  return vgc::print_derived(node);
}

// Answers go to the stdout vgc reads; r6's library prints progress with
// printf ("Handling connection, stage 1"), which main() sends to stderr.
std::FILE* g_answers = nullptr;
void answer(const std::string& text) {
  std::fwrite(text.data(), 1, text.size(), g_answers);
  std::fflush(g_answers);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: vgc_r6_exec HOST:PORT   (an exec program for vgc certify --impl exec:...)\n");
    return 2;
  }
  const std::string host = argv[1];
  g_answers = fdopen(dup(STDOUT_FILENO), "w");
  std::fflush(stdout);
  dup2(STDERR_FILENO, STDOUT_FILENO);
  if (g_answers == nullptr) give_up("cannot keep stdout for the answers");
  register_callbacks();
  if (verse_send_connect("vgc-r6-exec", "vgc", host.c_str(), nullptr) == nullptr) give_up("cannot reach " + host);
  pump_until([] { return g.accepted; }, "logging in to " + host);
  verse_send_node_index_subscribe(1u << V_NT_GEOMETRY);
  std::string line;
  while (std::getline(std::cin, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line == "?hello") {
      answer("vgc-exec 1 r6 host " + host + " through r6's libverse.a (vgc_r6_exec)\n");
    } else if (line == "?reset") {
      reset_node();
      answer("ok\n");
    } else if (line == "?snapshot") {
      if (!g.mirror_error.empty()) give_up("the host sent more state than vgc keeps: " + g.mirror_error);
      answer(snapshot());
    } else if (line == "?derived") {
      answer(derived());
    } else if (line == "?capabilities") {
      // What a Verse host behind r6's library cannot show (declared_profile.h,
      // docs/adapters.md "A declared profile"), as the wire route says it.
      answer("capabilities profile:no-derived profile:subscriptions-unseen profile:no-verdicts "
             "profile:no-bone-rotation profile:no-requests profile:c-string-names\nend\n");
    } else if (line == "?quit") {
      break;
    } else if (!line.empty() && line[0] == '?') {
      answer("error unknown request " + line + "\n");
    } else {
      vgc::Command c;
      bool blank = false;
      vgc::TextError error;
      if (!vgc::parse_command_line(line, 1, &c, &blank, &error) || blank) {
        answer("error cannot parse the command line\n");
        continue;
      }
      if (g.node == 0xFFFFFFFFu) reset_node();
      g.announced.clear();
      const bool sent = send(c);
      if (sent) settle(line);
      // A host's broadcasts are its verdict (as on the wire route): a
      // command whose own kind the host announced for the node was
      // applied, even when the state shows no change (a delete of what was
      // not live). Otherwise the verdict is not known: `done`.
      answer(sent && announced_verdict(c) ? "ok\n" : "done\n");
    }
  }
  verse_send_connect_terminate(host.c_str(), "vgc_r6_exec done");
  verse_callback_update(10000);
  return 0;
}
