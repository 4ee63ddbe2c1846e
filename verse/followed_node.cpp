// followed_node.cpp — see followed_node.h.
#include "followed_node.h"

#include <algorithm>
#include <set>
#include <string>
#include <utility>

#include "snapshot.h"

namespace vgc::verse {

Status FollowedNode::open(HostedNode& node, std::size_t verify_min_commands) {
  verify_min_ = std::max<std::size_t>(1, verify_min_commands);
  model_ = vgc::Node{};
  model_digest_ = vgc::NodeDigest{};
  StateChange ignored;
  return read_whole(node, &ignored);
}

Status FollowedNode::follow(HostedNode& node, const vgc::Command& command, bool node_failed, StateChange* out) {
  *out = StateChange{};
  model_.apply(command, nullptr, &changes_);
  model_digest_.update(model_, changes_);
  if (node_failed) {
    in_step_ = false;
    return {};
  }
  ++since_whole_;
  if (in_step_ && since_whole_ < verify_after_ && node.offers_digest()) {
    std::uint64_t digest = 0;
    std::string error;
    if (node.snapshot_digest(&digest, &error) && digest == model_digest_.digests().snapshot) {
      if (changed_lines(out)) {
        ++counters_.by_digest;
        return {};
      }
    } else {
      ++counters_.digest_differs;
    }
  }
  return read_whole(node, out);
}

Status FollowedNode::read_whole(HostedNode& node, StateChange* out) {
  std::string text, error;
  in_step_ = false;
  if (!node.snapshot(&text, &error)) return Status::protocol_error("the node gave no snapshot: " + error);
  NodeState after;
  Status st = parse_snapshot_state(text, &after);
  if (!st.ok()) return st;
  ++counters_.whole_reads;
  out->whole = true;
  out->before = std::move(state_);
  out->after = after;
  state_ = std::move(after);
  in_step_ = vgc::document_digest(text) == model_digest_.digests().snapshot;
  since_whole_ = 0;
  verify_after_ = std::max<std::size_t>(verify_min_, static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')));
  return {};
}

// The identities the model's ChangeLog names, as they were (state_) and as
// they are (the model's lines, read back by the snapshot parser so that
// they are held exactly as a whole read holds them); then state_ takes them.
bool FollowedNode::changed_lines(StateChange* out) {
  std::set<std::uint16_t> layers(changes_.layer_lines.begin(), changes_.layer_lines.end());
  const std::set<std::uint16_t> whole(changes_.whole_layers.begin(), changes_.whole_layers.end());
  layers.insert(whole.begin(), whole.end());
  for (const auto& [lid, e] : changes_.slots) layers.insert(lid);
  const std::set<std::uint16_t> bones(changes_.bones.begin(), changes_.bones.end());

  NodeState& before = out->before;
  for (std::uint16_t lid : layers)
    if (auto l = state_.layers.find(lid); l != state_.layers.end()) before.layers.emplace(lid, l->second);
  before.crease_vertex = state_.crease_vertex;
  before.crease_edge = state_.crease_edge;
  for (std::uint16_t id : bones)
    if (auto b = state_.bones.find(id); b != state_.bones.end()) before.bones.emplace(id, b->second);
  for (std::uint16_t lid : whole)
    if (auto s = state_.slots.find(lid); s != state_.slots.end()) before.slots[lid] = s->second;
  for (const auto& [lid, e] : changes_.slots) {
    if (whole.count(lid)) continue;
    auto s = state_.slots.find(lid);
    if (s == state_.slots.end()) continue;
    if (auto v = s->second.find(e); v != s->second.end()) before.slots[lid][e] = v->second;
  }

  std::string doc = vgc::kSnapshotHeader;
  for (std::uint16_t lid : layers)
    if (const vgc::Layer* l = model_.find_layer(lid)) doc += snapshot_layer_line(lid, *l);
  doc += snapshot_crease_lines(model_.vertex_crease(), model_.edge_crease());
  for (std::uint16_t lid : whole)
    if (const vgc::Layer* l = model_.find_layer(lid))
      for (const auto& [e, slot] : l->slots) doc += snapshot_slot_line(lid, l->type, e, slot);
  for (const auto& [lid, e] : changes_.slots) {
    if (whole.count(lid)) continue;
    const vgc::Layer* l = model_.find_layer(lid);
    if (!l) continue;
    if (auto v = l->slots.find(e); v != l->slots.end()) doc += snapshot_slot_line(lid, l->type, e, v->second);
  }
  for (std::uint16_t id : bones)
    if (auto b = model_.bones().find(id); b != model_.bones().end()) doc += snapshot_bone_line(id, b->second);
  doc += "end\n";
  NodeState& after = out->after;
  // The model prints what the parser reads (a failure would be the host's own bug: read whole instead).
  if (!parse_snapshot_state(doc, &after).ok()) {
    *out = StateChange{};
    return false;
  }

  for (std::uint16_t lid : layers) {
    if (auto l = after.layers.find(lid); l != after.layers.end()) {
      state_.layers[lid] = l->second;
    } else {
      state_.layers.erase(lid);
      state_.slots.erase(lid);
    }
  }
  state_.crease_vertex = after.crease_vertex;
  state_.crease_edge = after.crease_edge;
  for (std::uint16_t id : bones) {
    if (auto b = after.bones.find(id); b != after.bones.end()) state_.bones[id] = b->second;
    else state_.bones.erase(id);
  }
  for (std::uint16_t lid : whole) {
    if (auto s = after.slots.find(lid); s != after.slots.end()) state_.slots[lid] = s->second;
    else state_.slots.erase(lid);
  }
  for (const auto& [lid, e] : changes_.slots) {
    if (whole.count(lid)) continue;
    const auto a = after.slots.find(lid);
    const vgc::Slot* now = nullptr;
    if (a != after.slots.end())
      if (auto v = a->second.find(e); v != a->second.end()) now = &v->second;
    if (now) {
      state_.slots[lid][e] = *now;
    } else if (auto s = state_.slots.find(lid); s != state_.slots.end()) {
      s->second.erase(e);
    }
  }
  return true;
}

}  // namespace vgc::verse
