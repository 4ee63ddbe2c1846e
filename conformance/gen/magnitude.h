// magnitude.h — magnitude classes of the unsigned integer fields of commands
// (header only, standard library only: the fuzz mutator uses it too).
//
// Spec: docs/spec_facts.md "Command set of the geometry node" (ids are 32 bits
// for vertices and polygons, 16 bits for layers and bones; 0xFFFFFFFF and
// 0xFFFF ask the host to pick a free id; 0xFFFFFFFF is the unused fourth
// corner and the polygon-delete alias in corner 0) and docs/commands.md 4.3
// (the id bound, ID-BOUND-1).
//
// Rationale: an implementation's storage has bounds the spec does not name
// (the r6 host ignores a vertex or polygon id more than 4,096 past its
// current storage; a node may keep 16-bit ids in a 32-bit field, or an id in
// a signed int). Drawing ids uniformly, or from "small" and "huge", never
// lands between them: ids between 4,100 and 2^24 were never drawn, so a node
// that dropped them passed VERTEX-SET-1. Each field is drawn instead from a
// class: 0, small (1..15), each power of two 2^k from 2^8 to the top of the
// field and its neighbours 2^k-1 and 2^k+1 (from 2^5 for an 8-bit field),
// the all-ones value less one, and the all-ones sentinel itself. The class is drawn uniformly, so every
// boundary gets its share whatever the field's width; the same table
// classifies a sent value, for the reach measure (generator_reach_test.cpp).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace vgc::gen {

// One class: every value in [lo, hi].
struct MagnitudeClass {
  std::string name;  // "0", "small", "2^12-1", "2^12", "2^12+1", "max-1", "max"
  std::uint64_t lo = 0, hi = 0;
};

// The classes of an unsigned field `bits` wide (8, 16 or 32), in order.
inline std::vector<MagnitudeClass> make_magnitude_classes(int bits) {
  const std::uint64_t max = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
  std::vector<MagnitudeClass> out;
  out.push_back({"0", 0, 0});
  out.push_back({"small", 1, 15});
  for (int k = bits == 8 ? 5 : 8; k < bits; ++k) {  // 2^4-1 = 15 is "small"
    const std::uint64_t p = std::uint64_t{1} << k;
    const std::string n = "2^" + std::to_string(k);
    out.push_back({n + "-1", p - 1, p - 1});
    out.push_back({n, p, p});
    out.push_back({n + "+1", p + 1, p + 1});
  }
  out.push_back({"max-1", max - 1, max - 1});
  out.push_back({"max", max, max});  // the sentinel: "pick an id", unused corner
  return out;
}

// The same, computed once per width.
inline const std::vector<MagnitudeClass>& magnitude_classes(int bits) {
  static const std::vector<MagnitudeClass> c8 = make_magnitude_classes(8), c16 = make_magnitude_classes(16),
                                           c32 = make_magnitude_classes(32);
  if (bits == 8) return c8;
  if (bits == 16) return c16;
  if (bits == 32) return c32;
  static thread_local std::vector<MagnitudeClass> other;
  other = make_magnitude_classes(bits);
  return other;
}

// The name of the class `v` falls in, or "other" (a value between classes).
inline std::string magnitude_class_of(std::uint64_t v, int bits) {
  for (const auto& c : magnitude_classes(bits))
    if (v >= c.lo && v <= c.hi) return c.name;
  return "other";
}

// A value of class `index` (0..classes-1) of a `bits`-wide field; `pick` in
// [0, 2^64) chooses within a class of several values.
inline std::uint64_t magnitude_value(int bits, std::size_t index, std::uint64_t pick) {
  const auto& classes = magnitude_classes(bits);
  const auto& c = classes[index % classes.size()];
  return c.lo + pick % (c.hi - c.lo + 1);
}

}  // namespace vgc::gen
