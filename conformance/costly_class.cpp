// costly_class.cpp — see costly_class.h.
#include "costly_class.h"

#include <algorithm>
#include <type_traits>

namespace vgc {
namespace {

struct ElementId {
  ElementKind kind;
  std::uint32_t id;
};

// Every element id `c` names (the sentinel left out).
std::vector<ElementId> element_ids(const Command& c) {
  std::vector<ElementId> out;
  auto add = [&out](ElementKind k, std::uint32_t id) {
    if (id != kNone32) out.push_back({k, id});
  };
  std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, cmd::PolygonSetCornerUint32>) {
          add(ElementKind::Polygon, x.polygon_id);
          if (x.layer_id == 1)
            for (std::uint32_t v : x.v) add(ElementKind::Vertex, v);
        } else if constexpr (std::is_same_v<T, cmd::PolygonSetCornerReal64> ||
                             std::is_same_v<T, cmd::PolygonSetCornerReal32> ||
                             std::is_same_v<T, cmd::PolygonDelete> || std::is_same_v<T, cmd::PolygonSetFaceUint8> ||
                             std::is_same_v<T, cmd::PolygonSetFaceUint32> ||
                             std::is_same_v<T, cmd::PolygonSetFaceReal64> ||
                             std::is_same_v<T, cmd::PolygonSetFaceReal32>) {
          add(ElementKind::Polygon, x.polygon_id);
        } else if constexpr (std::is_same_v<T, cmd::VertexSetXyzReal32> || std::is_same_v<T, cmd::VertexSetXyzReal64> ||
                             std::is_same_v<T, cmd::VertexDelete> || std::is_same_v<T, cmd::VertexSetUint32> ||
                             std::is_same_v<T, cmd::VertexSetReal64> || std::is_same_v<T, cmd::VertexSetReal32>) {
          add(ElementKind::Vertex, x.vertex_id);
        }
      },
      c);
  return out;
}

std::uint32_t power_of_two_floor(std::uint32_t v) {
  std::uint32_t p = 1;
  while (p <= v / 2) p *= 2;
  return p;
}

}  // namespace

std::optional<CostlyClass> costly_class_of(const Command& c) {
  std::optional<ElementId> largest;
  for (const ElementId& e : element_ids(c))
    if (!largest || e.id > largest->id) largest = e;
  if (!largest || largest->id < 256) return std::nullopt;
  return CostlyClass{largest->kind, power_of_two_floor(largest->id)};
}

bool in_costly_class(const Command& c, const std::vector<CostlyClass>& avoided) {
  if (avoided.empty()) return false;
  for (const ElementId& e : element_ids(c))
    for (const CostlyClass& k : avoided)
      if (e.kind == k.kind && e.id >= k.floor) return true;
  return false;
}

std::string describe_costly_class(const CostlyClass& k) {
  int bits = 0;
  while (bits < 32 && (std::uint32_t{1} << bits) != k.floor) ++bits;
  return std::string(k.kind == ElementKind::Vertex ? "vertex" : "polygon") + " ids of 2^" + std::to_string(bits) +
         " (" + std::to_string(k.floor) + ") or more";
}

}  // namespace vgc
