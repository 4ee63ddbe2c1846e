// implementation_choice.cpp — see implementation_choice.h. Spec: README
// "pick a free id" (LAYER-ID-PICK-1, VERTEX-ID-PICK-1, BONE-ID-PICK-1).
#include "implementation_choice.h"

#include <cfloat>
#include <set>
#include <type_traits>
#include <variant>

#include "command_text.h"
#include "document_diff.h"
#include "number_text.h"
#include "snapshot.h"

namespace vgc {
namespace {

// What a picking command creates: the snapshot line kind of its element,
// the id width, the id range it picks from, and the clause of its reading.
struct Pick {
  const char* kind;  // "layer", "vertex", "polygon", "bone"
  int bits;
  std::uint32_t first, last;
  const char* clause;
};

std::optional<Pick> pick_of(const Command& c) {
  if (const auto* x = std::get_if<cmd::LayerCreate>(&c); x && x->layer_id == kNone16 && !x->name.empty())
    return Pick{"layer", 16, 2, 0xFFFE, "LAYER-ID-PICK-1"};
  if (const auto* x = std::get_if<cmd::VertexSetXyzReal32>(&c);
      x && x->layer_id == Node::kVertexLayer && x->vertex_id == kNone32 && x->x != FLT_MAX && x->y != FLT_MAX &&
      x->z != FLT_MAX)
    return Pick{"vertex", 32, 0, 0xFFFFFFFE, "VERTEX-ID-PICK-1"};
  if (const auto* x = std::get_if<cmd::VertexSetXyzReal64>(&c);
      x && x->layer_id == Node::kVertexLayer && x->vertex_id == kNone32 && x->x != DBL_MAX && x->y != DBL_MAX &&
      x->z != DBL_MAX)
    return Pick{"vertex", 32, 0, 0xFFFFFFFE, "VERTEX-ID-PICK-1"};
  if (const auto* x = std::get_if<cmd::PolygonSetCornerUint32>(&c);
      x && x->layer_id == Node::kPolygonLayer && x->polygon_id == kNone32 && x->v[0] != kNone32)
    return Pick{"polygon", 32, 0, 0xFFFFFFFE, "VERTEX-ID-PICK-1"};
  if (const auto* x = std::get_if<cmd::BoneCreate>(&c); x && x->bone_id == kNone16 && !x->weight.empty())
    return Pick{"bone", 16, 0, 0xFFFE, "BONE-ID-PICK-1"};
  return std::nullopt;
}

// The same command with `id` written instead of "pick".
Command with_id(Command c, std::uint32_t id) {
  std::visit(
      [id](auto& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, cmd::LayerCreate>) x.layer_id = static_cast<std::uint16_t>(id);
        if constexpr (std::is_same_v<T, cmd::VertexSetXyzReal32> || std::is_same_v<T, cmd::VertexSetXyzReal64>)
          x.vertex_id = id;
        if constexpr (std::is_same_v<T, cmd::PolygonSetCornerUint32>) x.polygon_id = id;
        if constexpr (std::is_same_v<T, cmd::BoneCreate>) x.bone_id = static_cast<std::uint16_t>(id);
      },
      c);
  return c;
}

// The ids of `kind` lines ("<kind> <id> ...") in a snapshot document.
std::set<std::uint32_t> ids_in(const std::string& snapshot, const Pick& p) {
  std::set<std::uint32_t> out;
  const std::string head = std::string(p.kind) + " ";
  for (const std::string& line : split_lines(snapshot)) {
    if (line.rfind(head, 0) != 0) continue;
    const std::size_t end = line.find(' ', head.size());
    std::uint32_t id = 0;
    if (parse_uint(std::string_view(line).substr(head.size(), end == std::string::npos ? std::string::npos
                                                                                         : end - head.size()),
                   p.bits, &id))
      out.insert(id);
  }
  return out;
}

std::string id_text(std::uint32_t id, int bits) { return format_uint(id, bits); }

}  // namespace

std::optional<ChoiceFollowed> follow_implementation_choice(const Node& before, const Command& c,
                                                           const std::string& observed) {
  const std::optional<Pick> p = pick_of(c);
  if (!p) return std::nullopt;
  const std::set<std::uint32_t> had = ids_in(print_snapshot(before), *p);
  std::optional<std::uint32_t> picked;
  for (std::uint32_t id : ids_in(observed, *p)) {
    if (had.count(id)) continue;
    if (picked) return std::nullopt;  // more than one new element: not a choice of id
    picked = id;
  }
  if (!picked || *picked < p->first || *picked > p->last) return std::nullopt;
  ChoiceFollowed out;
  out.model = before;
  out.applied = with_id(c, *picked);
  if (out.model.apply(out.applied) != Reason::Ok) return std::nullopt;
  if (diff_documents(print_snapshot(out.model), observed)) return std::nullopt;  // it differs otherwise too

  Node lowest = before;  // what the suite's reading picks, for the note
  lowest.apply(c);
  std::optional<std::uint32_t> reading;
  for (std::uint32_t id : ids_in(print_snapshot(lowest), *p))
    if (!had.count(id)) reading = id;
  out.note.clause = p->clause;
  out.note.status = FindingStatus::Fail;
  out.note.message = "`" + print_command(c) + "` created " + p->kind + " " + id_text(*picked, p->bits) +
                     "; the suite's reading picks the lowest free id" +
                     (reading ? " (" + id_text(*reading, p->bits) + ")" : std::string()) +
                     ". The spec asks for \"a free id\", so the model follows the implementation's choice.";
  return out;
}

}  // namespace vgc
