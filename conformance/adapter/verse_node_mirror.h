// verse_node_mirror.h — a geometry node rebuilt only from what a Verse host
// sends to a subscriber: the state the verse: route certifies.
//
// Spec: 000 section 2.6.1 (layers; a new slot takes the layer's default),
// 2.6.2 (crease settings), 2.6.3 (bones); docs/spec_facts.md sections 3-4
// (the commands a host sends, in their alias forms), section 5 (ids). What
// a host sends to subscribers: docs/adapters.md "The Verse wire route".
//
// Rationale: a client of a Verse host knows the node only through the
// commands the host sends it: layer_create for each layer (on subscribing
// and whenever one is created or changed), the values of each subscribed
// layer, crease settings and bones. The mirror applies each of them as a
// statement of fact, never judging it (that is the suite's job, on the
// snapshot it prints): a vertex written on layer 0 is a live vertex, and
// every vertex-stack layer gets a slot for it holding the layer's default
// until the host sends its value (a host sends only values that differ
// from the default, as r6 does on subscribing); a delete removes the
// element from its stack and nothing else (a host that also removes the
// polygons of a deleted vertex says so with polygon deletes). It keeps no
// subscription state: a host broadcasts none (RouteLimits::subscriptions).
// Its size is bounded (max_cells) so a hostile host cannot make vgc
// allocate without bound; past it apply() fails and the adapter reports a
// protocol error.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

#include "command.h"
#include "node.h"

namespace vgc {

class VerseNodeMirror {
 public:
  explicit VerseNodeMirror(std::size_t max_cells = std::size_t{1} << 22) : max_cells_(max_cells) {}

  // The bound on what it keeps (a node handed out by VerseNodePool, whose
  // mirrors keep little, gets the full bound).
  void set_max_cells(std::size_t max_cells) { max_cells_ = max_cells; }
  // Forgets everything: no layers (not even the base layers: a host
  // announces them like any other), smooth creases, no bones.
  void clear();
  // Applies one command the host sent. false with *error when it would
  // pass max_cells (the host sent more state than vgc keeps).
  bool apply(const Command& sent, std::string* error);
  // The snapshot document (reference/node/snapshot.h) of what the host sent,
  // with no subscription column ("-": a host broadcasts none).
  std::string snapshot() const;
  // This mirror is a REAL64 subscriber's view and `real32` a REAL32
  // subscriber's of the same state: wherever `real32` differs other than by
  // rounding to float (a slot's value, an element one has and the other
  // has not, in a real layer), this takes `real32`'s, so the difference
  // shows in snapshot() (the verse: route's late view).
  void take_real32_differences(const VerseNodeMirror& real32);

  const std::map<std::uint16_t, Layer>& layers() const { return layers_; }
  const CreaseSetting& vertex_crease() const { return vertex_crease_; }
  const CreaseSetting& edge_crease() const { return edge_crease_; }
  const std::map<std::uint16_t, Bone>& bones() const { return bones_; }

 private:
  bool new_element(bool vertex_stack, std::uint32_t id, std::string* error);
  Slot* slot(std::uint16_t layer_id, std::uint32_t element, std::string* error, bool* ok);
  void erase_element(bool vertex_stack, std::uint32_t id);
  bool set_xyz(std::uint16_t layer_id, std::uint32_t id, double x, double y, double z, std::string* error);
  bool typed(std::uint16_t layer_id, LayerType type, const Command& sent, std::string* error) const;
  bool set_uint(const Command& sent, std::uint16_t layer_id, LayerType type, std::uint32_t element,
                std::uint32_t value, std::string* error);
  bool set_real(const Command& sent, std::uint16_t layer_id, LayerType type, std::uint32_t element, double value,
                std::string* error);
  bool set_corner_reals(const Command& sent, std::uint16_t layer_id, std::uint32_t polygon,
                        const std::array<double, 4>& v, std::string* error);
  bool add_layer(const cmd::LayerCreate& c, LayerType type, std::string* error);
  // apply()'s steps, one per kind of command (verse_node_mirror.cpp).
  bool apply_one(const cmd::LayerCreate& c, std::string* error);
  bool apply_one(const cmd::LayerDestroy& c, std::string* error);
  bool apply_one(const cmd::LayerSubscribe& c, std::string* error);
  bool apply_one(const cmd::LayerUnsubscribe& c, std::string* error);
  bool apply_one(const cmd::VertexSetXyzReal32& c, std::string* error);
  bool apply_one(const cmd::VertexSetXyzReal64& c, std::string* error);
  bool apply_one(const cmd::VertexDelete& c, std::string* error);
  bool apply_one(const cmd::VertexSetUint32& c, std::string* error);
  bool apply_one(const cmd::VertexSetReal64& c, std::string* error);
  bool apply_one(const cmd::VertexSetReal32& c, std::string* error);
  bool apply_one(const cmd::PolygonSetCornerUint32& c, std::string* error);
  bool apply_one(const cmd::PolygonSetCornerReal64& c, std::string* error);
  bool apply_one(const cmd::PolygonSetCornerReal32& c, std::string* error);
  bool apply_one(const cmd::PolygonDelete& c, std::string* error);
  bool apply_one(const cmd::PolygonSetFaceUint8& c, std::string* error);
  bool apply_one(const cmd::PolygonSetFaceUint32& c, std::string* error);
  bool apply_one(const cmd::PolygonSetFaceReal64& c, std::string* error);
  bool apply_one(const cmd::PolygonSetFaceReal32& c, std::string* error);
  bool apply_one(const cmd::CreaseSetVertex& c, std::string* error);
  bool apply_one(const cmd::CreaseSetEdge& c, std::string* error);
  bool apply_one(const cmd::BoneCreate& c, std::string* error);
  bool apply_one(const cmd::BoneDestroy& c, std::string* error);
  std::size_t cells() const;

  std::size_t max_cells_;
  std::map<std::uint16_t, Layer> layers_;
  CreaseSetting vertex_crease_;
  CreaseSetting edge_crease_;
  std::map<std::uint16_t, Bone> bones_;
};

}  // namespace vgc
