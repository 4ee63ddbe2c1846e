// implementation_choice_test.cpp — the model follows a free id the
// implementation picked (implementation_choice.h): one note at the id
// clause, no divergence on later commands, and anything else still judged.
//
// Spec: README "asks the host to pick a free id" (LAYER-ID-PICK-1,
// VERTEX-ID-PICK-1, BONE-ID-PICK-1).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "check_step.h"
#include "command_text.h"
#include "derived_document.h"
#include "implementation_choice.h"
#include "reference_implementation.h"
#include "reference_wrapper.h"
#include "../reference/test_util.h"  // test::C, one command from its text
#include "runner.h"
#include "snapshot.h"

namespace vgc {
namespace {

using test::C;

Node state(const std::vector<std::string>& lines) {
  Node n;
  for (const auto& l : lines) EXPECT_EQ(reason_name(n.apply(C(l))), "OK") << l;
  return n;
}

TEST(ImplementationChoice, AnotherFreeIdIsFollowedWithANote) {
  const Node before = state({"layer_create 2 \"a\" VERTEX_REAL 0 1", "vertex_set_xyz_real64 0 0 0 0 0",
                             "vertex_set_xyz_real64 0 1 1 0 0", "vertex_set_xyz_real64 0 2 0 1 0",
                             "bone_create 0 \"a\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\""});
  struct Case {
    std::string pick, explicit_form, clause;
  };
  const Case cases[] = {
      {"layer_create 0xFFFF \"b\" POLYGON_FACE_REAL 0 2", "layer_create 40 \"b\" POLYGON_FACE_REAL 0 2",
       "LAYER-ID-PICK-1"},
      {"vertex_set_xyz_real64 0 0xFFFFFFFF 5 5 5", "vertex_set_xyz_real64 0 4000000000 5 5 5", "VERTEX-ID-PICK-1"},
      {"vertex_set_xyz_real32 0 0xFFFFFFFF 5 5 5", "vertex_set_xyz_real32 0 9 5 5 5", "VERTEX-ID-PICK-1"},
      {"polygon_set_corner_uint32 1 0xFFFFFFFF 0 1 2 0xFFFFFFFF", "polygon_set_corner_uint32 1 7 0 1 2 0xFFFFFFFF",
       "VERTEX-ID-PICK-1"},
      {"bone_create 0xFFFF \"a\" \"\" 0 1 2 3 \"\" 0 0 0 1 \"\"", "bone_create 0xFFFE \"a\" \"\" 0 1 2 3 \"\" 0 0 0 1 \"\"",
       "BONE-ID-PICK-1"},
  };
  for (const Case& k : cases) {
    Node impl = before;
    ASSERT_EQ(impl.apply(C(k.explicit_form)), Reason::Ok) << k.explicit_form;
    const auto followed = follow_implementation_choice(before, C(k.pick), print_snapshot(impl));
    ASSERT_TRUE(followed) << k.pick;
    EXPECT_EQ(print_snapshot(followed->model), print_snapshot(impl)) << k.pick;
    EXPECT_EQ(print_derived(followed->model), print_derived(impl)) << k.pick;
    EXPECT_EQ(followed->note.clause, k.clause);
    EXPECT_NE(followed->note.message.find("the suite's reading picks the lowest free id"), std::string::npos);
  }
}

TEST(ImplementationChoice, AnythingElseIsNotAChoice) {
  const Node before = state({"layer_create 2 \"a\" VERTEX_REAL 0 1", "vertex_set_xyz_real64 0 0 0 0 0"});
  auto follows = [&](const std::string& pick, const std::vector<std::string>& impl_lines) {
    Node impl = before;
    for (const auto& l : impl_lines) impl.apply(C(l));
    return follow_implementation_choice(before, C(pick), print_snapshot(impl)).has_value();
  };
  // the same id, something else wrong: judged as usual
  EXPECT_FALSE(follows("layer_create 0xFFFF \"b\" VERTEX_REAL 0 2", {"layer_create 3 \"b\" VERTEX_REAL 0 3"}));
  // another id and a wrong default
  EXPECT_FALSE(follows("layer_create 0xFFFF \"b\" VERTEX_REAL 0 2", {"layer_create 9 \"b\" VERTEX_REAL 0 3"}));
  // an id that was not free: the existing layer 2 overwritten
  EXPECT_FALSE(follows("layer_create 0xFFFF \"b\" VERTEX_REAL 0 2", {"layer_create 2 \"b\" VERTEX_REAL 0 2"}));
  // two new elements
  EXPECT_FALSE(follows("vertex_set_xyz_real64 0 0xFFFFFFFF 1 1 1",
                       {"vertex_set_xyz_real64 0 5 1 1 1", "vertex_set_xyz_real64 0 6 1 1 1"}));
  // not a pick: an explicit id, or the delete alias
  EXPECT_FALSE(follows("vertex_set_xyz_real64 0 3 1 1 1", {"vertex_set_xyz_real64 0 5 1 1 1"}));
  EXPECT_FALSE(follows("layer_create 4 \"b\" VERTEX_REAL 0 2", {"layer_create 5 \"b\" VERTEX_REAL 0 2"}));
  EXPECT_FALSE(follows("vertex_set_xyz_real64 0 0xFFFFFFFF 1.7976931348623157e+308 1 1", {"vertex_delete 0"}));
}

// The reference, except that every layer, vertex and polygon id it is asked
// to pick is the highest free one instead of the lowest: within the spec.
class PicksHighest final : public test::ReferenceWrapper {
 public:
  std::string name() const override { return "picks-highest"; }
  Answer apply(const Command& c) override {
    const Node& n = inner_.node();
    Command x = c;
    if (auto* l = std::get_if<cmd::LayerCreate>(&x); l && l->layer_id == kNone16 && !l->name.empty()) {
      std::uint16_t id = 0xFFFE;
      while (id > 2 && n.layers().count(id)) --id;
      l->layer_id = id;
    }
    if (auto* v = std::get_if<cmd::VertexSetXyzReal64>(&x); v && v->layer_id == 0 && v->vertex_id == kNone32) {
      std::uint32_t id = 0xFFFFFFFE;
      while (n.vertices().count(id)) --id;
      v->vertex_id = id;
    }
    if (auto* p = std::get_if<cmd::PolygonSetCornerUint32>(&x);
        p && p->layer_id == 1 && p->polygon_id == kNone32 && p->v[0] != kNone32) {
      std::uint32_t id = 0xFFFFFFFE;
      while (n.polygons().count(id)) --id;
      p->polygon_id = id;
    }
    return inner_.apply(x);
  }
};

TEST(ImplementationChoice, LaterCommandsOnThePickedIdAgree) {
  PicksHighest sut;
  ASSERT_EQ(sut.reset().status, CallStatus::Ok);
  Node model;
  std::vector<Finding> notes;
  for (const char* line : {"layer_create 0xFFFF \"w\" VERTEX_UINT32 3 0", "vertex_set_xyz_real64 0 0xFFFFFFFF 1 2 3",
                           "vertex_set_uint32 0xFFFE 0xFFFFFFFE 9", "layer_destroy 0xFFFE", "vertex_delete 0xFFFFFFFE"}) {
    Node after;
    const StepResult r = check_step(model, C(line), sut, &after, /*follow_choices=*/true);
    ASSERT_FALSE(r.failure) << line << ": " << r.failure->clause << ": " << r.failure->message;
    for (const auto& n : r.notes) notes.push_back(n);
    model = after;
  }
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(notes[0].clause, "LAYER-ID-PICK-1");
  EXPECT_EQ(notes[1].clause, "VERTEX-ID-PICK-1");
}

// A program that picks ids and then works on the picked elements, checked
// step by step from the model check_step returns: notes at the id clauses
// only. Without follow_choices the first different pick is a failure at its
// id clause, as before (what run_certification and replay_program do until
// they start each step from the model check_step returned).
const std::vector<std::string> kProgram = {
    "layer_create 0xFFFF \"w\" VERTEX_UINT32 3 0", "layer_create 0xFFFF \"c\" POLYGON_CORNER_UINT32 7 0",
    "vertex_set_xyz_real64 0 0xFFFFFFFF 0 0 0", "vertex_set_xyz_real64 0 0xFFFFFFFF 1 0 0",
    "vertex_set_xyz_real64 0 0xFFFFFFFF 0 1 0",
    "polygon_set_corner_uint32 1 0xFFFFFFFF 0xFFFFFFFE 0xFFFFFFFD 0xFFFFFFFC 0xFFFFFFFF",
    "crease_set_edge \"c\" 0", "polygon_set_corner_uint32 0xFFFD 0xFFFFFFFE 1 2 3 4",
    "vertex_set_uint32 0xFFFE 0xFFFFFFFD 9", "layer_create 0xFFFE \"w\" VERTEX_UINT32 4 0",
    "vertex_delete 0xFFFFFFFE", "layer_destroy 0xFFFD"};

TEST(ImplementationChoice, AProgramOnPickedIdsChecksWithOnlyIdNotes) {
  PicksHighest sut;
  ASSERT_EQ(sut.reset().status, CallStatus::Ok);
  Node model;
  std::vector<Finding> notes;
  for (const std::string& line : kProgram) {
    Node after;
    const StepResult r = check_step(model, C(line), sut, &after, true);
    ASSERT_FALSE(r.failure) << line << ": " << r.failure->clause << ": " << r.failure->message;
    for (const auto& n : r.notes) notes.push_back(n);
    model = after;
  }
  std::set<std::string> clauses;
  for (const Finding& n : notes) clauses.insert(n.clause);
  EXPECT_EQ(clauses, (std::set<std::string>{"LAYER-ID-PICK-1", "VERTEX-ID-PICK-1"}));
  EXPECT_EQ(notes.size(), 6u);  // two layers, three vertices, one polygon
}

TEST(ImplementationChoice, WithoutFollowingADifferentPickIsAFailureAtItsIdClause) {
  PicksHighest sut;
  ASSERT_EQ(sut.reset().status, CallStatus::Ok);
  Node after;
  const StepResult r = check_step(Node{}, C(kProgram[0]), sut, &after);
  ASSERT_TRUE(r.failure);
  EXPECT_EQ(r.failure->clause, "LAYER-ID-PICK-1");
}

}  // namespace
}  // namespace vgc
