// command.h — the geometry node's commands as plain value types.
//
// Spec: docs/spec_facts.md "Command set of the geometry node" (protocol
// commands 48..64) and 000 section 2.6.
//
// Rationale: every test, corpus file, counterexample and exec-adapter line is
// a sequence of these values. They mirror the wire protocol field for field,
// with the wire's overloaded forms (empty name = destroy, FLT_MAX = delete,
// v0 = 0xFFFFFFFF on layer 1 = delete) also given their own explicit command,
// so a file can say either. Fields hold exactly what was sent: a type byte
// that is no layer type, a 40-byte name, a NaN payload. Judging them is the
// node's job, not the value type's. Equality is bit-exact on floating point
// (NaN payloads and -0.0 included), which is what round-trip tests need.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace vgc {

// Layer types, Table 2-1, with the r6 protocol values.
enum class LayerType : std::uint8_t {
  VertexXyz = 0,
  VertexUint32 = 1,
  VertexReal = 2,
  PolygonCornerUint32 = 128,
  PolygonCornerReal = 129,
  PolygonFaceUint8 = 130,
  PolygonFaceUint32 = 131,
  PolygonFaceReal = 132,
};

// True when `raw` is one of the eight values of Table 2-1.
bool is_layer_type(std::uint8_t raw);
// "VERTEX_XYZ" etc.; empty for a value that is no layer type.
std::string_view layer_type_name(std::uint8_t raw);
// Inverse of layer_type_name; false when `name` is not one of the eight.
bool parse_layer_type_name(std::string_view name, std::uint8_t* out);
// Vertex-stack types are < 128, polygon-stack types >= 128 (Table 2-1).
inline bool is_vertex_layer_type(LayerType t) { return static_cast<std::uint8_t>(t) < 128; }

// Real format of a subscription (README: REAL32=0, REAL64=1).
enum class RealFormat : std::uint8_t { Real32 = 0, Real64 = 1 };

inline constexpr std::uint32_t kNone32 = 0xFFFFFFFFu;  // unused corner, "pick an id", crease max
inline constexpr std::uint16_t kNone16 = 0xFFFFu;      // "pick an id" for layers and bones
inline constexpr std::size_t kMaxNameBytes = 15;       // 16 bytes with the NUL

namespace cmd {

struct LayerCreate {        // 48
  std::uint16_t layer_id = 0;
  std::string name;         // empty: the wire's way of saying LayerDestroy
  std::uint8_t type = 0;    // raw LayerType value, possibly invalid
  std::uint32_t def_uint = 0;
  double def_real = 0.0;
};
struct LayerDestroy {       // 48 with an empty name
  std::uint16_t layer_id = 0;
};
struct LayerSubscribe {     // 49
  std::uint16_t layer_id = 0;
  std::uint8_t real_format = 0;  // raw RealFormat value, possibly invalid
};
struct LayerUnsubscribe {   // 49 (unsubscribe form)
  std::uint16_t layer_id = 0;
};
struct VertexSetXyzReal32 { // 50; any coordinate == FLT_MAX means VertexDelete
  std::uint16_t layer_id = 0;
  std::uint32_t vertex_id = 0;
  float x = 0, y = 0, z = 0;
};
struct VertexSetXyzReal64 { // 51; any coordinate == DBL_MAX means VertexDelete
  std::uint16_t layer_id = 0;
  std::uint32_t vertex_id = 0;
  double x = 0, y = 0, z = 0;
};
struct VertexDelete {       // 50/51 with the max sentinel
  std::uint32_t vertex_id = 0;
};
struct VertexSetUint32 {    // 52
  std::uint16_t layer_id = 0;
  std::uint32_t vertex_id = 0;
  std::uint32_t value = 0;
};
struct VertexSetReal64 {    // 53
  std::uint16_t layer_id = 0;
  std::uint32_t vertex_id = 0;
  double value = 0;
};
struct VertexSetReal32 {    // 54
  std::uint16_t layer_id = 0;
  std::uint32_t vertex_id = 0;
  float value = 0;
};
struct PolygonSetCornerUint32 {  // 55; on layer 1 with v[0] == kNone32 means PolygonDelete
  std::uint16_t layer_id = 0;
  std::uint32_t polygon_id = 0;
  std::array<std::uint32_t, 4> v{};
};
struct PolygonSetCornerReal64 {  // 56
  std::uint16_t layer_id = 0;
  std::uint32_t polygon_id = 0;
  std::array<double, 4> v{};
};
struct PolygonSetCornerReal32 {  // 57
  std::uint16_t layer_id = 0;
  std::uint32_t polygon_id = 0;
  std::array<float, 4> v{};
};
struct PolygonDelete {      // 55 with v0 == 0xFFFFFFFF on layer 1
  std::uint32_t polygon_id = 0;
};
struct PolygonSetFaceUint8 {     // 58
  std::uint16_t layer_id = 0;
  std::uint32_t polygon_id = 0;
  std::uint8_t value = 0;
};
struct PolygonSetFaceUint32 {    // 59
  std::uint16_t layer_id = 0;
  std::uint32_t polygon_id = 0;
  std::uint32_t value = 0;
};
struct PolygonSetFaceReal64 {    // 60
  std::uint16_t layer_id = 0;
  std::uint32_t polygon_id = 0;
  double value = 0;
};
struct PolygonSetFaceReal32 {    // 61
  std::uint16_t layer_id = 0;
  std::uint32_t polygon_id = 0;
  float value = 0;
};
struct CreaseSetVertex {    // 62; empty layer name: the constant def_crease applies
  std::string layer;
  std::uint32_t def_crease = 0;
};
struct CreaseSetEdge {      // 63
  std::string layer;
  std::uint32_t def_crease = 0;
};
struct BoneCreate {         // 64, in the form section 2.6.3 describes
  std::uint16_t bone_id = 0;
  std::string weight;       // empty: the wire's way of saying BoneDestroy
  std::string reference;    // empty: no reference layer
  std::uint16_t parent = 0;
  std::array<double, 3> pos{};
  std::string pos_label;
  std::array<double, 4> rot{0, 0, 0, 1};  // quaternion x, y, z, w
  std::string rot_label;
};
struct BoneDestroy {        // 64 with an empty weight name
  std::uint16_t bone_id = 0;
};

}  // namespace cmd

using Command = std::variant<cmd::LayerCreate, cmd::LayerDestroy, cmd::LayerSubscribe,
                             cmd::LayerUnsubscribe, cmd::VertexSetXyzReal32,
                             cmd::VertexSetXyzReal64, cmd::VertexDelete, cmd::VertexSetUint32,
                             cmd::VertexSetReal64, cmd::VertexSetReal32,
                             cmd::PolygonSetCornerUint32, cmd::PolygonSetCornerReal64,
                             cmd::PolygonSetCornerReal32, cmd::PolygonDelete,
                             cmd::PolygonSetFaceUint8, cmd::PolygonSetFaceUint32,
                             cmd::PolygonSetFaceReal64, cmd::PolygonSetFaceReal32,
                             cmd::CreaseSetVertex, cmd::CreaseSetEdge, cmd::BoneCreate,
                             cmd::BoneDestroy>;

inline constexpr std::size_t kCommandKinds = std::variant_size_v<Command>;

// The verb of the text form ("layer_create", ...), by variant index.
std::string_view command_verb(const Command& c);
std::string_view command_verb(std::size_t index);

// Bit-exact equality: floats compare by their bits, so NaN == NaN with the
// same payload and -0.0 != 0.0.
bool bit_equal(const Command& a, const Command& b);

}  // namespace vgc
