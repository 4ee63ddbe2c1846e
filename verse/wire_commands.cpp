// wire_commands.cpp — see wire_commands.h. Field order per command:
// docs/verse_wire.md sections 3 and 4 (from r6 v_cmd_def_s.c, v_cmd_def_g.c).
#include "wire_commands.h"

#include <array>
#include <cfloat>
#include <cstring>
#include <type_traits>

#include "wire_pack.h"

namespace vgc::verse {
namespace {

template <class T, class U>
inline constexpr bool is = std::is_same_v<std::decay_t<T>, U>;

constexpr std::uint8_t kUnsubscribeFormat = 0xFF;  // r6 g_layer_unsubscribe sends (uint8)-1

Status check_string(const std::string& s, const char* field) {
  if (s.find('\0') != std::string::npos)
    return Status::protocol_error(std::string("cannot encode ") + field + ": it holds a NUL byte");
  if (s.size() + 1 > kMaxWireString)
    return Status::protocol_error(std::string("cannot encode ") + field + ": " + std::to_string(s.size()) +
                                  " bytes, the wire carries at most " + std::to_string(kMaxWireString - 1));
  return {};
}

Status check_geometry_strings(const vgc::Command& c) {
  return std::visit(
      [](const auto& g) -> Status {
        using G = std::decay_t<decltype(g)>;
        if constexpr (is<G, cmd::LayerCreate>) return check_string(g.name, "layer name");
        if constexpr (is<G, cmd::CreaseSetVertex> || is<G, cmd::CreaseSetEdge>) return check_string(g.layer, "crease layer name");
        if constexpr (is<G, cmd::BoneCreate>) {
          for (const std::string* s : {&g.weight, &g.reference, &g.pos_label, &g.rot_label}) {
            Status st = check_string(*s, "bone name");
            if (!st.ok()) return st;
          }
        }
        return {};
      },
      c);
}

bool is_identity_rotation(const std::array<double, 4>& r) {
  static const std::array<double, 4> kIdentity{0, 0, 0, 1};
  return std::memcmp(r.data(), kIdentity.data(), sizeof kIdentity) == 0;  // bits: -0.0 is not carried either
}

// bone_create and its destroy alias in r6's form (v_gen_pack_g_node.c
// verse_send_g_bone_create / verse_send_g_bone_destroy).
void encode_bone_r6(const vgc::Command& c, PackWriter& w) {
  if (const auto* b = std::get_if<cmd::BoneCreate>(&c)) {
    w.u16(b->bone_id); w.string(b->weight); w.string(b->reference); w.u16(b->parent);
    for (double v : b->pos) w.f64(v);
    w.string(b->pos_label); w.string(b->rot_label); w.string("");
  } else if (const auto* d = std::get_if<cmd::BoneDestroy>(&c)) {
    w.u16(d->bone_id); w.string(""); w.string(""); w.u16(0xFFFF);
    for (int i = 0; i < 3; ++i) w.f64(DBL_MAX);
    w.string(""); w.string(""); w.string("");
  }
}

void encode_geometry(std::uint32_t node, const vgc::Command& c, PackWriter& w, BoneForm bones) {
  if (bones == BoneForm::R6 && geometry_command_number(c) == 64) {
    w.u8(64);
    w.u32(node);
    encode_bone_r6(c, w);
    return;
  }
  w.u8(geometry_command_number(c));
  w.u32(node);
  std::visit(
      [&](const auto& g) {
        using G = std::decay_t<decltype(g)>;
        if constexpr (is<G, cmd::LayerCreate>) {
          w.u16(g.layer_id); w.string(g.name); w.u8(g.type); w.u32(g.def_uint); w.f64(g.def_real);
        } else if constexpr (is<G, cmd::LayerDestroy>) {  // r6 verse_send_g_layer_destroy
          w.u16(g.layer_id); w.string(""); w.u8(0xFF); w.u32(0xFFFFFFFFu); w.f64(DBL_MAX);
        } else if constexpr (is<G, cmd::LayerSubscribe>) {
          w.u16(g.layer_id); w.u8(g.real_format);
        } else if constexpr (is<G, cmd::LayerUnsubscribe>) {
          w.u16(g.layer_id); w.u8(kUnsubscribeFormat);
        } else if constexpr (is<G, cmd::VertexSetXyzReal32>) {
          w.u16(g.layer_id); w.u32(g.vertex_id); w.f32(g.x); w.f32(g.y); w.f32(g.z);
        } else if constexpr (is<G, cmd::VertexSetXyzReal64>) {
          w.u16(g.layer_id); w.u32(g.vertex_id); w.f64(g.x); w.f64(g.y); w.f64(g.z);
        } else if constexpr (is<G, cmd::VertexDelete>) {  // r6 verse_send_g_vertex_delete_real32
          w.u16(0); w.u32(g.vertex_id); w.f32(FLT_MAX); w.f32(FLT_MAX); w.f32(FLT_MAX);
        } else if constexpr (is<G, cmd::VertexSetUint32>) {
          w.u16(g.layer_id); w.u32(g.vertex_id); w.u32(g.value);
        } else if constexpr (is<G, cmd::VertexSetReal64>) {
          w.u16(g.layer_id); w.u32(g.vertex_id); w.f64(g.value);
        } else if constexpr (is<G, cmd::VertexSetReal32>) {
          w.u16(g.layer_id); w.u32(g.vertex_id); w.f32(g.value);
        } else if constexpr (is<G, cmd::PolygonSetCornerUint32>) {
          w.u16(g.layer_id); w.u32(g.polygon_id);
          for (auto v : g.v) w.u32(v);
        } else if constexpr (is<G, cmd::PolygonSetCornerReal64>) {
          w.u16(g.layer_id); w.u32(g.polygon_id);
          for (auto v : g.v) w.f64(v);
        } else if constexpr (is<G, cmd::PolygonSetCornerReal32>) {
          w.u16(g.layer_id); w.u32(g.polygon_id);
          for (auto v : g.v) w.f32(v);
        } else if constexpr (is<G, cmd::PolygonDelete>) {  // r6 verse_send_g_polygon_delete
          w.u16(1); w.u32(g.polygon_id);
          for (int i = 0; i < 4; ++i) w.u32(0xFFFFFFFFu);
        } else if constexpr (is<G, cmd::PolygonSetFaceUint8>) {
          w.u16(g.layer_id); w.u32(g.polygon_id); w.u8(g.value);
        } else if constexpr (is<G, cmd::PolygonSetFaceUint32>) {
          w.u16(g.layer_id); w.u32(g.polygon_id); w.u32(g.value);
        } else if constexpr (is<G, cmd::PolygonSetFaceReal64>) {
          w.u16(g.layer_id); w.u32(g.polygon_id); w.f64(g.value);
        } else if constexpr (is<G, cmd::PolygonSetFaceReal32>) {
          w.u16(g.layer_id); w.u32(g.polygon_id); w.f32(g.value);
        } else if constexpr (is<G, cmd::CreaseSetVertex> || is<G, cmd::CreaseSetEdge>) {
          w.string(g.layer); w.u32(g.def_crease);
        } else if constexpr (is<G, cmd::BoneCreate>) {
          w.u16(g.bone_id); w.string(g.weight); w.string(g.reference); w.u16(g.parent);
          for (double v : g.pos) w.f64(v);
          w.string(g.pos_label);
          for (double v : g.rot) w.f64(v);
          w.string(g.rot_label);
        } else if constexpr (is<G, cmd::BoneDestroy>) {  // empty weight; the rest as r6's bone_destroy fills it
          w.u16(g.bone_id); w.string(""); w.string(""); w.u16(0xFFFF);
          for (int i = 0; i < 3; ++i) w.f64(DBL_MAX);
          w.string("");
          for (int i = 0; i < 4; ++i) w.f64(DBL_MAX);
          w.string("");
        }
      },
      c);
}

// Reads fields in order, remembering the first that is missing.
struct FieldReader {
  PackReader r;
  const char* command;
  const char* missing = nullptr;
  bool u8(std::uint8_t* v, const char* f) { return ok(r.u8(v), f); }
  bool u16(std::uint16_t* v, const char* f) { return ok(r.u16(v), f); }
  bool u32(std::uint32_t* v, const char* f) { return ok(r.u32(v), f); }
  bool f32(float* v, const char* f) { return ok(r.f32(v), f); }
  bool f64(double* v, const char* f) { return ok(r.f64(v), f); }
  bool str(std::string* s, const char* f) { return ok(r.string(s, kMaxWireString), f); }
  bool ok(bool b, const char* f) {
    if (!b && !missing) missing = f;
    return b && !missing;
  }
  Status status(std::size_t base) const {
    if (!missing) return {};
    return Status::protocol_error(std::string(command) + ": field " + missing + " truncated or unterminated at byte " +
                                  std::to_string(base + r.position()));
  }
};

bool is_flt_max(float v) { return v == FLT_MAX; }
bool is_dbl_max(double v) { return v == DBL_MAX; }

// Decodes fields after the node id of geometry command `number`.
bool decode_geometry_fields(std::uint8_t number, FieldReader& f, vgc::Command* out, BoneForm bones) {
  switch (number) {
    case 48: {
      cmd::LayerCreate c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.str(&c.name, "name") && f.u8(&c.type, "type") &&
            f.u32(&c.def_uint, "def_uint") && f.f64(&c.def_real, "def_real")))
        return false;
      if (c.name.empty()) *out = cmd::LayerDestroy{c.layer_id};
      else *out = c;
      return true;
    }
    case 49: {
      cmd::LayerSubscribe c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u8(&c.real_format, "type"))) return false;
      if (c.real_format > 1) *out = cmd::LayerUnsubscribe{c.layer_id};
      else *out = c;
      return true;
    }
    case 50: {
      cmd::VertexSetXyzReal32 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.vertex_id, "vertex_id") && f.f32(&c.x, "x") &&
            f.f32(&c.y, "y") && f.f32(&c.z, "z")))
        return false;
      if (is_flt_max(c.x) || is_flt_max(c.y) || is_flt_max(c.z)) *out = cmd::VertexDelete{c.vertex_id};
      else *out = c;
      return true;
    }
    case 51: {
      cmd::VertexSetXyzReal64 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.vertex_id, "vertex_id") && f.f64(&c.x, "x") &&
            f.f64(&c.y, "y") && f.f64(&c.z, "z")))
        return false;
      if (is_dbl_max(c.x) || is_dbl_max(c.y) || is_dbl_max(c.z)) *out = cmd::VertexDelete{c.vertex_id};
      else *out = c;
      return true;
    }
    case 52: {
      cmd::VertexSetUint32 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.vertex_id, "vertex_id") && f.u32(&c.value, "value")))
        return false;
      *out = c;
      return true;
    }
    case 53: {
      cmd::VertexSetReal64 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.vertex_id, "vertex_id") && f.f64(&c.value, "value")))
        return false;
      *out = c;
      return true;
    }
    case 54: {
      cmd::VertexSetReal32 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.vertex_id, "vertex_id") && f.f32(&c.value, "value")))
        return false;
      *out = c;
      return true;
    }
    case 55: {
      cmd::PolygonSetCornerUint32 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.polygon_id, "polygon_id") && f.u32(&c.v[0], "v0") &&
            f.u32(&c.v[1], "v1") && f.u32(&c.v[2], "v2") && f.u32(&c.v[3], "v3")))
        return false;
      if (c.layer_id == 1 && c.v[0] == 0xFFFFFFFFu) *out = cmd::PolygonDelete{c.polygon_id};
      else *out = c;
      return true;
    }
    case 56: {
      cmd::PolygonSetCornerReal64 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.polygon_id, "polygon_id") && f.f64(&c.v[0], "v0") &&
            f.f64(&c.v[1], "v1") && f.f64(&c.v[2], "v2") && f.f64(&c.v[3], "v3")))
        return false;
      *out = c;
      return true;
    }
    case 57: {
      cmd::PolygonSetCornerReal32 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.polygon_id, "polygon_id") && f.f32(&c.v[0], "v0") &&
            f.f32(&c.v[1], "v1") && f.f32(&c.v[2], "v2") && f.f32(&c.v[3], "v3")))
        return false;
      *out = c;
      return true;
    }
    case 58: {
      cmd::PolygonSetFaceUint8 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.polygon_id, "polygon_id") && f.u8(&c.value, "value")))
        return false;
      *out = c;
      return true;
    }
    case 59: {
      cmd::PolygonSetFaceUint32 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.polygon_id, "polygon_id") && f.u32(&c.value, "value")))
        return false;
      *out = c;
      return true;
    }
    case 60: {
      cmd::PolygonSetFaceReal64 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.polygon_id, "polygon_id") && f.f64(&c.value, "value")))
        return false;
      *out = c;
      return true;
    }
    case 61: {
      cmd::PolygonSetFaceReal32 c;
      if (!(f.u16(&c.layer_id, "layer_id") && f.u32(&c.polygon_id, "polygon_id") && f.f32(&c.value, "value")))
        return false;
      *out = c;
      return true;
    }
    case 62: {
      cmd::CreaseSetVertex c;
      if (!(f.str(&c.layer, "layer") && f.u32(&c.def_crease, "def_crease"))) return false;
      *out = c;
      return true;
    }
    case 63: {
      cmd::CreaseSetEdge c;
      if (!(f.str(&c.layer, "layer") && f.u32(&c.def_crease, "def_crease"))) return false;
      *out = c;
      return true;
    }
    case 64: {
      cmd::BoneCreate c;
      if (bones == BoneForm::R6) {
        std::string scale_label;
        if (!(f.u16(&c.bone_id, "bone_id") && f.str(&c.weight, "weight") && f.str(&c.reference, "reference") &&
              f.u16(&c.parent, "parent") && f.f64(&c.pos[0], "pos_x") && f.f64(&c.pos[1], "pos_y") &&
              f.f64(&c.pos[2], "pos_z") && f.str(&c.pos_label, "position_label") &&
              f.str(&c.rot_label, "rotation_label") && f.str(&scale_label, "scale_label")))
          return false;
        c.rot = {0, 0, 0, 1};
        if (c.weight.empty()) *out = cmd::BoneDestroy{c.bone_id};
        else *out = c;
        return true;
      }
      if (!(f.u16(&c.bone_id, "bone_id") && f.str(&c.weight, "weight") && f.str(&c.reference, "reference") &&
            f.u16(&c.parent, "parent") && f.f64(&c.pos[0], "pos_x") && f.f64(&c.pos[1], "pos_y") &&
            f.f64(&c.pos[2], "pos_z") && f.str(&c.pos_label, "pos_label") && f.f64(&c.rot[0], "rot_x") &&
            f.f64(&c.rot[1], "rot_y") && f.f64(&c.rot[2], "rot_z") && f.f64(&c.rot[3], "rot_w") &&
            f.str(&c.rot_label, "rot_label")))
        return false;
      if (c.weight.empty()) *out = cmd::BoneDestroy{c.bone_id};
      else *out = c;
      return true;
    }
    default: return false;
  }
}

const char* geometry_wire_name(std::uint8_t number) {
  static const char* const kNames[] = {
      "g_layer_create", "g_layer_subscribe", "g_vertex_set_xyz_real32", "g_vertex_set_xyz_real64",
      "g_vertex_set_uint32", "g_vertex_set_real64", "g_vertex_set_real32", "g_polygon_set_corner_uint32",
      "g_polygon_set_corner_real64", "g_polygon_set_corner_real32", "g_polygon_set_face_uint8",
      "g_polygon_set_face_uint32", "g_polygon_set_face_real64", "g_polygon_set_face_real32",
      "g_crease_set_vertex", "g_crease_set_edge", "g_bone_create"};
  if (number < kCmdGeometryFirst || number > kCmdGeometryLast) return "g_?";
  return kNames[number - kCmdGeometryFirst];
}

}  // namespace

const char* bone_form_name(BoneForm f) { return f == BoneForm::R6 ? "r6" : "spec"; }

std::uint8_t geometry_command_number(const vgc::Command& c) {
  return std::visit(
      [](const auto& g) -> std::uint8_t {
        using G = std::decay_t<decltype(g)>;
        if constexpr (is<G, cmd::LayerCreate> || is<G, cmd::LayerDestroy>) return 48;
        else if constexpr (is<G, cmd::LayerSubscribe> || is<G, cmd::LayerUnsubscribe>) return 49;
        else if constexpr (is<G, cmd::VertexSetXyzReal32> || is<G, cmd::VertexDelete>) return 50;
        else if constexpr (is<G, cmd::VertexSetXyzReal64>) return 51;
        else if constexpr (is<G, cmd::VertexSetUint32>) return 52;
        else if constexpr (is<G, cmd::VertexSetReal64>) return 53;
        else if constexpr (is<G, cmd::VertexSetReal32>) return 54;
        else if constexpr (is<G, cmd::PolygonSetCornerUint32> || is<G, cmd::PolygonDelete>) return 55;
        else if constexpr (is<G, cmd::PolygonSetCornerReal64>) return 56;
        else if constexpr (is<G, cmd::PolygonSetCornerReal32>) return 57;
        else if constexpr (is<G, cmd::PolygonSetFaceUint8>) return 58;
        else if constexpr (is<G, cmd::PolygonSetFaceUint32>) return 59;
        else if constexpr (is<G, cmd::PolygonSetFaceReal64>) return 60;
        else if constexpr (is<G, cmd::PolygonSetFaceReal32>) return 61;
        else if constexpr (is<G, cmd::CreaseSetVertex>) return 62;
        else if constexpr (is<G, cmd::CreaseSetEdge>) return 63;
        else return 64;  // BoneCreate, BoneDestroy
      },
      c);
}

std::uint8_t command_number(const WireCommand& c) {
  return std::visit(
      [](const auto& w) -> std::uint8_t {
        using W = std::decay_t<decltype(w)>;
        if constexpr (is<W, wire::ConnectTerminate>) return kCmdConnectTerminate;
        else if constexpr (is<W, wire::PacketAck>) return kCmdPacketAck;
        else if constexpr (is<W, wire::PacketNak>) return kCmdPacketNak;
        else if constexpr (is<W, wire::NodeIndexSubscribe>) return kCmdNodeIndexSubscribe;
        else if constexpr (is<W, wire::NodeCreate> || is<W, wire::NodeDestroy>) return kCmdNodeCreate;
        else if constexpr (is<W, wire::NodeSubscribe> || is<W, wire::NodeUnsubscribe>) return kCmdNodeSubscribe;
        else if constexpr (is<W, wire::TagGroupCreate>) return kCmdTagGroupCreate;
        else if constexpr (is<W, wire::NodeNameSet>) return kCmdNodeNameSet;
        else return geometry_command_number(w.command);
      },
      c);
}

std::string describe(const WireCommand& c) {
  return std::visit(
      [](const auto& w) -> std::string {
        using W = std::decay_t<decltype(w)>;
        if constexpr (is<W, wire::ConnectTerminate>) return "connect_terminate";
        else if constexpr (is<W, wire::PacketAck>) return "packet_ack " + std::to_string(w.packet_id);
        else if constexpr (is<W, wire::PacketNak>) return "packet_nak " + std::to_string(w.packet_id);
        else if constexpr (is<W, wire::NodeIndexSubscribe>) return "node_index_subscribe " + std::to_string(w.mask);
        else if constexpr (is<W, wire::NodeCreate>)
          return "node_create " + std::to_string(w.node_id) + " type " + std::to_string(w.type) + " owner " +
                 std::to_string(w.owner);
        else if constexpr (is<W, wire::NodeDestroy>) return "node_destroy " + std::to_string(w.node_id);
        else if constexpr (is<W, wire::NodeSubscribe>) return "node_subscribe " + std::to_string(w.node_id);
        else if constexpr (is<W, wire::NodeUnsubscribe>) return "node_unsubscribe " + std::to_string(w.node_id);
        else if constexpr (is<W, wire::TagGroupCreate>) return "tag_group_create " + std::to_string(w.node_id);
        else if constexpr (is<W, wire::NodeNameSet>) return "node_name_set " + std::to_string(w.node_id);
        else
          return std::string(geometry_wire_name(geometry_command_number(w.command))) + " node " +
                 std::to_string(w.node_id) + " (" + std::string(command_verb(w.command)) + ")";
      },
      c);
}

Status encode_command(const WireCommand& c, std::string* out, BoneForm bones) {
  std::string bytes;
  PackWriter w(&bytes);
  Status st = std::visit(
      [&](const auto& v) -> Status {
        using W = std::decay_t<decltype(v)>;
        w.u8(command_number(c));
        if constexpr (is<W, wire::ConnectTerminate>) {
          Status s = check_string(v.bye, "connect_terminate message");
          if (!s.ok()) return s;
          w.string(v.bye);
        } else if constexpr (is<W, wire::PacketAck> || is<W, wire::PacketNak>) {
          w.u32(v.packet_id);
        } else if constexpr (is<W, wire::NodeIndexSubscribe>) {
          w.u32(v.mask);
        } else if constexpr (is<W, wire::NodeCreate>) {
          w.u32(v.node_id); w.u8(v.type); w.u8(v.owner);
        } else if constexpr (is<W, wire::NodeDestroy>) {
          w.u32(v.node_id); w.u8(0xFF); w.u8(0xFF);
        } else if constexpr (is<W, wire::NodeSubscribe>) {
          w.u32(v.node_id); w.u8(1);
        } else if constexpr (is<W, wire::NodeUnsubscribe>) {
          w.u32(v.node_id); w.u8(0);
        } else if constexpr (is<W, wire::TagGroupCreate>) {
          Status s = check_string(v.name, "tag group name");
          if (!s.ok()) return s;
          w.u32(v.node_id); w.u16(v.group_id); w.string(v.name);
        } else if constexpr (is<W, wire::NodeNameSet>) {
          Status s = check_string(v.name, "node name");
          if (!s.ok()) return s;
          w.u32(v.node_id); w.string(v.name);
        } else {
          Status s = check_geometry_strings(v.command);
          if (!s.ok()) return s;
          if (const auto* b = std::get_if<cmd::BoneCreate>(&v.command);
              b && bones == BoneForm::R6 && !b->weight.empty() && !is_identity_rotation(b->rot))
            return Status::protocol_error(
                "cannot encode a bone rotation: r6's bone_create carries position, rotation and scale labels, "
                "no rotation value (only the identity 0 0 0 1 goes as no rotation)");
          bytes.clear();
          encode_geometry(v.node_id, v.command, w, bones);
        }
        return {};
      },
      c);
  if (!st.ok()) return st;
  out->append(bytes);
  return {};
}

Status decode_command(const std::uint8_t* data, std::size_t size, std::size_t* used, WireCommand* out,
                      BoneForm bones) {
  if (size == 0) return Status::protocol_error("empty command");
  const std::uint8_t number = data[0];
  FieldReader f{PackReader(data + 1, size - 1), "?"};
  auto done = [&](WireCommand&& c) {
    *out = std::move(c);
    *used = 1 + f.r.position();
    return Status{};
  };
  switch (number) {
    case kCmdConnectTerminate: {
      f.command = "connect_terminate";
      wire::ConnectTerminate c;
      if (!f.str(&c.bye, "bye")) return f.status(1);
      return done(std::move(c));
    }
    case kCmdPacketAck:
    case kCmdPacketNak: {
      f.command = number == kCmdPacketAck ? "packet_ack" : "packet_nak";
      std::uint32_t id = 0;
      if (!f.u32(&id, "packet_id")) return f.status(1);
      if (number == kCmdPacketAck) return done(wire::PacketAck{id});
      return done(wire::PacketNak{id});
    }
    case kCmdNodeIndexSubscribe: {
      f.command = "node_index_subscribe";
      wire::NodeIndexSubscribe c;
      if (!f.u32(&c.mask, "mask")) return f.status(1);
      return done(std::move(c));
    }
    case kCmdNodeCreate: {
      f.command = "node_create";
      wire::NodeCreate c;
      if (!(f.u32(&c.node_id, "node_id") && f.u8(&c.type, "type") && f.u8(&c.owner, "owner"))) return f.status(1);
      if (c.owner == 0xFF || c.type >= kNodeTypeCount) return done(wire::NodeDestroy{c.node_id});
      return done(std::move(c));
    }
    case kCmdNodeSubscribe: {
      f.command = "node_subscribe";
      std::uint32_t node = 0;
      std::uint8_t flag = 0;
      if (!(f.u32(&node, "node_id") && f.u8(&flag, "subscribe flag"))) return f.status(1);
      if (flag == 0) return done(wire::NodeUnsubscribe{node});
      return done(wire::NodeSubscribe{node});
    }
    case kCmdTagGroupCreate: {
      f.command = "tag_group_create";
      wire::TagGroupCreate c;
      if (!(f.u32(&c.node_id, "node_id") && f.u16(&c.group_id, "group_id") && f.str(&c.name, "name")))
        return f.status(1);
      return done(std::move(c));
    }
    case kCmdNodeNameSet: {
      f.command = "node_name_set";
      wire::NodeNameSet c;
      if (!(f.u32(&c.node_id, "node_id") && f.str(&c.name, "name"))) return f.status(1);
      return done(std::move(c));
    }
    default: break;
  }
  if (number >= kCmdGeometryFirst && number <= kCmdGeometryLast) {
    f.command = geometry_wire_name(number);
    wire::Geometry g;
    if (!f.u32(&g.node_id, "node_id") || !decode_geometry_fields(number, f, &g.command, bones)) return f.status(1);
    return done(std::move(g));
  }
  return Status::protocol_error("unknown command number " + std::to_string(number));
}

vgc::Command wire_canonical(const vgc::Command& c) {
  return std::visit(
      [&](const auto& g) -> vgc::Command {
        using G = std::decay_t<decltype(g)>;
        if constexpr (is<G, cmd::LayerCreate>) {
          if (g.name.empty()) return cmd::LayerDestroy{g.layer_id};
        } else if constexpr (is<G, cmd::LayerSubscribe>) {
          if (g.real_format > 1) return cmd::LayerUnsubscribe{g.layer_id};
        } else if constexpr (is<G, cmd::VertexSetXyzReal32>) {
          if (is_flt_max(g.x) || is_flt_max(g.y) || is_flt_max(g.z)) return cmd::VertexDelete{g.vertex_id};
        } else if constexpr (is<G, cmd::VertexSetXyzReal64>) {
          if (is_dbl_max(g.x) || is_dbl_max(g.y) || is_dbl_max(g.z)) return cmd::VertexDelete{g.vertex_id};
        } else if constexpr (is<G, cmd::PolygonSetCornerUint32>) {
          if (g.layer_id == 1 && g.v[0] == 0xFFFFFFFFu) return cmd::PolygonDelete{g.polygon_id};
        } else if constexpr (is<G, cmd::BoneCreate>) {
          if (g.weight.empty()) return cmd::BoneDestroy{g.bone_id};
        }
        return c;
      },
      c);
}

}  // namespace vgc::verse
