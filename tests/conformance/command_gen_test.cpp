// command_gen_test.cpp — the command generators reach the states the
// clauses are decided in (conformance/command_gen.h for the properties,
// conformance/gen/arbitrary_command.h for the reference's own properties).
//
// Each test draws many sequences with fixed seeds, as certify and the
// property fuzz targets do, and counts how many reach a state; the bounds
// are well under what the generators reach and well over what the
// generators before this change reached (figures in the comments, both
// measured with these tests), so each test fails if its bias is lost.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>

#include "command_gen.h"
#include "command_text.h"
#include "crease.h"
#include "gen/arbitrary_command.h"
#include "property.h"

namespace vgc {
namespace {

// Whether `reached` holds after some command of a sequence of `length`
// commands drawn for the state the previous ones left, from a fresh node,
// as byte_cases.cpp draws them (seed, size). Certify compares the states
// after every command, so a state counts even if a later command leaves it.
template <class Pred> bool focus_reaches(Focus focus, std::uint64_t seed, int length, Pred reached) {
  Node model;
  for (int i = 0; i < length; ++i) {
    const Command c = gen_command(model, focus)(rc::Random(seed * 1000 + static_cast<std::uint64_t>(i)), 50).value();
    model.apply(c);
    if (reached(model)) return true;
  }
  return false;
}

// A default-valued command of variant alternative `k` (for its name).
template <std::size_t... I> Command command_of_kind(std::size_t k, std::index_sequence<I...>) {
  Command c;
  ((k == I ? (void)(c = std::variant_alternative_t<I, Command>{}) : void()), ...);
  return c;
}
Command command_of_kind(std::size_t k) { return command_of_kind(k, std::make_index_sequence<kCommandKinds>{}); }

double squared_norm(const std::array<double, 4>& q) { return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]; }

// The quaternions of gen_quaternion_extreme cover every class named in its
// comment. Before: no such generator.
TEST(CommandGen, ExtremeQuaternionsCoverUnderflowOverflowSubnormalZeroAndNonFinite) {
  int underflow = 0, overflow = 0, subnormal_square = 0, zero = 0, non_finite = 0, normal = 0;
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    const auto q = gen::gen_quaternion_extreme()(rc::Random(seed), 50).value();
    const double n2 = squared_norm(q);
    const bool all_zero = q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0;
    bool finite = true;
    for (double c : q) finite = finite && std::isfinite(c);
    if (!finite) ++non_finite;
    else if (all_zero) ++zero;
    else if (n2 == 0) ++underflow;
    else if (std::isinf(n2)) ++overflow;
    else if (n2 < DBL_MIN) ++subnormal_square;
    else ++normal;
  }
  std::printf("underflow %d overflow %d subnormal %d zero %d non-finite %d normal %d\n", underflow, overflow,
              subnormal_square, zero, non_finite, normal);
  EXPECT_GE(underflow, 100);
  EXPECT_GE(overflow, 100);
  EXPECT_GE(subnormal_square, 20);
  EXPECT_GE(zero, 20);
  EXPECT_GE(non_finite, 20);
}

// The bones focus (bones.stateful) stores bones whose rotation has a norm
// that underflows or overflows, so the pose's normalization is checked
// there (a clean-room node divided by zero on rot=(1e-300,0,0,0)). Of 1000
// sequences of 40 commands: 0 before this generator, 176 with it.
TEST(CommandGen, BonesFocusStoresBonesWithDegenerateRotationNorms) {
  int sequences = 0;
  for (std::uint64_t seed = 1; seed <= 1000; ++seed) {
    sequences += focus_reaches(Focus::Bones, seed, 40, [](const Node& n) {
      for (const auto& [id, b] : n.bones()) {
        const double n2 = squared_norm(b.rot);
        if (n2 == 0 || std::isinf(n2)) return true;
      }
      return false;
    });
  }
  std::printf("%d of 1000 sequences hold a bone with a degenerate rotation norm\n", sequences);
  EXPECT_GE(sequences, 80);
}

// A state where the edge setting names a POLYGON_CORNER_UINT32 layer and a
// live polygon has two adjacent corners with different values in it: only
// there does the corner-to-edge rule (CREASE-EDGE-LAYER-1) show an
// off-by-one corner. Of 1000 sequences of 40 commands: 52 before the
// state-aware weights, 160 with them.
TEST(CommandGen, CreasesFocusReachesUnequalAdjacentEdgeCreases) {
  int sequences = 0;
  for (std::uint64_t seed = 1; seed <= 1000; ++seed) {
    sequences += focus_reaches(Focus::Creases, seed, 40, [](const Node& n) {
      for (const auto& [id, p] : n.polygons()) {
        const int k = corner_count(p);
        for (int c = 0; c < k; ++c)
          if (edge_crease(n, id, c) != edge_crease(n, id, (c + 1) % k)) return true;
      }
      return false;
    });
  }
  std::printf("%d of 1000 sequences reach unequal adjacent edge creases\n", sequences);
  EXPECT_GE(sequences, 100);
}

// gen_command_for (the reference's atomicity property, routes_agree) makes
// non-base layers and bones in most sequences: a layer_create's id is
// mostly 2..5, not the base layers 0 and 1 that always exist. Of 300
// sequences of 30 commands, before: 52 with a layer, 5 with a bone; now
// 247 and 53.
TEST(CommandGen, StateAwareSequencesHoldLayersAndBones) {
  int layers = 0, bones = 0;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    const auto cs = gen::gen_command_sequence(30)(rc::Random(seed), 50).value();
    Node n;
    for (const auto& c : cs) n.apply(c);
    layers += n.layers().size() > 2;
    bones += !n.bones().empty();
  }
  std::printf("of 300 sequences: %d hold a non-base layer, %d a bone\n", layers, bones);
  EXPECT_GE(layers, 150);
  EXPECT_GE(bones, 25);
}

// Every command kind of the language is generated and applied by the
// reference, from the generators alone: each property's focus, sequences
// from a fresh node at sizes 0..50 as certify draws them (a cheap proxy of
// a default certify run; the runner's own per-kind table is the real
// measure). Before the generators drew their choices independently of the
// RapidCheck size, five value writes (polygon_set_face_uint8 / _real64 /
// _real32, polygon_set_corner_real32 and, but for creases,
// polygon_set_face_uint32) were never generated and polygon_set_corner_real64
// never applied; and most polygon creates on layer 1 were rejected.
TEST(CommandGen, EveryCommandKindIsGeneratedAndAppliedOverThePropertyFoci) {
  std::array<int, kCommandKinds> sent{}, applied{};
  int base_creates = 0, base_created = 0;
  std::uint64_t seed = 0;
  for (const auto& property : property_catalog()) {
    for (int sequence = 0; sequence < 60; ++sequence) {
      Node model;
      const int size = sequence % 51;
      ++seed;
      for (int i = 0; i < 30; ++i) {
        const Command c =
            gen_command(model, property.focus)(rc::Random(seed * 1000 + static_cast<std::uint64_t>(i)), size).value();
        const bool ok = model.apply(c) == Reason::Ok;
        ++sent[c.index()];
        applied[c.index()] += ok;
        if (auto* p = std::get_if<cmd::PolygonSetCornerUint32>(&c); p && p->layer_id == 1 && p->v[0] != kNone32) {
          ++base_creates;
          base_created += ok;
        }
      }
    }
  }
  for (std::size_t k = 0; k < kCommandKinds; ++k) {
    const std::string name = print_command(command_of_kind(k));
    const std::string kind = name.substr(0, name.find(' '));
    std::printf("%-28s sent %5d applied %5d\n", kind.c_str(), sent[k], applied[k]);
    EXPECT_GE(applied[k], 50) << kind;
    EXPECT_GE(sent[k] - applied[k], 5) << kind << ": rejections are exercised too";
  }
  std::printf("polygon creates on layer 1: %d sent, %d applied\n", base_creates, base_created);
  EXPECT_GE(base_created * 2, base_creates);
}

}  // namespace
}  // namespace vgc
