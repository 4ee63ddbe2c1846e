// node.h — the reference geometry node.
//
// Spec: 000 section 2.6 (2.6.1 layers, 2.6.2 creases, 2.6.3 bones) and the
// protocol facts in docs/spec_facts.md. Where the text is silent the
// decision is written next to the rule in node.cpp, tagged "Decision:", and
// listed in docs/commands.md.
//
// Rationale: this is the model every other implementation is checked
// against, so it favours being obviously right over being fast. State is a
// few ordered maps keyed by id: an id of four billion costs one map entry,
// never four billion slots, and iteration order is the canonical order of
// the snapshot. Every command is validated completely before anything is
// changed, so a rejected command leaves the node exactly as it was.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "command.h"
#include "reason.h"
#include "rule.h"

namespace vgc {

// One layer slot. Uint-typed layers use `u`, real-typed layers use `r`;
// per-vertex and per-face layers use element 0 only, XYZ uses 0..2.
struct Slot {
  std::array<std::uint32_t, 4> u{};
  std::array<double, 4> r{};
  Written written;  // the rule that last wrote this slot's values (rule.h)
};

struct Layer {
  std::uint16_t id = 0;
  std::string name;
  LayerType type = LayerType::VertexXyz;
  std::uint32_t def_uint = 0;
  double def_real = 0.0;
  std::optional<RealFormat> subscription;  // layer_subscribe / unsubscribe
  std::map<std::uint32_t, Slot> slots;     // one per live vertex or polygon of its stack
  Written written;                         // the rule that last wrote the layer's own line
};

struct CreaseSetting {  // 2.6.2: a constant, or a named layer
  std::string layer;    // empty: the constant applies everywhere
  std::uint32_t def_crease = 0;
  Written written{Rule::InitialCreases, 0};
};

struct Bone {  // 2.6.3
  std::uint16_t id = 0;
  std::string weight;
  std::string reference;
  std::uint16_t parent = kNone16;
  std::array<double, 3> pos{};
  std::string pos_label;
  std::array<double, 4> rot{0, 0, 0, 1};
  std::string rot_label;
  Written written;
};

// The bone a bone_create stores under `id` (the command's id, or the one
// picked for it): every field as sent, nothing checked.
Bone bone_from_command(const cmd::BoneCreate& c, std::uint16_t id);

// What one command may have changed (Node::apply with a ChangeLog), as the
// identities of the snapshot lines it wrote, added or removed. A superset is
// fine (an entry whose line did not change costs only its recomputation);
// a change missing here is a bug that document_digest_test catches. It lets
// a digest of the node's documents (reference/geometry/document_digest.h)
// follow the node at the cost of the command, not of the node's size.
struct ChangeLog {
  std::vector<std::pair<std::uint16_t, std::uint32_t>> slots;  // (layer id, element id)
  std::vector<std::uint16_t> layer_lines;   // a layer's own line only (subscription)
  std::vector<std::uint16_t> whole_layers;  // created, re-created or destroyed: its line and every slot
  std::vector<std::uint16_t> bones;         // created or destroyed
  bool creases = false;                     // either crease setting
  void clear() {
    slots.clear();
    layer_lines.clear();
    whole_layers.clear();
    bones.clear();
    creases = false;
  }
};

// Storage bounds, so that no command sequence makes the node allocate
// without bound. A command that would pass one is rejected with LIMIT.
struct NodeLimits {
  std::size_t max_cells_per_stack = std::size_t{1} << 22;  // elements x layers in one stack
};

class Node {
 public:
  static constexpr std::uint16_t kVertexLayer = 0;   // "vertex", VERTEX_XYZ
  static constexpr std::uint16_t kPolygonLayer = 1;  // "polygon", POLYGON_CORNER_UINT32

  explicit Node(NodeLimits limits = {});

  // Applies `c` completely and returns Reason::Ok, or changes nothing and
  // returns why not. Never throws for any command value. When `trace` is
  // not null it receives the rules the command applied (rule.h), in order:
  // for a refusal, the guard that refused it (after any alias read first),
  // then every later guard of layer_create / bone_create that would refuse
  // it too.
  // Every element the command writes records the rule and step() (Written).
  // When `changes` is not null it is cleared and receives what the command
  // may have changed (ChangeLog).
  Reason apply(const Command& c, RuleTrace* trace = nullptr, ChangeLog* changes = nullptr);
  // How many commands apply() has been given (the step a Written refers to).
  std::uint32_t step() const { return step_; }

  const std::map<std::uint16_t, Layer>& layers() const { return layers_; }
  const Layer* find_layer(std::uint16_t id) const;
  const Layer* find_layer_by_name(const std::string& name) const;
  const std::map<std::uint32_t, Slot>& vertices() const { return layers_.at(kVertexLayer).slots; }
  const std::map<std::uint32_t, Slot>& polygons() const { return layers_.at(kPolygonLayer).slots; }
  const CreaseSetting& vertex_crease() const { return vertex_crease_; }
  const CreaseSetting& edge_crease() const { return edge_crease_; }
  const std::map<std::uint16_t, Bone>& bones() const { return bones_; }

 private:
  Reason apply_one(const cmd::LayerCreate& c);
  Reason apply_one(const cmd::LayerDestroy& c);
  Reason apply_one(const cmd::LayerSubscribe& c);
  Reason apply_one(const cmd::LayerUnsubscribe& c);
  Reason apply_one(const cmd::VertexSetXyzReal32& c);
  Reason apply_one(const cmd::VertexSetXyzReal64& c);
  Reason apply_one(const cmd::VertexDelete& c);
  Reason apply_one(const cmd::VertexSetUint32& c);
  Reason apply_one(const cmd::VertexSetReal64& c);
  Reason apply_one(const cmd::VertexSetReal32& c);
  Reason apply_one(const cmd::PolygonSetCornerUint32& c);
  Reason apply_one(const cmd::PolygonSetCornerReal64& c);
  Reason apply_one(const cmd::PolygonSetCornerReal32& c);
  Reason apply_one(const cmd::PolygonDelete& c);
  Reason apply_one(const cmd::PolygonSetFaceUint8& c);
  Reason apply_one(const cmd::PolygonSetFaceUint32& c);
  Reason apply_one(const cmd::PolygonSetFaceReal64& c);
  Reason apply_one(const cmd::PolygonSetFaceReal32& c);
  Reason apply_one(const cmd::CreaseSetVertex& c);
  Reason apply_one(const cmd::CreaseSetEdge& c);
  Reason apply_one(const cmd::BoneCreate& c);
  Reason apply_one(const cmd::BoneDestroy& c);

  // `value_rule`: the rule of a write to a non-base XYZ layer (real32 or real64).
  Reason set_xyz(std::uint16_t layer_id, std::uint32_t vertex_id, std::array<double, 3> xyz, Rule value_rule);
  Reason set_corners(std::uint16_t layer_id, std::uint32_t polygon_id, std::array<std::uint32_t, 4> v);
  // Finds a layer of `type` holding a live element `id`; writes the layer
  // to *out, or returns the first rule that fails.
  Reason find_slot(std::uint16_t layer_id, LayerType type, std::uint32_t id, Slot** out);
  Reason new_element(std::uint16_t base_layer, std::uint32_t id, const Slot& base_value);
  void erase_element(bool vertex_stack, std::uint32_t id);
  std::size_t layers_in_stack(bool vertex_stack) const;
  // The rule of a crease setting naming `layer`: `constant` for no name,
  // `named` when it names a layer of `type`, else CreaseLayerUnresolved.
  Rule crease_rule(const std::string& layer, LayerType type, Rule constant, Rule named) const;

  // Records `r` in the current command's trace, if any.
  void note(Rule r) {
    if (trace_) trace_->add(r);
  }
  // Records the guard `r` and returns its reason.
  Reason refuse(Rule r, Reason why) {
    note(r);
    return why;
  }
  // After a refusal, when tracing: records every other guard whose
  // condition also holds, so that a refused command names every rule that
  // refuses it (the first recorded decides the reason).
  void also_refusing(std::initializer_list<std::pair<Rule, bool>> guards) {
    if (!trace_) return;
    for (const auto& [rule, holds] : guards)
      if (holds) note(rule);
  }
  Written written(Rule r) const { return {r, step_}; }
  void touch_slot(std::uint16_t layer_id, std::uint32_t element) {
    if (changes_) changes_->slots.emplace_back(layer_id, element);
  }

  ChangeLog* changes_ = nullptr;

  NodeLimits limits_;
  RuleTrace* trace_ = nullptr;
  std::uint32_t step_ = 0;
  std::map<std::uint16_t, Layer> layers_;
  CreaseSetting vertex_crease_;
  CreaseSetting edge_crease_;
  std::map<std::uint16_t, Bone> bones_;
};

// The value a new slot of `layer` takes (2.6.1: "initialized with a default").
Slot default_slot(const Layer& layer);

}  // namespace vgc
