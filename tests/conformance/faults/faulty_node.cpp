// faulty_node.cpp — see faulty_node.h. Each fault is a few lines in apply()
// or in a document rewrite, marked with its name.
#include "faulty_node.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <thread>

#include "bone_pose.h"
#include "capability_documents.h"
#include "crease.h"
#include "derived_document.h"
#include "number_text.h"
#include "snapshot.h"

namespace vgc::faults {

namespace {
std::vector<FaultInfo> build_catalog() {
  std::vector<FaultInfo> catalog = {
      {"none", "", "", "the reference, unchanged"},
      {"base-layer-destroyable", "LAYER-BASE-2", "fail", "answers ok to destroying layer 0 or 1"},
      {"layer-type-unchecked", "LAYER-TYPE-1", "fail", "creates a layer with an unknown type as VERTEX_UINT32"},
      {"long-names-truncated", "LAYER-NAME-1", "fail", "truncates layer names over 15 bytes instead of rejecting"},
      {"duplicate-names-allowed", "LAYER-NAME-2", "fail", "answers ok to a layer name already in use"},
      {"no-default-on-new-slots", "LAYER-DEFAULT-1", "fail", "new vertex/polygon slots in other layers are zero"},
      {"recreate-resets-data", "LAYER-RECREATE-1", "fail", "re-creating a layer with its own type clears its data"},
      {"missing-corner-vertices-created", "POLY-VERTEX-REF-1", "fail",
       "a corner naming no vertex creates that vertex at the origin"},
      {"duplicate-corners-accepted", "POLY-DISTINCT-1", "fail", "a repeated corner is dropped, making a triangle"},
      // Refusing the delete breaks vertex.delete (VERTEX-DELETE-1, MUST) as
      // much as the cascade (POLY-VERTEX-DELETE-1, IMPLEMENTATION-DEFINED):
      // blamed on the strictest of the rules the refused command applies.
      {"vertex-delete-refused-when-used", "VERTEX-DELETE-1", "fail",
       "refuses to delete a vertex that polygons use"},
      {"edge-crease-off-by-one", "CREASE-EDGE-LAYER-1", "fail",
       "reports the crease of corner i+1 for the edge starting at corner i"},
      {"wrong-type-crease-layer-used", "CREASE-LAYER-MISSING-1", "fail",
       "reads vertex creases from a named layer of any vertex type"},
      {"bone-cycles-accepted", "BONE-FOREST-1", "fail", "stores a bone that closes a cycle as a root instead"},
      {"bone-rotation-not-inherited", "BONE-DOWNSTREAM-1", "fail",
       "a child's position ignores its parent's rotation"},
      {"real64-stored-as-float", "REAL-STORAGE-1", "fail", "REAL layers keep only 32 bits"},
      {"rejected-layer-still-created", "ATOMIC-1", "fail",
       "a layer_create rejected for its name still creates the layer with a shortened name"},
      {"pick-highest-layer-id", "LAYER-ID-PICK-1", "fail", "layer id 0xFFFF picks the highest free id"},
      {"polygon-delete-ignored", "POLY-DELETE-1", "fail", "answers ok to a polygon delete and keeps the polygon"},
      {"crash-on-self-parent", "BONE-FOREST-1", "crash", "aborts on a bone that names itself as parent (its cycle check)"},
      {"hang-on-subscribe-real64", "LAYER-SUBSCRIBE-1", "timeout", "never answers a REAL64 subscription"},
      // Issue 27: a worse kind of failure hidden behind a milder finding of
      // the same clause. Each has the milder deviation too, which most
      // cases find first; certify must still report the crash.
      {"destroy-missing-ok-double-free", "LAYER-DESTROY-1", "crash",
       "answers ok to destroying a missing layer (a wrong verdict), and aborts (a double free) when that layer "
       "existed and was destroyed before"},
      {"real32-ignored-grow-crash", "VERTEX-SET-1", "crash",
       "answers ok to vertex_set_xyz_real32 and stores nothing (a wrong state), and aborts (a realloc of a freed "
       "block) when a new vertex past every id so far (below 65536) is created after a vertex was deleted"},
      {"wrong-reason-codes", "REASON-1", "fail", "rejects with the right verdict but always says REJECTED (SHOULD)"},
      {"subdivision-ignores-creases", "SUBD-CATMARK-1", "fail",
       "claims subdivision; ?subdivide refines as if every crease were 0"},
      {"classify-misses-boundary", "MESH-CLASSIFY-1", "fail", "claims manifold; ?classify says boundary_loops 0"},
      {"normals-flat", "NORMALS-SPLIT-1", "fail", "claims normals; ?normals gives every corner its face normal"},
      {"loop-warren-weights", "LOOP-TRIANGLE-1", "fail", "claims loop; ?subdivide-loop uses Warren's vertex weights"},
      {"edit-holes-ignored", "EDIT-HIERARCHY-1", "fail", "claims edits; ?subdivide-edit keeps the faces of holes"},
      {"subdivision-non-manifold-smooth", "SUBD-CATMARK-1", "fail",
       "claims subdivision; ?subdivide leaves non-manifold vertices and same-direction edges smooth"},
      {"loop-edges-by-vertex-pair", "LOOP-TRIANGLE-1", "fail",
       "claims loop; ?subdivide-loop merges a level's edges by vertex pair (a pillow loses vertices)"},
      {"mid-range-ids-dropped", "VERTEX-SET-1", "fail",
       "answers ok to a new vertex or polygon id from 4,101 to 2^24-1 and stores nothing (the r6 host past its "
       "storage bound)"},
      {"ids-past-storage-bound", "VERTEX-SET-1", "fail",
       "answers ok to every new vertex or polygon id past 4,129 and stores nothing (the r6 host's storage bound "
       "on a fresh node, whole)"},
      {"vertex-delete-alias-layer-0-only", "VERTEX-DELETE-1", "fail",
       "treats FLT_MAX / DBL_MAX in a coordinate as a delete only on layer 0; elsewhere it is a plain write"},
      // Issue 27: no pick at all. The "pick a free id" sentinel kept as the
      // id itself breaks the create rule (a layer at an id no layer can
      // have: 2 to 0xFFFE), not the reading of which free id to pick.
      {"layer-kept-at-pick-id", "LAYER-CREATE-1", "fail",
       "stores layer_create 0xFFFF as layer 65535 (the \"pick a free id\" sentinel kept as the id), and a later "
       "layer_create 0xFFFF re-creates that layer"},
      {"bone-kept-at-pick-id", "BONE-CREATE-1", "fail",
       "stores bone_create 0xFFFF as bone 65535 (the \"pick a free id\" sentinel kept as the id, which is also "
       "the \"no parent\" id), and a later bone_create 0xFFFF re-creates that bone"},
      // Issue 27: two behaviours of the r6 host that its wire hides from
      // the session that watches (docs/verse_wire.md section 11), each as a
      // node that shows them on its documents and answers.
      {"recreated-element-keeps-slots", "LAYER-DEFAULT-1", "fail",
       "a deleted vertex or polygon keeps its values in the other layers, and one created at its id again has "
       "them instead of the layers' defaults (r6: a delete marks only the base layer)"},
      {"grown-polygon-ids-live", "POLY-DELETE-1", "fail",
       "polygon storage starts at 32 ids and grows to 32 past a new id beyond it; the ids it grew by and no "
       "polygon has are taken as live polygons no document shows: a delete of one is answered ok, and a pick "
       "skips them (r6 fills grown polygon storage with 0, not the unused marker)"},
      // The three MUST bugs of issue 17, each breaking one node rule alone.
      {"moved-vertex-slots-reset", "VERTEX-SET-1", "fail",
       "a moved vertex's slots in the other vertex layers are reset to their defaults", Rule::VertexMoveKeepsSlots},
      {"redefined-polygon-slots-reset", "POLY-TRIANGLE-1", "fail",
       "a re-defined polygon's slots in the other polygon layers are reset to their defaults",
       Rule::PolygonRedefineKeepsSlots},
      {"retype-other-stack-no-slots", "LAYER-STACK-1", "fail",
       "a layer re-typed into the other stack has no slots for that stack's live elements",
       Rule::LayerSlotsForStack},
  };
  // One generated fault per rule: "rule:<name>" (faulty_node.h).
  static std::vector<std::string> names;
  names.reserve(kRuleCount);
  for (std::size_t i = 1; i < kRuleCount; ++i) names.push_back("rule:" + std::string(rule_name(static_cast<Rule>(i))));
  for (std::size_t i = 1; i < kRuleCount; ++i) {
    const Rule r = static_cast<Rule>(i);
    catalog.push_back({names[i - 1], "", "fail", rule_info(r).says, r, true});
  }
  // And one per rule of the derived document: "rule:derived.<...>".
  static std::vector<std::string> derived_names;
  derived_names.reserve(kDerivedRuleCount);
  for (std::size_t i = 1; i < kDerivedRuleCount; ++i)
    derived_names.push_back("rule:" + std::string(derived_rule_name(static_cast<DerivedRule>(i))));
  for (std::size_t i = 1; i < kDerivedRuleCount; ++i) {
    const DerivedRule r = static_cast<DerivedRule>(i);
    catalog.push_back({derived_names[i - 1], "", "fail", derived_rule_info(r).says, Rule::None, true, r});
  }
  return catalog;
}
}  // namespace

const std::vector<FaultInfo>& fault_catalog() {
  static const std::vector<FaultInfo> catalog = build_catalog();
  return catalog;
}

int find_fault(std::string_view name) {
  const auto& c = fault_catalog();
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c[i].name == name) return static_cast<int>(i);
  return -1;
}

bool parse_fault_list(std::string_view list, std::vector<int>* out, std::string* error) {
  out->clear();
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string_view name = list.substr(start, comma - start);
    start = comma + 1;
    if (name.empty() || name == "none") continue;
    const int f = find_fault(name);
    if (f < 0) {
      *error = "unknown fault '" + std::string(name) + "' (the names are in tests/conformance/faults/faulty_node.cpp)";
      return false;
    }
    out->push_back(f);
  }
  return true;
}

std::string fault_list_name(const std::vector<int>& faults) {
  std::string out;
  for (int f : faults) out += (out.empty() ? "" : ",") + std::string(fault_catalog()[static_cast<std::size_t>(f)].name);
  return out.empty() ? "none" : out;
}

bool FaultyNode::is(std::string_view name) const {
  for (int f : faults_)
    if (fault_catalog()[static_cast<std::size_t>(f)].name == name) return true;
  return false;
}

FaultyAnswer FaultyNode::answer(Reason r) const {
  if (r == Reason::Ok) return {true, ""};
  if (is("wrong-reason-codes")) return {false, "REJECTED"};
  return {false, std::string(reason_name(r))};
}

namespace {
template <class... F> struct Overloaded : F... { using F::operator()...; };
template <class... F> Overloaded(F...) -> Overloaded<F...>;

bool creates_element(const Command& c, const Node& before, bool* vertex_stack, std::uint32_t* id) {
  if (auto* x = std::get_if<cmd::VertexSetXyzReal64>(&c); x && x->layer_id == 0 && !before.vertices().count(x->vertex_id)) {
    *vertex_stack = true, *id = x->vertex_id;
    return true;
  }
  if (auto* x = std::get_if<cmd::VertexSetXyzReal32>(&c); x && x->layer_id == 0 && !before.vertices().count(x->vertex_id)) {
    *vertex_stack = true, *id = x->vertex_id;
    return true;
  }
  if (auto* x = std::get_if<cmd::PolygonSetCornerUint32>(&c); x && x->layer_id == 1 && !before.polygons().count(x->polygon_id)) {
    *vertex_stack = false, *id = x->polygon_id;
    return true;
  }
  return false;
}

bool is_vertex_delete_alias(const Command& c) {
  if (auto* x = std::get_if<cmd::VertexSetXyzReal32>(&c)) return x->x == FLT_MAX || x->y == FLT_MAX || x->z == FLT_MAX;
  if (auto* x = std::get_if<cmd::VertexSetXyzReal64>(&c)) return x->x == DBL_MAX || x->y == DBL_MAX || x->z == DBL_MAX;
  return false;
}
}  // namespace

FaultyAnswer FaultyNode::apply(const Command& original) {
  for (int f : faults_)
    if (fault_catalog()[static_cast<std::size_t>(f)].breaks != Rule::None)
      return apply_breaking(original, fault_catalog()[static_cast<std::size_t>(f)].breaks);
  Command c = original;
  // The state before the command, for the faults that compare with it (a
  // copy costs the node's size: only when one of them is active).
  std::optional<Node> before_copy;
  if (is("no-default-on-new-slots")) before_copy = node_;
  const Node& before = before_copy ? *before_copy : node_;

  // base-layer-destroyable
  if (is("base-layer-destroyable")) {
    if (auto* x = std::get_if<cmd::LayerDestroy>(&c); x && x->layer_id < 2) return {true, ""};
  }
  // layer-type-unchecked
  if (auto* x = std::get_if<cmd::LayerCreate>(&c); x && is("layer-type-unchecked") && !is_layer_type(x->type))
    x->type = static_cast<std::uint8_t>(LayerType::VertexUint32);
  // long-names-truncated
  if (auto* x = std::get_if<cmd::LayerCreate>(&c); x && is("long-names-truncated") && x->name.size() > kMaxNameBytes)
    x->name.resize(kMaxNameBytes);
  // duplicate-names-allowed
  if (auto* x = std::get_if<cmd::LayerCreate>(&c); x && is("duplicate-names-allowed")) {
    if (const Layer* other = node_.find_layer_by_name(x->name); other && other->id != x->layer_id && !x->name.empty())
      return {true, ""};
  }
  // recreate-resets-data
  if (auto* x = std::get_if<cmd::LayerCreate>(&c); x && is("recreate-resets-data") && !x->name.empty()) {
    const Layer* l = node_.find_layer(x->layer_id);
    if (l && x->layer_id >= 2 && static_cast<std::uint8_t>(l->type) == x->type) {
      Node trial = node_;
      if (trial.apply(c) == Reason::Ok) {
        apply_node(cmd::LayerDestroy{x->layer_id});
        apply_node(c);
        return {true, ""};
      }
    }
  }
  // missing-corner-vertices-created
  // (The node is copied only for a polygon that names a missing vertex: a
  // copy costs the node's size, and a property at scale sends many polygons.)
  const auto names_missing_vertex = [this](const std::array<std::uint32_t, 4>& v) {
    return std::any_of(v.begin(), v.end(), [this](std::uint32_t x) { return x != kNone32 && !node_.vertices().count(x); });
  };
  if (auto* x = std::get_if<cmd::PolygonSetCornerUint32>(&c);
      x && is("missing-corner-vertices-created") && x->layer_id == 1 && names_missing_vertex(x->v)) {
    Node trial = node_;
    if (trial.apply(c) == Reason::NoSuchVertex) {
      for (std::uint32_t v : x->v)
        if (v != kNone32 && !trial.vertices().count(v)) trial.apply(cmd::VertexSetXyzReal64{0, v, 0, 0, 0});
      if (trial.apply(c) == Reason::Ok) {
        node_ = trial;
        node_changed();
        return {true, ""};
      }
    }
  }
  // duplicate-corners-accepted
  if (auto* x = std::get_if<cmd::PolygonSetCornerUint32>(&c); x && is("duplicate-corners-accepted") && x->layer_id == 1 &&
                                                              x->v[0] != kNone32) {
    std::array<std::uint32_t, 4> unique{kNone32, kNone32, kNone32, kNone32};
    int n = 0;
    for (std::uint32_t v : x->v) {
      bool seen = v == kNone32;
      for (int i = 0; i < n; ++i) seen = seen || unique[i] == v;
      if (!seen) unique[n++] = v;
    }
    if (n == 3 && x->v[3] != kNone32) x->v = unique;
  }
  // polygon-delete-ignored (both forms: the command and its wire alias)
  if (is("polygon-delete-ignored")) {
    if (auto* x = std::get_if<cmd::PolygonDelete>(&c); x && node_.polygons().count(x->polygon_id)) return {true, ""};
    if (auto* x = std::get_if<cmd::PolygonSetCornerUint32>(&c);
        x && x->layer_id == 1 && x->v[0] == kNone32 && node_.polygons().count(x->polygon_id))
      return {true, ""};
  }
  // vertex-delete-refused-when-used
  if (is("vertex-delete-refused-when-used")) {
    std::uint32_t victim = kNone32;
    if (auto* x = std::get_if<cmd::VertexDelete>(&c)) victim = x->vertex_id;
    if (auto* x = std::get_if<cmd::VertexSetXyzReal64>(&c); x && (x->x == std::numeric_limits<double>::max() ||
                                                                  x->y == std::numeric_limits<double>::max() ||
                                                                  x->z == std::numeric_limits<double>::max()))
      victim = x->vertex_id;
    if (victim != kNone32)
      for (const auto& [pid, slot] : node_.polygons())
        for (std::uint32_t v : slot.u)
          if (v == victim) return {false, "VERTEX_IN_USE"};
  }
  // bone-cycles-accepted
  if (auto* x = std::get_if<cmd::BoneCreate>(&c); x && is("bone-cycles-accepted")) {
    Node trial = node_;
    if (trial.apply(c) == Reason::BoneCycle) x->parent = kNone16;
  }
  // real64-stored-as-float
  if (is("real64-stored-as-float")) {
    auto narrow = [](double d) { return static_cast<double>(static_cast<float>(d)); };
    if (auto* x = std::get_if<cmd::VertexSetReal64>(&c)) x->value = narrow(x->value);
    if (auto* x = std::get_if<cmd::PolygonSetFaceReal64>(&c)) x->value = narrow(x->value);
    if (auto* x = std::get_if<cmd::PolygonSetCornerReal64>(&c))
      for (double& v : x->v) v = narrow(v);
  }
  // rejected-layer-still-created
  if (auto* x = std::get_if<cmd::LayerCreate>(&c); x && is("rejected-layer-still-created") && x->name.size() > kMaxNameBytes) {
    cmd::LayerCreate shortened = *x;
    shortened.name.resize(kMaxNameBytes);
    apply_node(shortened);
    return answer(Reason::BadName);
  }
  // pick-highest-layer-id
  if (auto* x = std::get_if<cmd::LayerCreate>(&c); x && is("pick-highest-layer-id") && x->layer_id == kNone16) {
    for (std::uint16_t id = 0xFFFE; id >= 2; --id)
      if (!node_.find_layer(id)) {
        x->layer_id = id;
        break;
      }
  }
  // layer-kept-at-pick-id
  if (auto* x = std::get_if<cmd::LayerCreate>(&c); x && is("layer-kept-at-pick-id") && x->layer_id == kNone16 &&
                                                    !x->name.empty())
    return answer(keep_layer_at_pick_id(*x));
  // bone-kept-at-pick-id
  if (auto* x = std::get_if<cmd::BoneCreate>(&c); x && is("bone-kept-at-pick-id") && x->bone_id == kNone16 &&
                                                   !x->weight.empty())
    return answer(keep_bone_at_pick_id(*x));
  // mid-range-ids-dropped: a new vertex or polygon past the bound that the
  // reference would create is answered ok and not stored. The r6 host drops
  // ids more than 4,096 past its storage (4,129 on a fresh node); ids from
  // 2^24 on this fault keeps, so that only generators that draw the ids in
  // between find it (the old ones drew 0..10, 2^24, 4e9 and 2^32-2).
  if (is("mid-range-ids-dropped")) {
    bool vertex_stack = false;
    std::uint32_t id = 0;
    if (creates_element(c, before, &vertex_stack, &id) && id > 4100 && id < (1u << 24)) {
      Node trial = node_;  // only for an id in the range: a copy costs the node's size
      if (trial.apply(c) == Reason::Ok) return {true, ""};
    }
  }
  // vertex-delete-alias-layer-0-only: on another layer the coordinates are
  // written as they are (into a VERTEX_XYZ layer holding the vertex), or the
  // write is refused as a plain write would be.
  if (is("vertex-delete-alias-layer-0-only") && is_vertex_delete_alias(c)) {
    std::uint16_t layer_id = 0;
    std::uint32_t vertex_id = 0;
    std::array<double, 3> xyz{};
    if (auto* x = std::get_if<cmd::VertexSetXyzReal32>(&c))
      layer_id = x->layer_id, vertex_id = x->vertex_id, xyz = {double(x->x), double(x->y), double(x->z)};
    if (auto* x = std::get_if<cmd::VertexSetXyzReal64>(&c))
      layer_id = x->layer_id, vertex_id = x->vertex_id, xyz = {x->x, x->y, x->z};
    if (layer_id != Node::kVertexLayer) {
      const Layer* l = node_.find_layer(layer_id);
      if (l && l->type == LayerType::VertexXyz && l->slots.count(vertex_id)) {
        Slot& slot = const_cast<Layer*>(l)->slots.at(vertex_id);  // test-only: reach into the node's storage
        node_changed();
        std::copy(xyz.begin(), xyz.end(), slot.r.begin());
        return {true, ""};
      }
      Node trial = node_;  // the answer to the same write with ordinary coordinates
      const Reason r = trial.apply(cmd::VertexSetXyzReal64{layer_id, vertex_id, 0, 0, 0});
      return answer(r == Reason::Ok ? Reason::NoSuchVertex : r);
    }
  }
  // crash-on-self-parent
  if (auto* x = std::get_if<cmd::BoneCreate>(&c); x && is("crash-on-self-parent") && x->parent == x->bone_id) {
    Node trial = node_;
    if (trial.apply(c) == Reason::BoneCycle) std::abort();  // dies in its cycle handling
  }
  // destroy-missing-ok-double-free
  if (auto* x = std::get_if<cmd::LayerDestroy>(&c); x && is("destroy-missing-ok-double-free") && x->layer_id > 1) {
    if (!node_.find_layer(x->layer_id)) {
      if (destroyed_layers_.count(x->layer_id)) std::abort();  // freed once already
      return {true, ""};
    }
    destroyed_layers_.insert(x->layer_id);
  }
  // real32-ignored-grow-crash
  if (is("real32-ignored-grow-crash")) {
    if (auto* x = std::get_if<cmd::VertexSetXyzReal32>(&c); x && x->layer_id == 0) return {true, ""};
    if (std::holds_alternative<cmd::VertexDelete>(c)) vertex_deleted_ = true;
    if (auto* x = std::get_if<cmd::VertexSetXyzReal64>(&c); x && x->layer_id == 0 && x->vertex_id != kNone32) {
      // Only a plain new vertex grows the arrays: finite coordinates, not
      // the delete alias, a dense id (the crash is VERTEX-SET-1's alone).
      const auto ordinary = [](double v) { return std::isfinite(v) && v != DBL_MAX; };
      const bool plain = ordinary(x->x) && ordinary(x->y) && ordinary(x->z) && x->vertex_id < 65536;
      if (plain && vertex_deleted_ && (!largest_vertex_id_ || x->vertex_id > *largest_vertex_id_)) std::abort();
      largest_vertex_id_ = std::max(largest_vertex_id_.value_or(0), x->vertex_id);
    }
  }
  // grown-polygon-ids-live
  std::optional<std::uint32_t> grown_polygon_set;
  if (is("grown-polygon-ids-live")) {
    const auto phantom = [this](std::uint32_t id) {
      return id >= 32 && id < polygon_storage_ && !node_.polygons().count(id) && !unused_polygons_.count(id);
    };
    std::optional<std::uint32_t> deleted;
    if (auto* x = std::get_if<cmd::PolygonDelete>(&c)) deleted = x->polygon_id;
    if (auto* x = std::get_if<cmd::PolygonSetCornerUint32>(&c); x && x->layer_id == 1 && x->v[0] == kNone32)
      deleted = x->polygon_id;
    if (deleted && phantom(*deleted)) {
      unused_polygons_.insert(*deleted);  // marked unused, as r6's delete does
      return {true, ""};
    }
    if (auto* x = std::get_if<cmd::PolygonSetCornerUint32>(&c); x && x->layer_id == 1 && x->v[0] != kNone32) {
      if (x->polygon_id == kNone32) {  // the pick skips the phantoms
        std::uint32_t id = 0;
        while (node_.polygons().count(id) || phantom(id)) ++id;
        x->polygon_id = id;
      }
      grown_polygon_set = x->polygon_id;  // marked and grown once applied (below)
    }
  }
  // recreated-element-keeps-slots: the deleted elements' slots are kept
  // (by stack, id and layer) and given to an element created at the id.
  std::optional<Node> before_delete;
  if (is("recreated-element-keeps-slots") &&
      (std::holds_alternative<cmd::VertexDelete>(c) || std::holds_alternative<cmd::PolygonDelete>(c) ||
       is_vertex_delete_alias(c) ||
       (std::holds_alternative<cmd::PolygonSetCornerUint32>(c) &&
        std::get<cmd::PolygonSetCornerUint32>(c).layer_id == 1 && std::get<cmd::PolygonSetCornerUint32>(c).v[0] == kNone32)))
    before_delete = node_;
  // hang-on-subscribe-real64
  if (auto* x = std::get_if<cmd::LayerSubscribe>(&c); x && is("hang-on-subscribe-real64") && x->real_format == 1)
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));

  bool vertex_stack = false;
  std::uint32_t new_id = 0;
  const bool creating = creates_element(c, before, &vertex_stack, &new_id);
  const Reason r = apply_node(c);
  // ids-past-storage-bound: the new element is dropped again (a new vertex
  // has no polygons, so deleting it leaves the rest as it was).
  if (r == Reason::Ok && creating && new_id > 4129 && new_id != kNone32 && is("ids-past-storage-bound")) {
    if (vertex_stack) apply_node(cmd::VertexDelete{new_id});
    else apply_node(cmd::PolygonDelete{new_id});
    return {true, ""};
  }
  if (grown_polygon_set && r == Reason::Ok) {
    const std::uint32_t id = *grown_polygon_set;
    unused_polygons_.insert(id);  // a polygon's corners, or once deleted the unused marker
    if (id >= polygon_storage_ && id - polygon_storage_ <= 4096) polygon_storage_ = id + 32;
  }
  if (before_delete && r == Reason::Ok) {
    for (const auto& [lid, layer] : before_delete->layers()) {
      if (lid < 2) continue;
      for (const auto& [eid, slot] : layer.slots) {
        const bool gone = is_vertex_layer_type(layer.type) ? !node_.vertices().count(eid) : !node_.polygons().count(eid);
        if (gone) kept_slots_[{is_vertex_layer_type(layer.type), eid, lid, layer.type}] = slot;
      }
    }
  }
  if (r == Reason::Ok && creating && new_id != kNone32 && is("recreated-element-keeps-slots")) {
    for (const auto& [lid, layer] : node_.layers()) {
      const auto it = kept_slots_.find({vertex_stack, new_id, lid, layer.type});
      if (it == kept_slots_.end() || !layer.slots.count(new_id)) continue;
      const_cast<Layer&>(layer).slots.at(new_id) = it->second;  // test-only: reach into the node's storage
      node_changed();
    }
  }
  // no-default-on-new-slots: zero every other layer's new slot.
  if (r == Reason::Ok && creating && is("no-default-on-new-slots")) {
    for (const auto& [lid, layer] : node_.layers()) {
      if (lid < 2 || is_vertex_layer_type(layer.type) != vertex_stack) continue;
      Layer& l = const_cast<Layer&>(layer);  // test-only: reach into the node's storage
      node_changed();
      for (auto& [eid, slot] : l.slots)
        if (!before.find_layer(lid) || !before.find_layer(lid)->slots.count(eid)) slot = Slot{};
    }
  }
  return answer(r);
}

namespace {

// The node cannot hold an element at 0xFFFF by a command (it picks): the
// element kept there is moved to a free id (the first from `first`) that
// stands in for 0xFFFF, `apply_at(stand_in)` applies the command at that
// id (creating or re-creating it), and the element is moved back.
template <class Element, class ApplyAt>
Reason keep_at_pick_id(std::map<std::uint16_t, Element>& elements, std::uint32_t first, ApplyAt apply_at) {
  std::uint32_t free_id = kNone16;
  for (std::uint32_t id = first; id < kNone16 && free_id == kNone16; ++id)
    if (!elements.count(static_cast<std::uint16_t>(id))) free_id = id;
  if (free_id == kNone16) return Reason::NoFreeId;
  const auto stand_in = static_cast<std::uint16_t>(free_id);
  const auto move = [&elements](std::uint16_t from, std::uint16_t to) {
    auto n = elements.extract(from);
    if (n.empty()) return;
    n.key() = to;
    n.mapped().id = to;
    elements.insert(std::move(n));
  };
  move(kNone16, stand_in);
  const Reason r = apply_at(stand_in);
  move(stand_in, kNone16);
  return r;
}

}  // namespace

Reason FaultyNode::keep_layer_at_pick_id(cmd::LayerCreate x) {
  auto& layers = const_cast<std::map<std::uint16_t, Layer>&>(node_.layers());  // test-only: reach into the node's storage
  const Reason r = keep_at_pick_id(layers, 2, [&](std::uint16_t id) {
    x.layer_id = id;
    return apply_node(x);
  });
  node_changed();
  return r;
}

Reason FaultyNode::keep_bone_at_pick_id(cmd::BoneCreate x) {
  auto& bones = const_cast<std::map<std::uint16_t, Bone>&>(node_.bones());  // test-only: reach into the node's storage
  const Reason r = keep_at_pick_id(bones, 0, [&](std::uint16_t id) {
    x.bone_id = id;
    return apply_node(x);
  });
  node_changed();
  return r;
}

namespace {

// A snapshot line's identity: its kind and ids ("slot 3 5", "layer 2",
// "crease_edge").
std::string key_of(const std::string& line) {
  std::size_t words = 2;
  if (line.rfind("slot ", 0) == 0) words = 3;
  if (line.rfind("crease_", 0) == 0) words = 1;
  std::size_t pos = 0;
  for (std::size_t w = 0; w < words; ++w) {
    pos = line.find(' ', w == 0 ? 0 : pos + 1);
    if (pos == std::string::npos) return line;
  }
  return line.substr(0, pos);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// The line with one value changed: a layer's name gets a 'Z' in front, any
// other line a different last word.
std::string corrupt(const std::string& line) {
  if (line.rfind("layer ", 0) == 0) {
    const auto q = line.find('"');
    return q == std::string::npos ? line + " Z" : line.substr(0, q + 1) + "Z" + line.substr(q + 1);
  }
  const auto sp = line.rfind(' ');
  const std::string last = line.substr(sp + 1);
  return line.substr(0, sp + 1) + (last == "12345" ? "54321" : "12345");
}

bool info_role_needs_ok(Rule r) {
  return rule_info(r).role == RuleRole::Alias || rule_info(r).role == RuleRole::Accept;
}

bool uses_other_stack(const Node& before, const Node& after, const RuleTrace& t, const Command& c) {
  const auto* x = std::get_if<cmd::LayerCreate>(&c);
  if (!x || !t.has(Rule::LayerRetype)) return false;
  const Layer* a = before.find_layer(x->layer_id);
  const Layer* b = after.find_layer(x->layer_id);
  return a && b && is_vertex_layer_type(a->type) != is_vertex_layer_type(b->type);
}

// The element a vertex move or polygon re-definition names.
std::uint32_t target_element(const Command& c) {
  if (auto* x = std::get_if<cmd::VertexSetXyzReal64>(&c)) return x->vertex_id;
  if (auto* x = std::get_if<cmd::VertexSetXyzReal32>(&c)) return x->vertex_id;
  if (auto* x = std::get_if<cmd::PolygonSetCornerUint32>(&c)) return x->polygon_id;
  return kNone32;
}

}  // namespace

// A rule no command applies (a fresh node's state: node.base_layers,
// node.initial_creases) is broken on the fresh node itself: the lines it
// wrote there show corrupted until a command writes them again. Without
// this, "rule:node.initial_creases" changed nothing (apply_breaking only
// sees the rules of a command's trace).
FaultyNode::FaultyNode(std::vector<int> faults) : faults_(std::move(faults)) {
  for (int f : faults_) {
    if (const DerivedRule d = fault_catalog()[static_cast<std::size_t>(f)].breaks_derived; d != DerivedRule::None)
      broken_derived_ = d;
    const Rule broken = fault_catalog()[static_cast<std::size_t>(f)].breaks;
    if (broken == Rule::None) continue;
    for (const auto& l : lines_of(print_snapshot(node_)))
      if (auto w = line_written(node_, l); w && w->rule == broken && w->step == 0) corrupted_[key_of(l)] = 0;
  }
}

FaultyAnswer FaultyNode::apply_breaking(const Command& c, Rule broken) {
  RuleTrace t;
  const Reason r = apply_node(c, &t);
  if (!t.has(broken)) return answer(r);
  const Node before = replay(history_.size() - 1);
  const auto restore_before = [&] {
    node_ = before;
    history_.pop_back();
    node_changed();
  };
  // An alias or acceptance also appears in a refused command's trace (the
  // alias read, then a guard refused): only an applied one is broken.
  const bool applied_only = info_role_needs_ok(broken);
  if (applied_only && r != Reason::Ok) return answer(r);
  const RuleInfo& info = rule_info(broken);
  const std::uint32_t now = node_.step();
  bool accepts = false;  // a 15-byte name in the command: left alone, so that only `broken` is broken
  for (Rule x : t) accepts = accepts || (rule_info(x).role == RuleRole::Accept && x != broken);
  // Every line the command wrote by `rule`, by identity.
  const auto written_by = [&](Rule rule, std::map<std::string, std::uint32_t>* into) {
    for (const auto& l : lines_of(print_snapshot(node_)))
      if (auto w = line_written(node_, l); w && w->rule == rule && w->step == now) (*into)[key_of(l)] = now;
  };
  switch (info.role) {
    case RuleRole::Guard:  // claims to apply what the guard refuses, and changes nothing
      for (Rule x : t)  // only where it decides: the first guard recorded
        if (rule_info(x).role == RuleRole::Guard) {
          if (x != broken) return answer(r);
          break;
        }
      restore_before();
      return {true, ""};
    case RuleRole::Alias:
    case RuleRole::Accept:  // refuses what the rule lets through
      restore_before();
      return {false, "REJECTED"};
    case RuleRole::Place:
      if (broken == Rule::ElementIdSparse) {  // drops a large id, as a dense array would
        restore_before();
        return {false, "LIMIT"};
      }
      if (broken == Rule::LayerSlotsForStack) {
        if (is("retype-other-stack-no-slots") && !uses_other_stack(before, node_, t, c)) break;
        written_by(Rule::LayerNewSlotDefault, &hidden_);
        written_by(Rule::LayerRetypeResetsSlots, &hidden_);
      }
      if (broken == Rule::ElementGrowsLayers) written_by(Rule::ElementNewSlotDefault, &hidden_);
      break;
    case RuleRole::Value:
      if (!accepts) written_by(broken, &corrupted_);
      break;
    case RuleRole::Keep:
      if (broken == Rule::RejectedChangesNothing) {  // a refused command still changes the vertex crease
        apply_node(cmd::CreaseSetVertex{node_.vertex_crease().layer, node_.vertex_crease().def_crease + 1});
        return answer(r);
      }
      for (const auto& [lid, layer] : node_.layers()) {
        if (lid < 2) continue;
        const bool vertex_layer = is_vertex_layer_type(layer.type);
        Layer& l = const_cast<Layer&>(layer);  // test-only: reach into the node's storage
        node_changed();
        if (broken == Rule::LayerRecreateKeepsSlots) {
          if (auto* x = std::get_if<cmd::LayerCreate>(&c); x && x->layer_id == lid)
            for (auto& [eid, slot] : l.slots) slot = default_slot(l);
          continue;
        }
        if (vertex_layer != (broken == Rule::VertexMoveKeepsSlots)) continue;
        if (auto it = l.slots.find(target_element(c)); it != l.slots.end()) it->second = default_slot(l);
      }
      break;
    case RuleRole::Remove: {  // still shows the lines the rule removed
      const auto now_lines = lines_of(print_snapshot(node_));
      std::map<std::string, bool> present;
      for (const auto& l : now_lines) present[key_of(l)] = true;
      for (const auto& l : lines_of(print_snapshot(before))) {
        const std::string kind = l.substr(0, l.find(' '));
        if ((line_kind_bit(kind) & info.lines) && !present.count(key_of(l))) ghosts_[key_of(l)] = l;
      }
      break;
    }
  }
  return answer(r);
}

std::string FaultyNode::rule_fault_snapshot(std::string text) const {
  if (corrupted_.empty() && hidden_.empty() && ghosts_.empty()) return text;
  std::string out;
  std::map<std::string, bool> present;
  for (const auto& l : lines_of(text)) {
    const std::string k = key_of(l);
    present[k] = true;
    const auto w = line_written(node_, l);
    if (l == "end") {
      for (const auto& [gk, g] : ghosts_)
        if (!present.count(gk)) out += g + "\n";
    }
    if (auto it = hidden_.find(k); it != hidden_.end() && w && w->step == it->second) continue;
    if (auto it = corrupted_.find(k); it != corrupted_.end() && w && w->step == it->second) {
      out += corrupt(l) + "\n";
      continue;
    }
    out += l + "\n";
  }
  return out;
}

Reason FaultyNode::apply_node(const Command& c, RuleTrace* trace) {
  const Reason r = node_.apply(c, trace, &changes_);
  if (!digest_stale_) digest_.update(node_, changes_);
  history_.push_back(c);
  return r;
}

Node FaultyNode::replay(std::size_t n) const {
  Node node;
  for (std::size_t i = 0; i < n && i < history_.size(); ++i) node.apply(history_[i]);
  return node;
}

bool FaultyNode::documents_rewritten() const {
  if (!corrupted_.empty() || !hidden_.empty() || !ghosts_.empty()) return true;
  // The derived rewrites, where they can change a line (as derived() does them).
  const auto named = [this](const CreaseSetting& s, LayerType type) {
    const Layer* l = s.layer.empty() ? nullptr : node_.find_layer_by_name(s.layer);
    return l && l->type == type;
  };
  if (broken_derived_ != DerivedRule::None) return true;
  return (is("edge-crease-off-by-one") && named(node_.edge_crease(), LayerType::PolygonCornerUint32)) ||
         (is("wrong-type-crease-layer-used") && named(node_.vertex_crease(), LayerType::VertexReal)) ||
         (is("bone-rotation-not-inherited") && !node_.bones().empty());
}

bool FaultyNode::digest_cheap() const {
  return broken_derived_ == DerivedRule::None && !is("edge-crease-off-by-one") && !is("wrong-type-crease-layer-used") && !is("bone-rotation-not-inherited");
}

DocumentDigests FaultyNode::digests() {
  if (documents_rewritten()) return digests_of(snapshot(), derived());
  if (digest_stale_) {
    digest_ = NodeDigest(node_);
    digest_stale_ = false;
  }
  return digest_.digests();
}

std::string FaultyNode::snapshot() const { return rule_fault_snapshot(print_snapshot(node_)); }

std::string FaultyNode::request(const std::string& line) const {
  CapabilityDocumentFaults f;
  f.ignore_creases = is("subdivision-ignores-creases");
  f.zero_boundary_loops = is("classify-misses-boundary");
  f.flat_normals = is("normals-flat");
  f.loop_warren_weights = is("loop-warren-weights");
  f.edit_holes_ignored = is("edit-holes-ignored");
  f.non_manifold_smooth = is("subdivision-non-manifold-smooth");
  f.loop_edges_by_vertex_pair = is("loop-edges-by-vertex-pair");
  auto text = answer_capability_request(node_, line, f);
  return text ? *text : "error unknown request\n";
}

// A derived-rule fault, at every line the broken rule decides: a value
// rule's lines show another last number (corrupt: a crease, a rotation's
// w); derived.edge_crease.per_corner drops each polygon's last edge (a
// quad listed as a triangle, a triangle with two edges);
// derived.bone_pose.per_bone poses one bone more than the node has (the id
// past the highest, while there is a bone: a fresh node stays as it is).
std::string FaultyNode::derived_rule_fault(const std::string& text) const {
  const DerivedRule broken = broken_derived_;
  std::string out;
  for (const auto& l : lines_of(text)) {
    if (l == "end" && broken == DerivedRule::BonePosePerBone && !node_.bones().empty() &&
        node_.bones().rbegin()->first < kNone16 - 1)
      out += "bone_pose " + format_uint(static_cast<std::uint16_t>(node_.bones().rbegin()->first + 1), 16) +
             " 0 0 0 0 0 0 1\n";
    if (broken == DerivedRule::EdgePerCorner) {
      std::istringstream words(l);
      std::string kind;
      std::uint32_t polygon = 0;
      int corner = 0;
      words >> kind >> polygon >> corner;
      if (kind == "edge_crease" && node_.polygons().count(polygon) &&
          corner == corner_count(node_.polygons().at(polygon)) - 1)
        continue;
    } else if (derived_rule_of(node_, l) == broken) {
      out += corrupt(l) + "\n";
      continue;
    }
    out += l + "\n";
  }
  return out;
}

std::string FaultyNode::derived() const {
  if (broken_derived_ != DerivedRule::None) return derived_rule_fault(print_derived(node_));
  if (!is("edge-crease-off-by-one") && !is("wrong-type-crease-layer-used") && !is("bone-rotation-not-inherited"))
    return print_derived(node_);
  std::istringstream in(print_derived(node_));
  std::string line, out;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "edge_crease" && is("edge-crease-off-by-one")) {
      std::uint32_t p = 0;
      int corner = 0;
      words >> p >> corner;
      const int n = corner_count(node_.polygons().at(p));
      line = "edge_crease " + std::to_string(p) + " " + std::to_string(corner) + " " +
             format_uint(edge_crease(node_, p, (corner + 1) % n), 32);
    } else if (kind == "vertex_crease" && is("wrong-type-crease-layer-used")) {
      std::uint32_t v = 0;
      words >> v;
      const Layer* l = node_.find_layer_by_name(node_.vertex_crease().layer);
      if (l && l->type == LayerType::VertexReal) {
        const double d = l->slots.at(v).r[0];
        const std::uint32_t u = std::isfinite(d) && d >= 0 && d < 4294967295.0 ? static_cast<std::uint32_t>(d) : 0;
        line = "vertex_crease " + std::to_string(v) + " " + format_uint(u, 32);
      }
    } else if (kind == "bone_pose" && is("bone-rotation-not-inherited")) {
      long id = 0;
      words >> id;
      // Positions add up the chain without rotating; rotations are right.
      const auto poses = bone_world_poses(node_);
      const auto& bones = node_.bones();
      std::array<double, 3> pos = bones.at(static_cast<std::uint16_t>(id)).pos;
      std::uint16_t b = bones.at(static_cast<std::uint16_t>(id)).parent;
      for (std::size_t guard = 0; bones.count(b) && guard <= bones.size(); ++guard) {
        for (int i = 0; i < 3; ++i) pos[static_cast<std::size_t>(i)] += bones.at(b).pos[static_cast<std::size_t>(i)];
        b = bones.at(b).parent;
      }
      const auto& rot = poses.at(static_cast<std::uint16_t>(id)).rot;
      line = "bone_pose " + std::to_string(id);
      for (double d : pos) line += " " + format_f64(d);
      for (double d : rot) line += " " + format_f64(d);
    }
    out += line + "\n";
  }
  return out;
}

}  // namespace vgc::faults
