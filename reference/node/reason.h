// reason.h — why a command was rejected: stable codes, stable names.
//
// Spec: 000 section 2.6 and docs/spec_facts.md; each code names the
// rule that failed. The names (upper case, as printed) are part of the
// command language contract (docs/commands.md) and never change meaning.
#pragma once

#include <string_view>

namespace vgc {

enum class Reason {
  Ok,                 // applied
  NoSuchLayer,        // the layer id names no layer
  BaseLayer,          // layers 0 and 1 cannot be created, re-typed or destroyed
  BadLayerType,       // the type byte is not one of Table 2-1's eight values
  WrongLayerType,     // the layer exists but the command is not for its type
  BadName,            // a name or label is over 15 bytes or holds a NUL byte
  NameInUse,          // another layer already has this name
  NoFreeId,           // "pick an id" asked, none left
  NoSuchVertex,       // the vertex id names no live vertex
  NoSuchPolygon,      // the polygon id names no live polygon
  BadPolygon,         // corners: not 3 or 4, repeated, or unused before the 4th
  BadValue,           // a value the rule forbids (non-finite base position, zero rotation)
  BadRealFormat,      // kept for stable names; no longer produced: a format > 1 is the unsubscribe alias
  NoSuchBone,         // the bone id names no bone
  BoneCycle,          // the parent link would make the bone its own ancestor
  BadWeightLayer,     // weight layer missing or not VERTEX_UINT32 / VERTEX_REAL
  BadReferenceLayer,  // reference layer missing or not VERTEX_UINT32
  Limit,              // the node's documented storage limit would be exceeded
};

// "OK", "NO_SUCH_LAYER", ...
std::string_view reason_name(Reason r);
// Inverse of reason_name; false for an unknown name.
bool parse_reason_name(std::string_view name, Reason* out);

}  // namespace vgc
