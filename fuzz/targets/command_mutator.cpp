// command_mutator.cpp — see command_mutator.h.
#include "command_mutator.h"

#include <algorithm>
#include <cfloat>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <type_traits>

#include "command_binary.h"
#include "command_fields.h"
#include "magnitude.h"
#include "node.h"

namespace vgc::fuzz {
namespace {

using Rng = std::mt19937;

std::size_t below(Rng& rng, std::size_t n) { return n == 0 ? 0 : rng() % n; }

// Names creases and bones can refer to: the base layers, a few short ones,
// the longest valid name, one byte too long, one with a NUL.
const char* const kNames[] = {"",     "vertex", "polygon", "a",      "b",      "crease",
                              "edge", "weight", "ref",     "uv",     "pos",    "rot",
                              "abcdefghijklmno", "abcdefghijklmnop"};

std::string pick_name(Rng& rng) {
  const std::size_t n = sizeof(kNames) / sizeof(kNames[0]);
  const std::size_t k = below(rng, n + 2);
  if (k < n) return kNames[k];
  if (k == n) return std::string("a\0b", 3);
  std::string s(below(rng, 20), 'x');
  for (char& c : s) c = static_cast<char>('a' + below(rng, 26));
  return s;
}

template <class T> T pick_uint(Rng& rng, T current) {
  constexpr T kMax = std::numeric_limits<T>::max();
  constexpr int kBits = static_cast<int>(sizeof(T) * 8);
  switch (below(rng, 12)) {
    case 10:
    case 11: {  // a magnitude class (magnitude.h): 2^k and its neighbours, where storage bounds are
      static const std::size_t classes = gen::magnitude_classes(kBits).size();
      return static_cast<T>(gen::magnitude_value(kBits, below(rng, classes), rng()));
    }
    case 0: return 0;
    case 1: return 1;
    case 2: case 3: return static_cast<T>(below(rng, 4));   // small ids hit live elements
    case 4: return static_cast<T>(below(rng, 16));
    case 5: return kMax;                                     // "pick an id", unused corner, max crease
    case 6: return static_cast<T>(kMax - 1);
    case 7: return static_cast<T>(current + 1);
    case 8: return static_cast<T>(current - 1);
    default: return static_cast<T>(rng());
  }
}

std::uint8_t pick_layer_type(Rng& rng) {
  static const std::uint8_t kTypes[] = {0, 1, 2, 128, 129, 130, 131, 132};
  if (below(rng, 8) == 0) return static_cast<std::uint8_t>(rng());
  return kTypes[below(rng, 8)];
}

template <class F> F pick_float(Rng& rng, F current) {
  using L = std::numeric_limits<F>;
  switch (below(rng, 16)) {
    case 0: return F(0);
    case 1: return -F(0);
    case 2: return F(1);
    case 3: return F(-1);
    case 4: return L::quiet_NaN();
    case 5: {  // a NaN with a payload, either sign
      using U = std::conditional_t<sizeof(F) == 4, std::uint32_t, std::uint64_t>;
      U bits;
      F nan = L::quiet_NaN();
      std::memcpy(&bits, &nan, sizeof bits);
      bits |= static_cast<U>(rng()) & (U(0xFFFF));
      if (below(rng, 2)) bits |= U(1) << (sizeof(U) * 8 - 1);
      F out;
      std::memcpy(&out, &bits, sizeof out);
      return out;
    }
    case 6: return L::infinity();
    case 7: return -L::infinity();
    case 8: return L::max();  // FLT_MAX / DBL_MAX: the delete forms
    case 9: return L::lowest();
    case 10: return L::denorm_min();
    case 11: return current * F(2);
    case 12: return -current;
    default: return static_cast<F>(static_cast<int>(below(rng, 21)) - 10) / F(2);
  }
}

template <class T> void pick_scalar(Rng& rng, T& v, FieldHint hint) {
  if constexpr (std::is_same_v<T, std::string>) {
    v = pick_name(rng);
  } else if constexpr (std::is_floating_point_v<T>) {
    v = pick_float<T>(rng, v);
  } else if (hint == FieldHint::LayerType) {
    v = pick_layer_type(rng);
  } else if (hint == FieldHint::RealFormat) {
    v = static_cast<T>(below(rng, 4) == 0 ? rng() : below(rng, 2));
  } else {
    v = pick_uint<T>(rng, v);
  }
}

// Randomizes every field (whole=true) or only the field numbered `target`.
struct FieldMutator {
  Rng& rng;
  bool whole;
  std::size_t target;
  std::size_t index = 0;
  template <class T> void operator()(const char*, T& v, FieldHint hint) {
    const bool hit = whole || index == target;
    ++index;
    if (!hit) return;
    if constexpr (std::is_class_v<T> && !std::is_same_v<T, std::string>) {
      if (whole) {
        for (auto& e : v) pick_scalar(rng, e, hint);
      } else {
        pick_scalar(rng, v[below(rng, v.size())], hint);
      }
    } else {
      pick_scalar(rng, v, hint);
    }
  }
};

struct FieldCounter {
  std::size_t n = 0;
  template <class T> void operator()(const char*, T&, FieldHint) { ++n; }
};

template <std::size_t I = 0> void emplace_kind(std::size_t index, Command* out) {
  if constexpr (I < kCommandKinds) {
    if (index == I) {
      out->emplace<I>();
      return;
    }
    emplace_kind<I + 1>(index, out);
  }
}

Command random_command(Rng& rng) {
  Command c;
  emplace_kind(below(rng, kCommandKinds), &c);
  std::visit([&](auto& x) { visit_fields(x, FieldMutator{rng, true, 0}); }, c);
  // Polygon corners mostly name small, distinct vertices, with an unused 4th.
  if (auto* p = std::get_if<cmd::PolygonSetCornerUint32>(&c); p && below(rng, 2)) {
    p->layer_id = 1;
    const std::uint32_t base = static_cast<std::uint32_t>(below(rng, 4));
    for (std::uint32_t i = 0; i < 4; ++i) p->v[i] = base + i;
    if (below(rng, 2)) p->v[3] = kNone32;
  }
  return c;
}

void mutate_field(Rng& rng, Command& c) {
  std::visit(
      [&](auto& x) {
        FieldCounter count;
        visit_fields(x, count);
        visit_fields(x, FieldMutator{rng, false, below(rng, count.n)});
      },
      c);
}

// The ids the stream itself creates, by kind. A rule shows only on a state
// whose ids match (a polygon on live vertices, a slot write to a live layer,
// a bone under a live bone); edits that pick ids from the value pools
// above make such a state rarely, and from an empty corpus the faults that
// need a polygon were not found within 60 s (docs/fuzzing.md "Time to
// find"). link_ids and insert_polygon build it directly.
struct StreamIds {
  std::vector<std::uint32_t> layers{Node::kVertexLayer, Node::kPolygonLayer}, vertices, polygons, bones;
};

StreamIds ids_of(const std::vector<Command>& cs) {
  StreamIds ids;
  for (const Command& c : cs) {
    if (const auto* l = std::get_if<cmd::LayerCreate>(&c)) ids.layers.push_back(l->layer_id);
    if (const auto* v = std::get_if<cmd::VertexSetXyzReal64>(&c)) ids.vertices.push_back(v->vertex_id);
    if (const auto* v = std::get_if<cmd::VertexSetXyzReal32>(&c)) ids.vertices.push_back(v->vertex_id);
    if (const auto* p = std::get_if<cmd::PolygonSetCornerUint32>(&c); p && p->layer_id == Node::kPolygonLayer)
      ids.polygons.push_back(p->polygon_id);
    if (const auto* b = std::get_if<cmd::BoneCreate>(&c)) ids.bones.push_back(b->bone_id);
  }
  return ids;
}

// Points one id field of `c` at an id the stream creates: layer_id at a
// layer, vertex_id at a vertex, polygon_id at a polygon, bone_id and parent
// at a bone, a polygon's corners at distinct vertices. Nothing to point at:
// no change.
struct IdLinker {
  Rng& rng;
  const StreamIds& ids;
  std::size_t target;
  std::size_t index = 0;
  template <class T> void operator()(const char* name, T& v, FieldHint) {
    if (!linkable(name)) return;
    if (index++ != target) return;
    const std::string_view n(name);
    if constexpr (std::is_integral_v<T>) {
      const auto& pool = n == "layer_id" ? ids.layers
                         : n == "vertex_id" ? ids.vertices
                         : n == "polygon_id" ? ids.polygons
                                             : ids.bones;
      if (!pool.empty()) v = static_cast<T>(pool[below(rng, pool.size())]);
    } else if constexpr (std::is_same_v<T, std::array<std::uint32_t, 4>>) {
      std::vector<std::uint32_t> pool = ids.vertices;
      std::sort(pool.begin(), pool.end());
      pool.erase(std::unique(pool.begin(), pool.end()), pool.end());
      if (pool.size() < 3) return;
      const std::size_t n_corners = pool.size() >= 4 && below(rng, 2) ? 4 : 3;
      v = {kNone32, kNone32, kNone32, kNone32};
      for (std::size_t i = 0; i < n_corners; ++i) {
        const std::size_t k = below(rng, pool.size());
        v[i] = pool[k];
        pool.erase(pool.begin() + static_cast<std::ptrdiff_t>(k));
      }
    }
  }
  static bool linkable(std::string_view n) {
    return n == "layer_id" || n == "vertex_id" || n == "polygon_id" || n == "bone_id" || n == "parent" || n == "v";
  }
};

struct LinkableCounter {
  std::size_t n = 0;
  template <class T> void operator()(const char* name, T&, FieldHint) {
    if (!IdLinker::linkable(name)) return;
    if constexpr (std::is_integral_v<T> || std::is_same_v<T, std::array<std::uint32_t, 4>>) ++n;
  }
};

void link_ids(Rng& rng, std::vector<Command>* cs) {
  if (cs->empty()) return;
  const StreamIds ids = ids_of(*cs);
  Command& c = (*cs)[below(rng, cs->size())];
  std::visit(
      [&](auto& x) {
        LinkableCounter count;
        visit_fields(x, count);
        if (count.n > 0) visit_fields(x, IdLinker{rng, ids, below(rng, count.n)});
      },
      c);
}

// Three or four vertices at small ids and, right after them, a polygon on
// them: the smallest state where polygon, corner-layer and crease rules show.
void insert_polygon(Rng& rng, std::vector<Command>* cs) {
  const std::size_t n = below(rng, 2) ? 3 : 4;
  const std::uint32_t base = static_cast<std::uint32_t>(below(rng, 6));
  std::vector<Command> piece;
  cmd::PolygonSetCornerUint32 p;
  p.layer_id = Node::kPolygonLayer;
  p.polygon_id = static_cast<std::uint32_t>(below(rng, 4));
  p.v = {kNone32, kNone32, kNone32, kNone32};
  for (std::size_t i = 0; i < n; ++i) {
    cmd::VertexSetXyzReal64 v;
    v.layer_id = Node::kVertexLayer;
    v.vertex_id = base + static_cast<std::uint32_t>(i);
    v.x = static_cast<double>(i == 1 || i == 2);
    v.y = static_cast<double>(i >= 2);
    v.z = static_cast<double>(below(rng, 3));
    piece.emplace_back(v);
    p.v[i] = v.vertex_id;
  }
  piece.emplace_back(p);
  cs->insert(cs->begin() + static_cast<std::ptrdiff_t>(below(rng, cs->size() + 1)), piece.begin(), piece.end());
}

// A vertex weight layer and a bone on it whose parent is a bone the stream
// creates (or, with none yet, a small id): bone hierarchies, cycles and
// poses need a bone the node accepts, which needs a weight layer by name.
void insert_bone(Rng& rng, std::vector<Command>* cs) {
  const StreamIds ids = ids_of(*cs);
  cmd::LayerCreate layer;
  layer.layer_id = static_cast<std::uint16_t>(2 + below(rng, 4));
  layer.name = below(rng, 2) ? "weight" : "w";
  layer.type = static_cast<std::uint8_t>(below(rng, 2) ? LayerType::VertexReal : LayerType::VertexUint32);
  cmd::BoneCreate bone;
  bone.bone_id = static_cast<std::uint16_t>(below(rng, 4));
  bone.weight = layer.name;
  bone.parent = ids.bones.empty() || below(rng, 4) == 0 ? static_cast<std::uint16_t>(below(rng, 4))
                                                        : static_cast<std::uint16_t>(ids.bones[below(rng, ids.bones.size())]);
  bone.pos = {static_cast<double>(below(rng, 3)), 0, 0};
  const std::size_t at = below(rng, cs->size() + 1);
  cs->insert(cs->begin() + static_cast<std::ptrdiff_t>(at), Command{bone});
  cs->insert(cs->begin() + static_cast<std::ptrdiff_t>(at), Command{layer});
}

std::size_t encode_into(const std::vector<Command>& cs, std::uint8_t* out, std::size_t max_out) {
  std::string bytes;
  for (const Command& c : cs) {
    const std::size_t before = bytes.size();
    if (!encode_command(c, &bytes)) continue;
    if (bytes.size() > max_out) {
      bytes.resize(before);
      break;
    }
  }
  if (!bytes.empty()) std::memcpy(out, bytes.data(), bytes.size());
  return bytes.size();
}

}  // namespace

void mutate_commands(std::vector<Command>* cs, unsigned seed) {
  Rng rng(seed);
  const std::size_t edits = 1 + below(rng, 3);
  for (std::size_t e = 0; e < edits; ++e) {
    const std::size_t n = cs->size();
    static const std::size_t kFromNothing[] = {0, 7, 8};  // an empty stream: only what adds
    switch (n == 0 ? kFromNothing[below(rng, 3)] : below(rng, 9)) {
      case 0:  // insert a new command
        cs->insert(cs->begin() + static_cast<std::ptrdiff_t>(below(rng, n + 1)), random_command(rng));
        break;
      case 6:  // point an id field at an id the stream creates
        link_ids(rng, cs);
        break;
      case 7:  // insert vertices and a polygon on them
        insert_polygon(rng, cs);
        break;
      case 8:  // insert a weight layer and a bone on it
        insert_bone(rng, cs);
        break;
      case 1:  // delete one
        cs->erase(cs->begin() + static_cast<std::ptrdiff_t>(below(rng, n)));
        break;
      case 2: {  // duplicate one right after itself
        const std::size_t i = below(rng, n);
        const Command copy = (*cs)[i];
        cs->insert(cs->begin() + static_cast<std::ptrdiff_t>(i + 1), copy);
        break;
      }
      case 3:  // swap two
        std::swap((*cs)[below(rng, n)], (*cs)[below(rng, n)]);
        break;
      default:  // change one field of one command
        mutate_field(rng, (*cs)[below(rng, n)]);
        break;
    }
  }
}

std::size_t mutate_stream(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned seed) {
  std::vector<Command> cs;
  if (decode_commands(data, size, &cs) != DecodeStatus::End) return 0;
  mutate_commands(&cs, seed);
  const std::size_t n = encode_into(cs, data, max_size);
  return n == 0 ? 0 : n;
}

namespace {

// Where each command of a stream starts, then the stream's size; false
// unless the whole stream decodes. One Command decoded into at a time: no
// vector of commands, and the splice below copies bytes instead of
// re-encoding (re-encoding a decoded command gives back its bytes, which
// fuzz_stream checks on every command it runs).
bool command_starts(const std::uint8_t* data, std::size_t size, std::vector<std::size_t>* starts) {
  starts->clear();
  std::size_t pos = 0;
  Command c;
  for (;;) {
    starts->push_back(pos);
    const DecodeStatus s = decode_command(data, size, &pos, &c);
    if (s == DecodeStatus::End) return true;
    if (s != DecodeStatus::Ok) return false;
  }
}

}  // namespace

// The same bytes as decoding both streams, joining a's first cut_a commands
// with b's from cut_b on and re-encoding as many as fit (encode_into), at a
// fraction of the cost: the cross-over was a tenth of a fuzz_stream run.
std::size_t cross_over_streams(const std::uint8_t* a, std::size_t a_size, const std::uint8_t* b,
                               std::size_t b_size, std::uint8_t* out, std::size_t max_out, unsigned seed) {
  std::vector<std::size_t> sa, sb;
  if (!command_starts(a, a_size, &sa) || !command_starts(b, b_size, &sb)) return 0;
  Rng rng(seed);
  const std::size_t cut_a = below(rng, sa.size());  // sa.size() - 1 commands: a cut in [0, that]
  const std::size_t cut_b = below(rng, sb.size());
  std::size_t n = 0;
  // Copies commands [from, to) of `stream` while they fit; false at the first that does not.
  auto take = [&](const std::uint8_t* stream, const std::vector<std::size_t>& starts, std::size_t from,
                  std::size_t to) {
    for (std::size_t i = from; i < to; ++i) {
      const std::size_t len = starts[i + 1] - starts[i];
      if (n + len > max_out) return false;
      std::memcpy(out + n, stream + starts[i], len);
      n += len;
    }
    return true;
  };
  if (take(a, sa, 0, cut_a)) take(b, sb, cut_b, sb.size() - 1);
  return n;
}

}  // namespace vgc::fuzz
