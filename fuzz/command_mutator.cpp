// command_mutator.cpp — see command_mutator.h.
#include "command_mutator.h"

#include <cfloat>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <type_traits>

#include "command_binary.h"
#include "command_fields.h"

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
  switch (below(rng, 10)) {
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

std::size_t encode_into(const std::vector<Command>& cs, std::uint8_t* out, std::size_t max_out) {
  std::string bytes;
  for (const Command& c : cs) {
    std::string one;
    if (!encode_command(c, &one)) continue;
    if (bytes.size() + one.size() > max_out) break;
    bytes += one;
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
    switch (n == 0 ? 0 : below(rng, 6)) {
      case 0:  // insert a new command
        cs->insert(cs->begin() + static_cast<std::ptrdiff_t>(below(rng, n + 1)), random_command(rng));
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

std::size_t cross_over_streams(const std::uint8_t* a, std::size_t a_size, const std::uint8_t* b,
                               std::size_t b_size, std::uint8_t* out, std::size_t max_out, unsigned seed) {
  std::vector<Command> ca, cb;
  if (decode_commands(a, a_size, &ca) != DecodeStatus::End) return 0;
  if (decode_commands(b, b_size, &cb) != DecodeStatus::End) return 0;
  Rng rng(seed);
  const std::size_t cut_a = below(rng, ca.size() + 1);
  const std::size_t cut_b = below(rng, cb.size() + 1);
  std::vector<Command> joined(ca.begin(), ca.begin() + static_cast<std::ptrdiff_t>(cut_a));
  joined.insert(joined.end(), cb.begin() + static_cast<std::ptrdiff_t>(cut_b), cb.end());
  return encode_into(joined, out, max_out);
}

}  // namespace vgc::fuzz
