// snapshot.h — canonical text of a node's whole state, made for diffing.
//
// Spec: 000 section 2.6 (what a node holds); docs/commands.md "Snapshot"
// defines the format for other implementations.
//
// The snapshot document, deterministic (ids ascending, numbers in the exact
// forms of number_text.h) and ending in a line "end": what is stored —
// layers, creases as set, live vertices and polygons, every slot of every
// other layer, bones as sent. Two conforming nodes fed the same commands
// print the same snapshot byte for byte. What the stored data means (the
// derived document: effective creases, bone world poses) is derived
// geometry: reference/geometry/derived_document.h.
#pragma once

#include <optional>
#include <string>

#include "node.h"

namespace vgc {

std::string print_snapshot(const Node& node);

// Which rule last wrote the snapshot line `line` (or a line with the same
// identity: its kind and ids, e.g. "slot 3 17", "layer 2", "crease_edge"),
// and at which step (rule.h Written); nullopt when the node prints no line
// with that identity. The printed header and "end" lines have none.
std::optional<Written> line_written(const Node& node, const std::string& line);

// The parts of a node's state the snapshot prints, held anywhere: a client
// that rebuilds a node from what a host sends (conformance/adapter/
// verse_implementation.h) prints its own copy with the same printer. The
// live vertices are the slots of layer 0, the live polygons those of
// layer 1 (none when the layer is absent).
struct SnapshotParts {
  const std::map<std::uint16_t, Layer>& layers;
  const CreaseSetting& vertex_crease;
  const CreaseSetting& edge_crease;
  const std::map<std::uint16_t, Bone>& bones;
};
std::string print_snapshot(const SnapshotParts& state);

// The snapshot's lines one identity at a time, exactly as print_snapshot
// prints them (each ending in "\n"; print_snapshot is made of them), for a
// digest that follows the node line by line (document_digest.h).
// kSnapshotHeader is the first line; the last is "end\n".
inline constexpr const char* kSnapshotHeader = "vgc-snapshot 1\n";
std::string snapshot_layer_line(std::uint16_t id, const Layer& layer);
std::string snapshot_crease_lines(const CreaseSetting& vertex, const CreaseSetting& edge);  // two lines
// "vertex ..." for layer 0, "polygon ..." for layer 1, "slot ..." otherwise.
std::string snapshot_slot_line(std::uint16_t layer_id, LayerType type, std::uint32_t element, const Slot& slot);
std::string snapshot_bone_line(std::uint16_t id, const Bone& b);

// Which of a layer's two defaults the spec gives meaning to (000 2.6.1: a new
// slot "is typically initialized with a default value"; Table 2-1 gives each
// type one value type): an integer type's new slots take def_uint, a real or
// XYZ type's take def_real (in every component), and the base layers 0 and 1
// take neither (their slots hold the written positions and corners). The
// snapshot prints an unused default as "-", and document comparison ignores
// that field whatever an implementation prints there (docs/commands.md 6.1).
struct UsedDefaults {
  bool def_uint = false;
  bool def_real = false;
};
UsedDefaults used_defaults(std::uint16_t layer_id, LayerType type);

}  // namespace vgc
