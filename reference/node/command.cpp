// command.cpp — names, verbs and bit-exact equality of commands.
// Spec: docs/spec_facts.md (layer type values, command set).
#include "command.h"

#include <cstring>
#include <type_traits>

#include "command_fields.h"

namespace vgc {
namespace {

struct TypeName {
  std::uint8_t value;
  std::string_view name;
};
constexpr TypeName kTypeNames[] = {
    {0, "VERTEX_XYZ"},
    {1, "VERTEX_UINT32"},
    {2, "VERTEX_REAL"},
    {128, "POLYGON_CORNER_UINT32"},
    {129, "POLYGON_CORNER_REAL"},
    {130, "POLYGON_FACE_UINT8"},
    {131, "POLYGON_FACE_UINT32"},
    {132, "POLYGON_FACE_REAL"},
};

// In the order of the Command variant.
constexpr std::string_view kVerbs[] = {
    "layer_create",
    "layer_destroy",
    "layer_subscribe",
    "layer_unsubscribe",
    "vertex_set_xyz_real32",
    "vertex_set_xyz_real64",
    "vertex_delete",
    "vertex_set_uint32",
    "vertex_set_real64",
    "vertex_set_real32",
    "polygon_set_corner_uint32",
    "polygon_set_corner_real64",
    "polygon_set_corner_real32",
    "polygon_delete",
    "polygon_set_face_uint8",
    "polygon_set_face_uint32",
    "polygon_set_face_real64",
    "polygon_set_face_real32",
    "crease_set_vertex",
    "crease_set_edge",
    "bone_create",
    "bone_destroy",
};
static_assert(sizeof(kVerbs) / sizeof(kVerbs[0]) == kCommandKinds, "one verb per command");

template <class T> bool field_equal(const T& a, const T& b) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
  } else if constexpr (std::is_same_v<T, std::string> || std::is_integral_v<T>) {
    return a == b;
  } else {  // std::array of numbers
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!field_equal(a[i], b[i])) return false;
    return true;
  }
}

}  // namespace

bool is_layer_type(std::uint8_t raw) { return !layer_type_name(raw).empty(); }

std::string_view layer_type_name(std::uint8_t raw) {
  for (const auto& t : kTypeNames)
    if (t.value == raw) return t.name;
  return {};
}

bool parse_layer_type_name(std::string_view name, std::uint8_t* out) {
  for (const auto& t : kTypeNames)
    if (t.name == name) {
      *out = t.value;
      return true;
    }
  return false;
}

std::string_view command_verb(std::size_t index) {
  return index < kCommandKinds ? kVerbs[index] : std::string_view{};
}
std::string_view command_verb(const Command& c) { return command_verb(c.index()); }

bool bit_equal(const Command& a, const Command& b) {
  if (a.index() != b.index()) return false;
  return std::visit(
      [&](const auto& x) {
        using C = std::decay_t<decltype(x)>;
        const C& y = std::get<C>(b);
        // Walk both commands' fields in step: collect y's field addresses
        // by walking it with the same visitor order.
        std::vector<const void*> ys;
        visit_fields_const(y, [&](const char*, const auto& f, FieldHint) { ys.push_back(&f); });
        std::size_t i = 0;
        bool eq = true;
        visit_fields_const(x, [&](const char*, const auto& f, FieldHint) {
          using F = std::decay_t<decltype(f)>;
          eq = eq && field_equal(f, *static_cast<const F*>(ys[i]));
          ++i;
        });
        return eq;
      },
      a);
}

}  // namespace vgc
