// r6_client.cpp — vgc_r6_client: our own client on an already-built r6
// libverse.a. It runs one scripted session that uses every geometry command
// (48..64) and every alias through r6's own API, against any Verse host:
//
//   vgc_r6_client record HOST:PORT OUT.txt   the transcript (r6_tap.h) of
//                                            every packet, both directions
//   vgc_r6_client check HOST:PORT            the state read back after each
//                                            step must be what the spec says
//
// Spec: docs/verse_wire.md section 12 (the session, the transcript format,
// what `check` expects and which of it r6's own host does differently);
// docs/spec_facts.md sections 3-4 (commands and aliases).
//
// Rationale: the only client library a Verse host meets in the field is
// r6's, and it does not keep the order of one flush (v_network_out_que.c
// sorts commands by a hash of their address). The script therefore drains
// its queue and does a name round trip between steps that depend on each
// other, like a careful r6 client must; step "burst" sends a layer, three
// vertices and a triangle in one flush on purpose (issue 18).
// Every wait is bounded; exit 0 ok, 1 a check failed, 2 no session.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <map>
#include <string>
#include <vector>

extern "C" {
#include "verse.h"
}

#include "r6_callbacks.h"
#include "r6_tap.h"

namespace {

using r6tap::r32;
using r6tap::r64;
using r6tap::str;

// ---- what the host told us: a mirror of the node, from callbacks only ----
struct Layer {
  std::string name;
  unsigned type = 0;
  std::uint32_t def_uint = 0;
  double def_real = 0;
  std::map<std::uint32_t, std::string> slots;  // element id -> value text
};
struct Mirror {
  bool accepted = false, terminated = false;
  std::uint32_t avatar = 0;
  std::uint32_t node = 0xFFFFFFFFu;
  std::string node_name;
  std::map<unsigned, Layer> layers;
  std::string crease_vertex, crease_edge;
  std::map<unsigned, std::string> bones;
} g;

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : " ") + s;
  return out;
}

// Records the decoded text (r6_tap) and tells whether to act on it.
bool note(const std::string& text) {
  static const bool debug = std::getenv("VGC_R6_DEBUG") != nullptr;
  if (debug) std::fprintf(stderr, "%s %s\n", r6tap::decode_only() ? "sent" : "recv", text.c_str());
  r6tap::note_decoded(text);
  return !r6tap::decode_only();
}

std::string nd(VNodeID n) { return "node=" + std::to_string(n); }

// ---- callbacks: one per command and alias r6 can decode ----
void cb_accept(void*, uint32 avatar, void*, void*, uint8*) {
  g.accepted = true;
  g.avatar = avatar;
  r6tap::data_key();  // the data key is set now; keep it for the transcript
}
void cb_terminate(void*, char* address, const char* bye) {
  if (note("connect_terminate bye=" + str(bye))) g.terminated = true;
  (void)address;
}
void cb_node_index_subscribe(void*, uint32 mask) { note("node_index_subscribe mask=" + std::to_string(mask)); }
void cb_node_create(void*, VNodeID node, VNodeType type, VNodeOwner owner) {
  if (note("node_create " + nd(node) + " type=" + std::to_string(type) + " owner=" + std::to_string(owner)) &&
      type == V_NT_GEOMETRY && owner == VN_OWNER_MINE && g.node == 0xFFFFFFFFu)
    g.node = node;
}
void cb_node_destroy(void*, VNodeID node) { note("node_destroy " + nd(node)); }
void cb_node_subscribe(void*, VNodeID node) { note("node_subscribe " + nd(node)); }
void cb_node_unsubscribe(void*, VNodeID node) { note("node_unsubscribe " + nd(node)); }
void cb_tag_group_create(void*, VNodeID node, uint16 group, const char* name) {
  note("tag_group_create " + nd(node) + " group=" + std::to_string(group) + " name=" + str(name));
}
void cb_tag_group_destroy(void*, VNodeID node, uint16 group) {
  note("tag_group_destroy " + nd(node) + " group=" + std::to_string(group));
}
void cb_node_name_set(void*, VNodeID node, const char* name) {
  if (note("node_name_set " + nd(node) + " name=" + str(name)) && node == g.node) g.node_name = name;
}

void cb_layer_create(void*, VNodeID node, VLayerID layer, const char* name, VNGLayerType type, uint32 def_uint,
                     real64 def_real) {
  if (!note("g_layer_create " + nd(node) + " layer=" + std::to_string(layer) + " name=" + str(name) +
            " type=" + std::to_string(type) + " def_uint=" + std::to_string(def_uint) + " def_real=" + r64(def_real)))
    return;
  Layer& l = g.layers[layer];
  if (l.type != static_cast<unsigned>(type) || l.name != name) l.slots.clear();
  l.name = name;
  l.type = type;
  l.def_uint = def_uint;
  l.def_real = def_real;
}
void cb_layer_destroy(void*, VNodeID node, VLayerID layer) {
  if (note("g_layer_destroy " + nd(node) + " layer=" + std::to_string(layer))) g.layers.erase(layer);
}
void cb_layer_subscribe(void*, VNodeID node, VLayerID layer, VNRealFormat type) {
  note("g_layer_subscribe " + nd(node) + " layer=" + std::to_string(layer) + " type=" + std::to_string(type));
}
void cb_layer_unsubscribe(void*, VNodeID node, VLayerID layer) {
  note("g_layer_unsubscribe " + nd(node) + " layer=" + std::to_string(layer));
}
void set_slot(VLayerID layer, uint32 id, const std::string& value) { g.layers[layer].slots[id] = value; }
void delete_vertex(uint32 id) {
  for (auto& [lid, l] : g.layers)
    if (l.type < 128) l.slots.erase(id);
}
void delete_polygon(uint32 id) {
  for (auto& [lid, l] : g.layers)
    if (l.type >= 128) l.slots.erase(id);
}
std::string slot_head(const char* verb, VNodeID node, VLayerID layer, const char* what, uint32 id) {
  return std::string(verb) + " " + nd(node) + " layer=" + std::to_string(layer) + " " + what + "=" +
         std::to_string(id);
}
void cb_xyz32(void*, VNodeID node, VLayerID layer, uint32 v, real32 x, real32 y, real32 z) {
  if (note(slot_head("g_vertex_set_xyz_real32", node, layer, "vertex", v) + " x=" + r32(x) + " y=" + r32(y) +
           " z=" + r32(z)))
    set_slot(layer, v, join({r64(x), r64(y), r64(z)}));
}
void cb_xyz64(void*, VNodeID node, VLayerID layer, uint32 v, real64 x, real64 y, real64 z) {
  if (note(slot_head("g_vertex_set_xyz_real64", node, layer, "vertex", v) + " x=" + r64(x) + " y=" + r64(y) +
           " z=" + r64(z)))
    set_slot(layer, v, join({r64(x), r64(y), r64(z)}));
}
void cb_vdel32(void*, VNodeID node, uint32 v) {
  if (note("g_vertex_delete_real32 " + nd(node) + " vertex=" + std::to_string(v))) delete_vertex(v);
}
void cb_vdel64(void*, VNodeID node, uint32 v) {
  if (note("g_vertex_delete_real64 " + nd(node) + " vertex=" + std::to_string(v))) delete_vertex(v);
}
void cb_vuint(void*, VNodeID node, VLayerID layer, uint32 v, uint32 value) {
  if (note(slot_head("g_vertex_set_uint32", node, layer, "vertex", v) + " value=" + std::to_string(value)))
    set_slot(layer, v, std::to_string(value));
}
void cb_vreal64(void*, VNodeID node, VLayerID layer, uint32 v, real64 value) {
  if (note(slot_head("g_vertex_set_real64", node, layer, "vertex", v) + " value=" + r64(value)))
    set_slot(layer, v, r64(value));
}
void cb_vreal32(void*, VNodeID node, VLayerID layer, uint32 v, real32 value) {
  if (note(slot_head("g_vertex_set_real32", node, layer, "vertex", v) + " value=" + r32(value)))
    set_slot(layer, v, r64(value));
}
void cb_corner_uint(void*, VNodeID node, VLayerID layer, uint32 p, uint32 v0, uint32 v1, uint32 v2, uint32 v3) {
  std::vector<std::string> v = {std::to_string(v0), std::to_string(v1), std::to_string(v2), std::to_string(v3)};
  if (note(slot_head("g_polygon_set_corner_uint32", node, layer, "polygon", p) + " v0=" + v[0] + " v1=" + v[1] +
           " v2=" + v[2] + " v3=" + v[3]))
    set_slot(layer, p, join(v));
}
void cb_pdel(void*, VNodeID node, uint32 p) {
  if (note("g_polygon_delete " + nd(node) + " polygon=" + std::to_string(p))) delete_polygon(p);
}
void cb_corner64(void*, VNodeID node, VLayerID layer, uint32 p, real64 v0, real64 v1, real64 v2, real64 v3) {
  if (note(slot_head("g_polygon_set_corner_real64", node, layer, "polygon", p) + " v0=" + r64(v0) + " v1=" +
           r64(v1) + " v2=" + r64(v2) + " v3=" + r64(v3)))
    set_slot(layer, p, join({r64(v0), r64(v1), r64(v2), r64(v3)}));
}
void cb_corner32(void*, VNodeID node, VLayerID layer, uint32 p, real32 v0, real32 v1, real32 v2, real32 v3) {
  if (note(slot_head("g_polygon_set_corner_real32", node, layer, "polygon", p) + " v0=" + r32(v0) + " v1=" +
           r32(v1) + " v2=" + r32(v2) + " v3=" + r32(v3)))
    set_slot(layer, p, join({r64(v0), r64(v1), r64(v2), r64(v3)}));
}
void cb_face_u8(void*, VNodeID node, VLayerID layer, uint32 p, uint8 value) {
  if (note(slot_head("g_polygon_set_face_uint8", node, layer, "polygon", p) + " value=" + std::to_string(value)))
    set_slot(layer, p, std::to_string(value));
}
void cb_face_u32(void*, VNodeID node, VLayerID layer, uint32 p, uint32 value) {
  if (note(slot_head("g_polygon_set_face_uint32", node, layer, "polygon", p) + " value=" + std::to_string(value)))
    set_slot(layer, p, std::to_string(value));
}
void cb_face64(void*, VNodeID node, VLayerID layer, uint32 p, real64 value) {
  if (note(slot_head("g_polygon_set_face_real64", node, layer, "polygon", p) + " value=" + r64(value)))
    set_slot(layer, p, r64(value));
}
void cb_face32(void*, VNodeID node, VLayerID layer, uint32 p, real32 value) {
  if (note(slot_head("g_polygon_set_face_real32", node, layer, "polygon", p) + " value=" + r32(value)))
    set_slot(layer, p, r64(value));
}
void cb_crease_vertex(void*, VNodeID node, const char* layer, uint32 def) {
  if (note("g_crease_set_vertex " + nd(node) + " layer=" + str(layer) + " def_crease=" + std::to_string(def)))
    g.crease_vertex = str(layer) + " " + std::to_string(def);
}
void cb_crease_edge(void*, VNodeID node, const char* layer, uint32 def) {
  if (note("g_crease_set_edge " + nd(node) + " layer=" + str(layer) + " def_crease=" + std::to_string(def)))
    g.crease_edge = str(layer) + " " + std::to_string(def);
}
void cb_bone_create(void*, VNodeID node, uint16 bone, const char* weight, const char* reference, uint16 parent,
                    real64 x, real64 y, real64 z, const char* pos_label, const char* rot_label,
                    const char* scale_label) {
  std::string fields = "weight=" + str(weight) + " reference=" + str(reference) + " parent=" +
                       std::to_string(parent) + " pos_x=" + r64(x) + " pos_y=" + r64(y) + " pos_z=" + r64(z) +
                       " position_label=" + str(pos_label) + " rotation_label=" + str(rot_label) +
                       " scale_label=" + str(scale_label);
  if (note("g_bone_create " + nd(node) + " bone=" + std::to_string(bone) + " " + fields)) g.bones[bone] = fields;
}
void cb_bone_destroy(void*, VNodeID node, uint16 bone) {
  if (note("g_bone_destroy " + nd(node) + " bone=" + std::to_string(bone))) g.bones.erase(bone);
}

void register_callbacks() {
  VGC_R6_NODE_CALLBACKS(VGC_R6_REGISTER)
  VGC_R6_GEOMETRY_CALLBACKS(VGC_R6_REGISTER)
  // What only the recording client takes.
  VGC_R6_REGISTER(verse_send_node_index_subscribe, cb_node_index_subscribe)
  VGC_R6_REGISTER(verse_send_node_destroy, cb_node_destroy)
  VGC_R6_REGISTER(verse_send_node_subscribe, cb_node_subscribe)
  VGC_R6_REGISTER(verse_send_node_unsubscribe, cb_node_unsubscribe)
  VGC_R6_REGISTER(verse_send_tag_group_create, cb_tag_group_create)
  VGC_R6_REGISTER(verse_send_tag_group_destroy, cb_tag_group_destroy)
  VGC_R6_REGISTER(verse_send_g_layer_subscribe, cb_layer_subscribe)
  VGC_R6_REGISTER(verse_send_g_layer_unsubscribe, cb_layer_unsubscribe)
}

// ---- bounded waiting ----
double now_s() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + t.tv_nsec / 1e9;
}
bool pump_until(const std::function<bool()>& done, double seconds) {
  double end = now_s() + seconds;
  while (!done()) {
    if (now_s() > end || g.terminated) return false;
    verse_callback_update(5000);
  }
  return true;
}
// Everything queued goes out, then a node_name_set round trip: the host
// has processed what we sent and we have what it sent back. r6 has no call
// that says "the unsent queue is empty" (verse_session_get_size() also
// counts its ack-only packets, which nobody acknowledges), so the queue is
// given 30 ms of verse_callback_update() first: each call sends a packet of
// up to 1500 bytes, and no step here is bigger than one packet. The name
// then goes in a later packet, and a host handles packets in id order.
int g_barrier = 0;
bool settle(double seconds = 5.0) {
  double until = now_s() + 0.03;
  pump_until([&] { return now_s() > until; }, 1);
  std::string name = "r6b-" + std::to_string(++g_barrier);
  verse_send_node_name_set(g.node, name.c_str());
  return pump_until([&] { return g.node_name == name; }, seconds);
}
// The layer id the host gave the layer of this name (0xFFFF when none).
VLayerID layer_named(const std::string& name) {
  for (const auto& [id, l] : g.layers)
    if (l.name == name) return static_cast<VLayerID>(id);
  return 0xFFFF;
}

// ---- the check mode's expectations ----
int g_failures = 0;
bool g_checking = false;
void expect(const std::string& step, const std::string& what, const std::string& want, const std::string& got) {
  if (!g_checking) return;
  if (want == got) return;
  ++g_failures;
  std::fprintf(stdout, "FAIL %s: %s: expected \"%s\", read back \"%s\"\n", step.c_str(), what.c_str(), want.c_str(),
               got.c_str());
}
std::string slot(const std::string& layer, std::uint32_t id) {
  VLayerID l = layer_named(layer);
  if (l == 0xFFFF) return "(no layer " + layer + ")";
  auto it = g.layers[l].slots.find(id);
  return it == g.layers[l].slots.end() ? "(none)" : it->second;
}
std::string base_slot(unsigned layer, std::uint32_t id) {
  auto it = g.layers[layer].slots.find(id);
  return it == g.layers[layer].slots.end() ? "(none)" : it->second;
}

struct Names {
  const char* name;
  VNGLayerType type;
  uint32 def_uint;
  double def_real;
};
const Names kLayers[] = {
    {"v_uint", VN_G_LAYER_VERTEX_UINT32, 7, 0},        {"v_real", VN_G_LAYER_VERTEX_REAL, 0, 0.25},
    {"v_xyz", VN_G_LAYER_VERTEX_XYZ, 0, 0},            {"p_cuint", VN_G_LAYER_POLYGON_CORNER_UINT32, 0, 0},
    {"p_creal", VN_G_LAYER_POLYGON_CORNER_REAL, 0, 0}, {"p_fu8", VN_G_LAYER_POLYGON_FACE_UINT8, 0, 0},
    {"p_fu32", VN_G_LAYER_POLYGON_FACE_UINT32, 0, 0},  {"p_freal", VN_G_LAYER_POLYGON_FACE_REAL, 0, 0},
    {"doomed", VN_G_LAYER_VERTEX_UINT32, 0, 0},
};
const uint32 kNone = 0xFFFFFFFFu;

// One step's outcome: false (and the step's name kept) when the host did
// not answer in time.
using Check = std::function<bool(const char*, bool)>;

// login: index subscription, our node, its base layers
bool step_login(const Check& check) {
  verse_send_node_index_subscribe(1u << V_NT_GEOMETRY);
  verse_send_node_create(~0u, V_NT_GEOMETRY, VN_OWNER_MINE);
  if (!check("node_create", pump_until([] { return g.node != 0xFFFFFFFFu; }, 5))) return false;
  verse_send_node_subscribe(g.node);
  if (!check("node_subscribe",
            pump_until([] { return g.layers.count(0) != 0 && g.layers.count(1) != 0; }, 5) && settle()))
    return false;
  verse_send_g_layer_subscribe(g.node, 0, VN_FORMAT_REAL32);
  verse_send_g_layer_subscribe(g.node, 1, VN_FORMAT_REAL32);
  return true;
}

// step layers: one of every type, the host picks the ids
bool step_layers(const Check& check) {
  for (const Names& l : kLayers) verse_send_g_layer_create(g.node, 0xFFFF, l.name, l.type, l.def_uint, l.def_real);
  if (!check("layers", settle())) return false;
  for (const Names& l : kLayers) {
    expect("layers", std::string("layer ") + l.name, "1", layer_named(l.name) == 0xFFFF ? "0" : "1");
    if (layer_named(l.name) != 0xFFFF) verse_send_g_layer_subscribe(g.node, layer_named(l.name), VN_FORMAT_REAL32);
  }
  if (!check("subscribe", settle())) return false;
  return true;
}

// step vertices, then polygons (each after the other has arrived)
bool step_geometry(const Check& check) {
  verse_send_g_vertex_set_xyz_real32(g.node, 0, 0, 0, 0, 0);
  verse_send_g_vertex_set_xyz_real32(g.node, 0, 1, 1, 0, 0);
  verse_send_g_vertex_set_xyz_real64(g.node, 0, 2, 0, 1, 0);
  verse_send_g_vertex_set_xyz_real64(g.node, 0, 3, -4, -4, -4);
  verse_send_g_vertex_set_xyz_real32(g.node, 0, 4, 2, 2, 2);
  if (!check("vertices", settle())) return false;
  expect("vertices", "vertex 2", "0 1 0", base_slot(0, 2));
  expect("vertices", "vertex 3", "-4 -4 -4", base_slot(0, 3));
  verse_send_g_polygon_set_corner_uint32(g.node, 1, 0, 0, 1, 2, kNone);
  verse_send_g_polygon_set_corner_uint32(g.node, 1, 1, 0, 1, 2, 3);
  if (!check("polygons", settle())) return false;
  expect("polygons", "polygon 0", "0 1 2 4294967295", base_slot(1, 0));
  expect("polygons", "polygon 1", "0 1 2 3", base_slot(1, 1));
  return true;
}

// step slots: every set command on a layer of its type
bool step_slots(const Check& check) {
  verse_send_g_vertex_set_uint32(g.node, layer_named("v_uint"), 1, 42);
  verse_send_g_vertex_set_real64(g.node, layer_named("v_real"), 0, -4.0);
  verse_send_g_vertex_set_real32(g.node, layer_named("v_real"), 2, 1.5f);
  verse_send_g_vertex_set_xyz_real32(g.node, layer_named("v_xyz"), 1, 1, 2, 3);
  verse_send_g_vertex_set_xyz_real64(g.node, layer_named("v_xyz"), 3, -4, 0.5, 3.25);
  verse_send_g_polygon_set_corner_uint32(g.node, layer_named("p_cuint"), 0, 10, 11, 12, 13);
  verse_send_g_polygon_set_corner_real64(g.node, layer_named("p_creal"), 0, 0.5, -4, 2, 0);
  verse_send_g_polygon_set_corner_real32(g.node, layer_named("p_creal"), 1, 1, 2, 3, 4);
  verse_send_g_polygon_set_face_uint8(g.node, layer_named("p_fu8"), 0, 200);
  verse_send_g_polygon_set_face_uint32(g.node, layer_named("p_fu32"), 1, 123456);
  verse_send_g_polygon_set_face_real64(g.node, layer_named("p_freal"), 0, -4.0);
  verse_send_g_polygon_set_face_real32(g.node, layer_named("p_freal"), 1, 0.125f);
  verse_send_g_crease_set_vertex(g.node, "v_uint", 5);
  verse_send_g_crease_set_edge(g.node, "p_cuint", 9);
  if (!check("slots", settle())) return false;
  expect("slots", "v_uint[1]", "42", slot("v_uint", 1));
  expect("slots", "v_real[0]", "-4", slot("v_real", 0));
  expect("slots", "v_real[2]", "1.5", slot("v_real", 2));
  expect("slots", "v_xyz[1]", "1 2 3", slot("v_xyz", 1));
  expect("slots", "v_xyz[3]", "-4 0.5 3.25", slot("v_xyz", 3));
  expect("slots", "p_cuint[0]", "10 11 12 13", slot("p_cuint", 0));
  expect("slots", "p_creal[0]", "0.5 -4 2 0", slot("p_creal", 0));
  expect("slots", "p_creal[1]", "1 2 3 4", slot("p_creal", 1));
  expect("slots", "p_fu8[0]", "200", slot("p_fu8", 0));
  expect("slots", "p_fu32[1]", "123456", slot("p_fu32", 1));
  expect("slots", "p_freal[0]", "-4", slot("p_freal", 0));
  expect("slots", "p_freal[1]", "0.125", slot("p_freal", 1));
  expect("slots", "crease vertex", "v_uint 5", g.crease_vertex);
  expect("slots", "crease edge", "p_cuint 9", g.crease_edge);
  return true;
}

// step bone: r6's own form of bone_create (v_cmd_def_g.c), in a flush of its own
bool step_bone(const Check& check) {
  verse_send_g_bone_create(g.node, 0xFFFF, "v_real", "v_uint", 0xFFFF, 1, 2, 3, "pl", "rl", "sl");
  if (!check("bone", settle())) return false;
  expect("bone", "bones", "1", std::to_string(g.bones.size()));
  // Spec 2.6.3 has no scale label (r6's form does): compared up to it.
  std::string bone = g.bones.empty() ? "(none)" : g.bones.begin()->second;
  expect("bone", "bone fields",
         "weight=v_real reference=v_uint parent=65535 pos_x=1 pos_y=2 pos_z=3 position_label=pl rotation_label=rl",
         bone.substr(0, bone.find(" scale_label=")));
  return true;
}

// step real64: every real layer again at REAL64 (the 49 alias, then 49)
bool step_real64(const Check& check) {
  std::vector<VLayerID> reals = {0, 1, layer_named("v_real"), layer_named("v_xyz"), layer_named("p_creal"),
                                 layer_named("p_freal")};
  for (VLayerID l : reals) verse_send_g_layer_unsubscribe(g.node, l);
  if (!check("unsubscribe", settle())) return false;
  for (VLayerID l : reals) verse_send_g_layer_subscribe(g.node, l, VN_FORMAT_REAL64);
  if (!check("real64", settle())) return false;
  expect("real64", "vertex 3", "-4 -4 -4", base_slot(0, 3));
  expect("real64", "v_real[0]", "-4", slot("v_real", 0));
  expect("real64", "p_creal[0]", "0.5 -4 2 0", slot("p_creal", 0));
  return true;
}

// step deletes: polygon 1, vertex 3 (real64 alias), the bone, a layer
bool step_deletes(const Check& check) {
  verse_send_g_polygon_delete(g.node, 1);
  if (!check("polygon_delete", settle())) return false;
  verse_send_g_vertex_delete_real64(g.node, 3);
  if (!g.bones.empty()) verse_send_g_bone_destroy(g.node, static_cast<uint16>(g.bones.begin()->first));
  verse_send_g_layer_destroy(g.node, layer_named("doomed"));
  if (!check("deletes", settle())) return false;
  expect("deletes", "polygon 1", "(none)", base_slot(1, 1));
  expect("deletes", "vertex 3", "(none)", base_slot(0, 3));
  expect("deletes", "bones", "0", std::to_string(g.bones.size()));
  expect("deletes", "layer doomed", "0", layer_named("doomed") == 0xFFFF ? "0" : "1");
  return true;
}

// step real32 delete: layer 0 at REAL32 again, vertex 4 by the real32 alias
bool step_real32_delete(const Check& check) {
  verse_send_g_layer_unsubscribe(g.node, 0);
  if (!check("resubscribe", settle())) return false;
  verse_send_g_layer_subscribe(g.node, 0, VN_FORMAT_REAL32);
  if (!check("resubscribe", settle())) return false;
  verse_send_g_vertex_delete_real32(g.node, 4);
  verse_send_g_crease_set_vertex(g.node, "", 0);
  if (!check("delete_real32", settle())) return false;
  expect("delete_real32", "vertex 4", "(none)", base_slot(0, 4));
  expect("delete_real32", "vertex 0", "0 0 0", base_slot(0, 0));
  expect("delete_real32", "crease vertex", "\\empty 0", g.crease_vertex);
  return true;
}

// step burst (issue 18): a layer, three vertices and a triangle in one flush
bool step_burst(const Check& check) {
  verse_send_g_layer_create(g.node, 0xFFFF, "burst", VN_G_LAYER_VERTEX_UINT32, 0, 0);
  verse_send_g_vertex_set_xyz_real32(g.node, 0, 10, 5, 5, 5);
  verse_send_g_vertex_set_xyz_real32(g.node, 0, 11, 6, 5, 5);
  verse_send_g_vertex_set_xyz_real32(g.node, 0, 12, 5, 6, 5);
  verse_send_g_polygon_set_corner_uint32(g.node, 1, 5, 10, 11, 12, kNone);
  if (!check("burst", settle())) return false;
  expect("burst", "layer burst", "1", layer_named("burst") == 0xFFFF ? "0" : "1");
  expect("burst", "vertex 12", "5 6 5", base_slot(0, 12));
  expect("burst", "polygon 5", "10 11 12 4294967295", base_slot(1, 5));
  return true;
}

// the end: the node goes, the session says goodbye
bool step_end(const Check& check) {
  verse_send_node_destroy(g.node);
  double until = now_s() + 0.1;
  return check("node_destroy", pump_until([&] { return now_s() > until; }, 1));
}

// The scripted session, step by step; false when a step could not
// complete (no answer), *failed_step naming it.
bool run_script(std::string* failed_step) {
  const Check check = [&](const char* name, bool ok) {
    if (!ok && failed_step->empty()) *failed_step = name;
    return ok;
  };
  for (bool (*step)(const Check&) : {step_login, step_layers, step_geometry, step_slots, step_bone, step_real64,
                                     step_deletes, step_real32_delete, step_burst, step_end})
    if (!step(check)) return false;
  return true;
}

bool write_transcript(const char* path, const char* host) {
  std::FILE* f = std::fopen(path, "w");
  if (f == nullptr) return false;
  std::fprintf(f,
               "# vgc r6 interop transcript (docs/verse_wire.md section 12): what r6's client library\n"
               "# (libverse.a, linked by tests/verse/r6_interop) sent and received in the scripted session\n"
               "# of r6_client.cpp, and what r6's own unpackers decoded from each data packet.\n"
               "# packet <r|s> <id>   r: received by r6's library, s: sent by it\n"
               "# raw <hex>           the datagram on the wire (encrypted with the key)\n"
               "# plain <hex>         the same after r6's decryption\n"
               "# cmd <no> <len> <r6's callback and its arguments>   len: bytes after the command byte\n");
  std::fprintf(f, "host %s\n", host);
  std::fprintf(f, "key %s\n", r6tap::hex(r6tap::data_key()).c_str());
  for (const r6tap::PacketRecord& p : r6tap::records()) {
    if (!p.unpacked || p.raw.empty()) continue;
    std::fprintf(f, "packet %c %u\nraw %s\nplain %s\n", p.dir, p.id, r6tap::hex(p.raw).c_str(),
                 r6tap::hex(p.plain).c_str());
    for (const r6tap::Cmd& c : p.cmds)
      std::fprintf(f, "cmd %u %u %s\n", c.number, c.length, c.decoded.empty() ? "(no callback)" : c.decoded.c_str());
  }
  std::fprintf(f, "end\n");
  return std::fclose(f) == 0;
}

int usage() {
  std::fprintf(stderr,
               "usage: vgc_r6_client record HOST:PORT OUT.txt\n"
               "       vgc_r6_client check HOST:PORT\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  std::string mode = argv[1];
  if ((mode == "record" && argc != 4) || (mode == "check" && argc != 3) || (mode != "record" && mode != "check"))
    return usage();
  g_checking = mode == "check";
  register_callbacks();
  if (verse_send_connect("vgc-r6", "vgc", argv[2], nullptr) == nullptr) {
    std::fprintf(stderr, "vgc_r6_client: cannot reach %s\n", argv[2]);
    return 2;
  }
  if (!pump_until([] { return g.accepted; }, 10)) {
    std::fprintf(stderr, "vgc_r6_client: no login accept from %s within 10 s\n", argv[2]);
    return 2;
  }
  std::string failed;
  bool ran = run_script(&failed);
  if (!ran) std::fprintf(stdout, "FAIL step %s: no answer from the host within 5 s\n", failed.c_str());
  verse_send_connect_terminate(argv[2], "vgc_r6_client done");
  pump_until([] { return false; }, 0.2);
  if (mode == "record") {
    if (!ran || !write_transcript(argv[3], argv[2])) {
      std::fprintf(stderr, "vgc_r6_client: transcript not written\n");
      return 2;
    }
    return 0;
  }
  if (!ran) return 2;
  std::fprintf(stdout, "%s: %d check(s) failed\n", g_failures == 0 ? "ok" : "FAIL", g_failures);
  return g_failures == 0 ? 0 : 1;
}
