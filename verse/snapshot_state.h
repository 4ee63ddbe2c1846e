// snapshot_state.h — a node's stored state read back from its snapshot
// document, for the host's "what changed" comparison.
//
// Spec: the snapshot document of reference/node/snapshot.h (docs/commands.md
// "Snapshot"); what the host sends for each difference: docs/verse_wire.md
// section 7.
//
// Rationale: the host serves any node (a plugin, a faulty one) and must not
// trust it to report its own changes; the snapshot is the one view every
// node gives, so the host reads it back into maps it can compare.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "node.h"
#include "wire_status.h"

namespace vgc::verse {

struct LayerInfo {
  std::string name;
  std::uint8_t type = 0;
  std::uint32_t def_uint = 0;  // 0 when the snapshot prints "-"
  double def_real = 0.0;
  bool operator==(const LayerInfo& o) const;
};

struct NodeState {
  std::map<std::uint16_t, LayerInfo> layers;
  vgc::CreaseSetting crease_vertex, crease_edge;
  // Layer id -> element id -> values; layer 0 holds the vertices, layer 1
  // the polygons, as in the node.
  std::map<std::uint16_t, std::map<std::uint32_t, vgc::Slot>> slots;
  std::map<std::uint16_t, vgc::Bone> bones;
};

// ProtocolError naming the line for a document that is not a snapshot.
Status parse_snapshot_state(const std::string& text, NodeState* out);

// Bit-exact equality of the values a slot of `type` holds.
bool slot_equal(std::uint8_t type, const vgc::Slot& a, const vgc::Slot& b);
// The value a new, untouched slot of the layer holds (its default).
vgc::Slot layer_default_slot(std::uint16_t layer_id, const LayerInfo& layer);

}  // namespace vgc::verse
