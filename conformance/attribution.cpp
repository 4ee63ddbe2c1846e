// attribution.cpp — see attribution.h.
#include "attribution.h"

#include <cfloat>
#include <sstream>
#include <type_traits>

namespace vgc {
namespace {

template <class... F> struct Overloaded : F... { using F::operator()...; };
template <class... F> Overloaded(F...) -> Overloaded<F...>;

constexpr std::uint32_t kLargeId = 1u << 24;  // ids this large test ID-BOUND-1

bool is_xyz_delete(const cmd::VertexSetXyzReal32& c) { return c.x == FLT_MAX || c.y == FLT_MAX || c.z == FLT_MAX; }
bool is_xyz_delete(const cmd::VertexSetXyzReal64& c) { return c.x == DBL_MAX || c.y == DBL_MAX || c.z == DBL_MAX; }

bool vertex_in_use(const Node& n, std::uint32_t v) {
  for (const auto& [pid, slot] : n.polygons())
    for (std::uint32_t c : slot.u)
      if (c == v) return true;
  return false;
}

// The clause of a value write (LAYER-VALUE-1 and its real forms).
template <class C> std::string_view value_clause(const C&) {
  using T = std::decay_t<C>;
  if constexpr (std::is_same_v<T, cmd::VertexSetReal64> || std::is_same_v<T, cmd::PolygonSetCornerReal64> ||
                std::is_same_v<T, cmd::PolygonSetFaceReal64>)
    return "REAL-STORAGE-1";
  else if constexpr (std::is_same_v<T, cmd::VertexSetReal32> || std::is_same_v<T, cmd::PolygonSetCornerReal32> ||
                     std::is_same_v<T, cmd::PolygonSetFaceReal32> || std::is_same_v<T, cmd::VertexSetXyzReal32>)
    return "REAL-32BIT-1";
  else
    return "LAYER-VALUE-1";
}

std::string_view crease_clause(const Node& n, const std::string& name, LayerType required) {
  if (name.empty()) return "CREASE-DEFAULT-1";
  const Layer* l = n.find_layer_by_name(name);
  if (!l || l->type != required) return "CREASE-LAYER-MISSING-1";
  return required == LayerType::VertexUint32 ? "CREASE-VERTEX-LAYER-1" : "CREASE-EDGE-LAYER-1";
}

// A name of exactly the longest length a name may have (15 bytes, 16 with
// the NUL: docs/spec_facts.md 2). When a command carrying one is refused, or
// its name is stored wrongly, the rule broken is taken to be the
// name-length rule (LAYER-NAME-1, CREASE-NAME-1, BONE-NAME-1), the boundary
// an implementation most often gets wrong (a 16-byte buffer without room for
// the NUL), not the command's general one. Any other fault on such a
// command is still reported, under the name clause.
bool name_at_limit(const std::string& name) { return name.size() == kMaxNameBytes; }

std::string_view vertex_set_acceptance(std::uint16_t layer, std::uint32_t id, bool is_delete, const Node& before) {
  if (is_delete) return vertex_in_use(before, id) ? "POLY-VERTEX-DELETE-1" : "VERTEX-DELETE-1";
  if (layer != Node::kVertexLayer) return "LAYER-WRITE-1";
  if (id == kNone32) return "VERTEX-ID-PICK-1";
  if (id >= kLargeId) return "ID-BOUND-1";
  return "VERTEX-SET-1";
}

}  // namespace

std::string_view clause_for_rejection(const Command& c, Reason why, const Node& /*before*/) {
  switch (why) {
    case Reason::Ok: return "ACCEPT-1";
    case Reason::BaseLayer: return "LAYER-BASE-2";
    case Reason::BadLayerType: return "LAYER-TYPE-1";
    case Reason::NameInUse: return "LAYER-NAME-2";
    case Reason::WrongLayerType: return "LAYER-WRITE-1";
    case Reason::BadRealFormat: return "LAYER-SUBSCRIBE-1";
    case Reason::NoSuchBone: return "BONE-DESTROY-1";
    case Reason::BoneCycle: return "BONE-FOREST-1";
    case Reason::BadWeightLayer: return "BONE-WEIGHT-1";
    case Reason::BadReferenceLayer: return "BONE-REFERENCE-1";
    case Reason::Limit: return "ID-BOUND-1";
    default: break;
  }
  return std::visit(
      Overloaded{
          [&](const cmd::LayerCreate&) -> std::string_view {
            return why == Reason::NoFreeId ? "LAYER-ID-PICK-1" : "LAYER-NAME-1";
          },
          [&](const cmd::LayerDestroy&) -> std::string_view { return "LAYER-DESTROY-1"; },
          [&](const cmd::LayerSubscribe&) -> std::string_view { return "LAYER-SUBSCRIBE-1"; },
          [&](const cmd::LayerUnsubscribe&) -> std::string_view { return "LAYER-SUBSCRIBE-1"; },
          [&](const cmd::VertexSetXyzReal32& x) -> std::string_view {
            if (is_xyz_delete(x)) return "VERTEX-DELETE-1";
            if (why == Reason::BadValue) return "VERTEX-FINITE-1";
            if (why == Reason::NoFreeId) return "VERTEX-ID-PICK-1";
            return "LAYER-WRITE-1";
          },
          [&](const cmd::VertexSetXyzReal64& x) -> std::string_view {
            if (is_xyz_delete(x)) return "VERTEX-DELETE-1";
            if (why == Reason::BadValue) return "VERTEX-FINITE-1";
            if (why == Reason::NoFreeId) return "VERTEX-ID-PICK-1";
            return "LAYER-WRITE-1";
          },
          [&](const cmd::VertexDelete&) -> std::string_view { return "VERTEX-DELETE-1"; },
          [&](const cmd::PolygonSetCornerUint32& x) -> std::string_view {
            if (x.layer_id != Node::kPolygonLayer) return "LAYER-WRITE-1";
            if (x.v[0] == kNone32) return "POLY-DELETE-1";
            if (why == Reason::BadPolygon)
              return (x.v[1] == kNone32 || x.v[2] == kNone32) ? "POLY-CORNERS-1" : "POLY-DISTINCT-1";
            if (why == Reason::NoSuchVertex) return "POLY-VERTEX-REF-1";
            if (why == Reason::NoFreeId) return "VERTEX-ID-PICK-1";
            return "POLY-TRIANGLE-1";
          },
          [&](const cmd::PolygonDelete&) -> std::string_view { return "POLY-DELETE-1"; },
          [&](const cmd::CreaseSetVertex&) -> std::string_view { return "CREASE-NAME-1"; },
          [&](const cmd::CreaseSetEdge&) -> std::string_view { return "CREASE-NAME-1"; },
          [&](const cmd::BoneCreate&) -> std::string_view {
            if (why == Reason::BadName) return "BONE-NAME-1";
            if (why == Reason::BadValue) return "BONE-VALUE-1";
            if (why == Reason::NoFreeId) return "BONE-ID-PICK-1";
            return "BONE-CREATE-1";
          },
          [&](const cmd::BoneDestroy&) -> std::string_view { return "BONE-DESTROY-1"; },
          [&](const auto&) -> std::string_view { return "LAYER-WRITE-1"; },  // value writes
      },
      c);
}

std::string_view clause_for_acceptance(const Command& c, const Node& before) {
  return std::visit(
      Overloaded{
          [&](const cmd::LayerCreate& x) -> std::string_view {
            if (x.name.empty()) return "LAYER-DESTROY-1";
            if (name_at_limit(x.name)) return "LAYER-NAME-1";
            if (x.layer_id == kNone16) return "LAYER-ID-PICK-1";
            if (before.find_layer(x.layer_id)) return "LAYER-RECREATE-1";
            return "LAYER-CREATE-1";
          },
          [&](const cmd::LayerDestroy&) -> std::string_view { return "LAYER-DESTROY-1"; },
          [&](const cmd::LayerSubscribe&) -> std::string_view { return "LAYER-SUBSCRIBE-1"; },
          [&](const cmd::LayerUnsubscribe&) -> std::string_view { return "LAYER-SUBSCRIBE-1"; },
          [&](const cmd::VertexSetXyzReal32& x) -> std::string_view {
            return vertex_set_acceptance(x.layer_id, x.vertex_id, is_xyz_delete(x), before);
          },
          [&](const cmd::VertexSetXyzReal64& x) -> std::string_view {
            return vertex_set_acceptance(x.layer_id, x.vertex_id, is_xyz_delete(x), before);
          },
          [&](const cmd::VertexDelete& x) -> std::string_view {
            return vertex_set_acceptance(0, x.vertex_id, true, before);
          },
          [&](const cmd::PolygonSetCornerUint32& x) -> std::string_view {
            if (x.layer_id != Node::kPolygonLayer) return "LAYER-WRITE-1";
            if (x.v[0] == kNone32) return "POLY-DELETE-1";
            if (x.polygon_id == kNone32) return "VERTEX-ID-PICK-1";
            if (x.polygon_id >= kLargeId) return "ID-BOUND-1";
            return "POLY-TRIANGLE-1";
          },
          [&](const cmd::PolygonDelete&) -> std::string_view { return "POLY-DELETE-1"; },
          [&](const cmd::CreaseSetVertex& x) -> std::string_view {
            if (name_at_limit(x.layer)) return "CREASE-NAME-1";
            return crease_clause(before, x.layer, LayerType::VertexUint32);
          },
          [&](const cmd::CreaseSetEdge& x) -> std::string_view {
            if (name_at_limit(x.layer)) return "CREASE-NAME-1";
            return crease_clause(before, x.layer, LayerType::PolygonCornerUint32);
          },
          [&](const cmd::BoneCreate& x) -> std::string_view {
            if (x.weight.empty()) return "BONE-DESTROY-1";
            if (name_at_limit(x.weight) || name_at_limit(x.reference) || name_at_limit(x.pos_label) ||
                name_at_limit(x.rot_label))
              return "BONE-NAME-1";
            if (x.bone_id == kNone16) return "BONE-ID-PICK-1";
            if (!before.bones().count(x.parent)) return "BONE-PARENT-1";
            return "BONE-CREATE-1";
          },
          [&](const cmd::BoneDestroy&) -> std::string_view { return "BONE-DESTROY-1"; },
          [&](const auto&) -> std::string_view { return "LAYER-WRITE-1"; },  // value writes
      },
      c);
}

std::string_view clause_for_snapshot(const Command& c, const Node& before, const Node& after,
                                     std::string_view kind, bool missing_or_extra) {
  (void)after;
  const bool slot = kind == "slot";
  return std::visit(
      Overloaded{
          [&](const cmd::LayerCreate& x) -> std::string_view {
            if (x.name.empty()) return "LAYER-DESTROY-1";
            if (x.layer_id == kNone16 && kind == "layer") return "LAYER-ID-PICK-1";
            if (kind == "layer" && name_at_limit(x.name)) return "LAYER-NAME-1";
            if (x.layer_id != kNone16 && before.find_layer(x.layer_id)) return "LAYER-RECREATE-1";
            if (slot) return missing_or_extra ? "LAYER-STACK-1" : "LAYER-DEFAULT-1";
            return "LAYER-CREATE-1";
          },
          [&](const cmd::LayerDestroy&) -> std::string_view { return "LAYER-DESTROY-1"; },
          [&](const cmd::LayerSubscribe&) -> std::string_view { return "LAYER-SUBSCRIBE-1"; },
          [&](const cmd::LayerUnsubscribe&) -> std::string_view { return "LAYER-SUBSCRIBE-1"; },
          [&](const cmd::VertexSetXyzReal32& x) -> std::string_view {
            if (is_xyz_delete(x))
              return kind == "polygon" ? "POLY-VERTEX-DELETE-1" : slot ? "LAYER-SIZE-1" : "VERTEX-DELETE-1";
            if (slot && x.layer_id == Node::kVertexLayer) return missing_or_extra ? "LAYER-SIZE-1" : "LAYER-DEFAULT-1";
            if (x.layer_id != Node::kVertexLayer) return "REAL-32BIT-1";
            return x.vertex_id == kNone32 ? "VERTEX-ID-PICK-1" : "REAL-32BIT-1";
          },
          [&](const cmd::VertexSetXyzReal64& x) -> std::string_view {
            if (is_xyz_delete(x))
              return kind == "polygon" ? "POLY-VERTEX-DELETE-1" : slot ? "LAYER-SIZE-1" : "VERTEX-DELETE-1";
            if (slot && x.layer_id == Node::kVertexLayer) return missing_or_extra ? "LAYER-SIZE-1" : "LAYER-DEFAULT-1";
            if (x.layer_id != Node::kVertexLayer) return "REAL-STORAGE-1";
            return x.vertex_id == kNone32 ? "VERTEX-ID-PICK-1" : "VERTEX-SET-1";
          },
          [&](const cmd::VertexDelete&) -> std::string_view {
            return kind == "polygon" ? "POLY-VERTEX-DELETE-1" : slot ? "LAYER-SIZE-1" : "VERTEX-DELETE-1";
          },
          [&](const cmd::PolygonSetCornerUint32& x) -> std::string_view {
            if (x.layer_id != Node::kPolygonLayer) return "LAYER-VALUE-1";
            if (x.v[0] == kNone32) return slot ? "LAYER-SIZE-1" : "POLY-DELETE-1";
            if (slot) return missing_or_extra ? "LAYER-SIZE-1" : "LAYER-DEFAULT-1";
            return x.polygon_id == kNone32 ? "VERTEX-ID-PICK-1" : "POLY-TRIANGLE-1";
          },
          [&](const cmd::PolygonDelete&) -> std::string_view { return slot ? "LAYER-SIZE-1" : "POLY-DELETE-1"; },
          [&](const cmd::CreaseSetVertex& x) -> std::string_view {
            if (name_at_limit(x.layer)) return "CREASE-NAME-1";
            return x.layer.empty() ? "CREASE-DEFAULT-1" : "CREASE-VERTEX-LAYER-1";
          },
          [&](const cmd::CreaseSetEdge& x) -> std::string_view {
            if (name_at_limit(x.layer)) return "CREASE-NAME-1";
            return x.layer.empty() ? "CREASE-DEFAULT-1" : "CREASE-EDGE-LAYER-1";
          },
          [&](const cmd::BoneCreate& x) -> std::string_view {
            if (x.weight.empty()) return "BONE-DESTROY-1";
            if (kind == "bone" && (name_at_limit(x.weight) || name_at_limit(x.reference) ||
                                   name_at_limit(x.pos_label) || name_at_limit(x.rot_label)))
              return "BONE-NAME-1";
            return x.bone_id == kNone16 ? "BONE-ID-PICK-1" : "BONE-CREATE-1";
          },
          [&](const cmd::BoneDestroy&) -> std::string_view { return "BONE-DESTROY-1"; },
          [&](const auto& x) -> std::string_view { return value_clause(x); },
      },
      c);
}

std::string_view clause_for_derived(const Node& after, std::string_view kind, long bone_id) {
  if (kind == "vertex_crease") {
    const auto clause = crease_clause(after, after.vertex_crease().layer, LayerType::VertexUint32);
    if (clause == "CREASE-DEFAULT-1" && after.vertex_crease().def_crease == 0) return "CREASE-INITIAL-1";
    return clause;
  }
  if (kind == "edge_crease") {
    const auto clause = crease_clause(after, after.edge_crease().layer, LayerType::PolygonCornerUint32);
    if (clause == "CREASE-DEFAULT-1" && after.edge_crease().def_crease == 0) return "CREASE-INITIAL-1";
    return clause;
  }
  if (kind == "bone_pose") {
    auto it = after.bones().find(static_cast<std::uint16_t>(bone_id));
    if (it != after.bones().end() && !after.bones().count(it->second.parent)) return "BONE-PARENT-1";
    return "BONE-DOWNSTREAM-1";
  }
  return "ATOMIC-1";
}

std::string_view clause_for_derived(const Node& after, const DocumentDifference& d, long bone_id) {
  if (d.kind == "edge_crease") {
    // "edge_crease <polygon> <corner> <crease>": the two sides list
    // different edges (a line missing, extra, or for another polygon or
    // corner) when they disagree on how many corners a polygon has, i.e.
    // whether its fourth corner is a vertex reference: POLY-TRIANGLE-1.
    // Only a different crease on the same edge is about creases.
    const auto edge = [](const std::string& line) {
      std::istringstream in(line);
      std::string kind, polygon, corner;
      in >> kind >> polygon >> corner;
      return polygon + " " + corner;
    };
    if (d.expected_line.empty() || d.observed_line.empty() || edge(d.expected_line) != edge(d.observed_line))
      return "POLY-TRIANGLE-1";
  }
  return clause_for_derived(after, d.kind, bone_id);
}

long bone_id_of(const std::string& line) {
  // "bone_pose <id> ..."
  const auto sp = line.find(' ');
  if (sp == std::string::npos) return -1;
  try {
    return std::stol(line.substr(sp + 1));
  } catch (...) {
    return -1;
  }
}

}  // namespace vgc
