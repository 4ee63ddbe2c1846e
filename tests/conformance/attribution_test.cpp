// attribution_test.cpp — the clause a divergence is attributed to is the
// clause whose rule was broken (conformance/attribution.cpp).
//
// Spec clauses: POLY-TRIANGLE-1 (000 2.6: "if the three first references are
// valid and the fourth unused, the polygon is a triangle. If also the fourth
// reference is to a valid vertex, it is a quadrilateral"), CREASE-NAME-1,
// LAYER-NAME-1, BONE-NAME-1 (names of at most 15 bytes, docs/spec_facts.md).
//
// Each case runs check_step against a tiny faulty implementation: the
// reference, wrapped, misbehaving on one thing, as a real host could.
#include <gtest/gtest.h>

#include <functional>
#include <set>
#include <sstream>

#include "attribution.h"
#include "bone_pose.h"
#include "check_step.h"
#include "command_text.h"
#include "derived_document.h"
#include "derived_rule.h"
#include "document_diff.h"
#include "reference_implementation.h"
#include "reference_wrapper.h"
#include "rule_clauses.h"
#include "runner.h"
#include "../reference/test_util.h"  // test::C, one command from its text

namespace vgc {
namespace {

// The reference, except as the two hooks say.
class OneFault final : public test::ReferenceWrapper {
 public:
  // refuse(c): answer "rejected BAD_NAME" to c instead of applying it.
  std::function<bool(const Command&)> refuse = [](const Command&) { return false; };
  // edit_derived(node, text): the derived document as the faulty host prints it.
  std::function<std::string(const Node&, const std::string&)> edit_derived =
      [](const Node&, const std::string& t) { return t; };
  // edit_snapshot(text): the snapshot as the faulty host prints it.
  std::function<std::string(const std::string&)> edit_snapshot = [](const std::string& t) { return t; };

  std::string name() const override { return "one-fault"; }
  Answer apply(const Command& c) override {
    if (refuse(c)) {
      Answer a;
      a.reason = "BAD_NAME";
      return a;
    }
    return inner_.apply(c);
  }
  Document snapshot() override {
    Document d = inner_.snapshot();
    d.text = edit_snapshot(d.text);
    return d;
  }
  Document derived() override {
    Document d = inner_.derived();
    d.text = edit_derived(inner_.node(), d.text);
    return d;
  }
};

// Runs `lines` through check_step; returns the first failure's clause ("" if none).
std::string first_failure(Implementation& sut, const std::vector<std::string>& lines, std::string* message) {
  sut.reset();
  Node model;
  for (const auto& line : lines) {
    Node after;
    const StepResult r = check_step(model, test::C(line), sut, &after);
    if (r.failure) {
      *message = r.failure->message;
      return r.failure->clause;
    }
    model = after;
  }
  return "";
}

const std::vector<std::string> kFourVertices = {
    "vertex_set_xyz_real64 0 0 0 0 0", "vertex_set_xyz_real64 0 1 1 0 0", "vertex_set_xyz_real64 0 2 1 1 0",
    "vertex_set_xyz_real64 0 3 0 1 0"};

// A host that stores [1 2 3 0] as sent but reads a fourth corner of 0 as
// "unused": its derived document lists three edges for that quad.
TEST(Attribution, FourthCornerZeroReadAsTriangleIsPolyTriangle) {
  OneFault sut;
  sut.edit_derived = [](const Node& n, const std::string& text) {
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line)) {
      std::istringstream w(line);
      std::string kind;
      std::uint32_t polygon = 0, corner = 0;
      w >> kind >> polygon >> corner;
      if (kind == "edge_crease" && corner == 3 && n.polygons().count(polygon) &&
          n.polygons().at(polygon).u[3] == 0)
        continue;
      out += line + "\n";
    }
    return out;
  };
  for (const char* crease : {"", "crease_set_edge \"\" 7"}) {  // the constant 0 (initial) and another
    auto lines = kFourVertices;
    if (*crease) lines.push_back(crease);
    lines.push_back("polygon_set_corner_uint32 1 5 1 2 3 0");
    std::string message;
    EXPECT_EQ(first_failure(sut, lines, &message), "POLY-TRIANGLE-1") << message;
  }
}

// A host whose name limit is off by one: it refuses valid 15-byte names.
TEST(Attribution, ValidFifteenByteNameRefusedIsTheNameClause) {
  OneFault sut;
  const std::string n15 = "abcdefghijklmno";  // 15 bytes: the longest name allowed
  ASSERT_EQ(n15.size(), 15u);
  sut.refuse = [](const Command& c) {
    if (auto* x = std::get_if<cmd::CreaseSetVertex>(&c)) return x->layer.size() == 15;
    if (auto* x = std::get_if<cmd::CreaseSetEdge>(&c)) return x->layer.size() == 15;
    if (auto* x = std::get_if<cmd::LayerCreate>(&c)) return x->name.size() == 15;
    if (auto* x = std::get_if<cmd::BoneCreate>(&c))
      return x->weight.size() == 15 || x->reference.size() == 15 || x->pos_label.size() == 15 ||
             x->rot_label.size() == 15;
    return false;
  };
  std::string message;
  // Naming no layer (the constant applies), and naming a layer of the right type.
  EXPECT_EQ(first_failure(sut, {"crease_set_vertex \"" + n15 + "\" 7"}, &message), "CREASE-NAME-1") << message;
  EXPECT_EQ(first_failure(sut, {"crease_set_edge \"" + n15 + "\" 7"}, &message), "CREASE-NAME-1") << message;
  EXPECT_EQ(first_failure(sut, {"layer_create 2 \"abc\" VERTEX_UINT32 0 0", "crease_set_vertex \"" + n15 + "\" 7"},
                          &message),
            "CREASE-NAME-1")
      << message;
  // The same shape elsewhere: layer names, bone names.
  EXPECT_EQ(first_failure(sut, {"layer_create 2 \"" + n15 + "\" VERTEX_UINT32 0 0"}, &message), "LAYER-NAME-1")
      << message;
  EXPECT_EQ(first_failure(sut, {"layer_create 2 \"w\" VERTEX_REAL 0 0",
                                "bone_create 0 \"w\" \"\" 0xFFFF 0 0 0 \"" + n15 + "\" 0 0 0 1 \"\""},
                          &message),
            "BONE-NAME-1")
      << message;
}

// A host that keeps only 14 bytes of a 15-byte name (a 16-byte buffer
// whose last byte it spends on something else): the snapshot shows the
// shortened name, the rule broken is the name length.
TEST(Attribution, FifteenByteNameStoredShortenedIsTheNameClause) {
  OneFault sut;
  sut.edit_snapshot = [](const std::string& text) {
    std::string out = text;
    for (std::size_t at; (at = out.find("abcdefghijklmno")) != std::string::npos;) out.erase(at + 14, 1);
    return out;
  };
  const std::string n15 = "abcdefghijklmno";
  std::string message;
  EXPECT_EQ(first_failure(sut, {"crease_set_vertex \"" + n15 + "\" 7"}, &message), "CREASE-NAME-1") << message;
  EXPECT_EQ(first_failure(sut, {"crease_set_edge \"" + n15 + "\" 7"}, &message), "CREASE-NAME-1") << message;
  EXPECT_EQ(first_failure(sut, {"layer_create 2 \"" + n15 + "\" VERTEX_UINT32 0 0"}, &message), "LAYER-NAME-1")
      << message;
  EXPECT_EQ(first_failure(sut, {"layer_create 2 \"w\" VERTEX_REAL 0 0",
                                "bone_create 0 \"w\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"" + n15 + "\""},
                          &message),
            "BONE-NAME-1")
      << message;
}

// The attributions that were right stay so: a changed crease on the same
// edge is a crease clause, a shorter name refused is the command's own.
TEST(Attribution, SameEdgeDifferentCreaseAndShortNamesKeepTheirClauses) {
  OneFault sut;
  sut.edit_derived = [](const Node&, const std::string& text) {
    std::string out = text;
    const auto at = out.find("edge_crease 5 1 0\n");
    if (at != std::string::npos) out.replace(at, 18, "edge_crease 5 1 9\n");
    return out;
  };
  auto lines = kFourVertices;
  lines.push_back("polygon_set_corner_uint32 1 5 1 2 3 0");
  std::string message;
  EXPECT_EQ(first_failure(sut, lines, &message), "CREASE-INITIAL-1") << message;

  OneFault refusing;
  refusing.refuse = [](const Command& c) { return std::holds_alternative<cmd::CreaseSetVertex>(c); };
  EXPECT_EQ(first_failure(refusing, {"crease_set_vertex \"abc\" 7"}, &message), "CREASE-LAYER-MISSING-1")
      << message;
}

// Issue 17: a host that ignores the layer id asked for and creates the layer
// at the lowest free id (as r6 does) is blamed on layer.create
// (LAYER-CREATE-1), not on the name or the id pick, and the finding says
// where the layer went and where it was asked for.
TEST(Attribution, LayerCreatedAtAnotherIdNamesTheRuleAndBothLines) {
  OneFault sut;
  sut.edit_snapshot = [](const std::string& text) {
    std::string out = text;
    for (const std::string from : {"layer 3 ", "slot 3 "}) {
      const std::string to = from == "layer 3 " ? "layer 2 " : "slot 2 ";
      for (std::size_t at; (at = out.find(from)) != std::string::npos;) out.replace(at, from.size(), to);
    }
    return out;
  };
  std::string message;
  EXPECT_EQ(first_failure(sut, {"layer_create 3 \"abcdefghijklmno\" VERTEX_UINT32 0 0"}, &message), "LAYER-CREATE-1")
      << message;
  EXPECT_NE(message.find("rule layer.create (LAYER-CREATE-1, MUST)"), std::string::npos) << message;
  EXPECT_NE(message.find("created `layer 2` instead"), std::string::npos) << message;
  EXPECT_NE(message.find("the command asked for `layer 3`"), std::string::npos) << message;
}

// Issue 17: a host that resets a moved vertex's slots is blamed on the
// rule that keeps them (VERTEX-SET-1, MUST), not on the default it shows
// (LAYER-DEFAULT-1, SHOULD).
TEST(Attribution, MovedVertexSlotResetIsTheKeepRuleNotTheDefault) {
  OneFault sut;
  bool moved = false;
  sut.edit_snapshot = [&moved](const std::string& text) {
    std::string out = text;
    const auto at = out.find("slot 2 0 7\n");
    if (moved && at != std::string::npos) out.replace(at, 11, "slot 2 0 5\n");  // 5: the layer's default
    return out;
  };
  sut.refuse = [&moved](const Command& c) {
    if (auto* x = std::get_if<cmd::VertexSetXyzReal64>(&c); x && x->vertex_id == 0 && x->x == 9) moved = true;
    return false;
  };
  std::string message;
  EXPECT_EQ(first_failure(sut, {"vertex_set_xyz_real64 0 0 0 0 0", "layer_create 2 \"u\" VERTEX_UINT32 5 0",
                                "vertex_set_uint32 2 0 7", "vertex_set_xyz_real64 0 0 9 9 9"},
                          &message),
            "VERTEX-SET-1")
      << message;
  EXPECT_NE(message.find("vertex.move.keeps_slots"), std::string::npos) << message;
  EXPECT_NE(message.find("\"slot 2 0 7\""), std::string::npos) << message;
  EXPECT_NE(message.find("\"slot 2 0 5\""), std::string::npos) << message;
}

// Issue 27: a host that keeps the "pick a free id" sentinel as the id
// (layer_create 0xFFFF stored as layer 65535, bone_create 0xFFFF as bone
// 65535) made no pick: it is blamed on the create rule (MUST), not on the
// reading of which free id to pick (LAYER-ID-PICK-1, IMPLEMENTATION-DEFINED;
// BONE-ID-PICK-1, SHOULD), where it was blamed before.
TEST(Attribution, AnElementKeptAtThePickSentinelIsTheCreateRule) {
  OneFault sut;
  sut.edit_snapshot = [](const std::string& text) {
    std::string out = text;
    for (const std::string from : {"layer 2 ", "bone 0 "}) {
      const std::string to = from == "layer 2 " ? "layer 0xFFFF " : "bone 0xFFFF ";  // as snapshots print them
      if (const auto at = out.find(from); at != std::string::npos) out.replace(at, from.size(), to);
    }
    return out;
  };
  std::string message;
  EXPECT_EQ(first_failure(sut, {"layer_create 0xFFFF \"a\" VERTEX_UINT32 0 0"}, &message), "LAYER-CREATE-1")
      << message;
  EXPECT_NE(message.find("rule layer.create (LAYER-CREATE-1, MUST)"), std::string::npos) << message;
  EXPECT_NE(message.find("kept the \"pick a free id\" sentinel"), std::string::npos) << message;
  EXPECT_EQ(message.find("LAYER-ID-PICK-1"), std::string::npos) << message;

  sut.edit_snapshot = [](const std::string& text) {
    std::string out = text;
    if (const auto at = out.find("bone 0 "); at != std::string::npos) out.replace(at, 7, "bone 0xFFFF ");
    return out;
  };
  EXPECT_EQ(first_failure(sut,
                          {"layer_create 2 \"w\" VERTEX_REAL 0 0",
                           "bone_create 0xFFFF \"w\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\""},
                          &message),
            "BONE-CREATE-1")
      << message;
  EXPECT_NE(message.find("rule bone.create (BONE-CREATE-1, MUST)"), std::string::npos) << message;
  EXPECT_EQ(message.find("BONE-ID-PICK-1"), std::string::npos) << message;
}

// Issue 29: a fresh node that differs from the model's is blamed through
// the rule that placed the line, node.base_layers (LAYER-BASE-1) or
// node.initial_creases (CREASE-INITIAL-1), not by the words of the message
// (which blamed a base layer renamed "crease" on the initial creases).
// Checked as `vgc replay` checks a fresh node before a program (the
// runner's check_fresh) and by check_fresh_state itself.
TEST(Attribution, AFreshNodeIsBlamedOnTheFreshNodeRuleOfItsLine) {
  const auto replace = [](std::string from, std::string to) {
    return [from, to](const std::string& text) {
      std::string out = text;
      if (const auto at = out.find(from); at != std::string::npos) out.replace(at, from.size(), to);
      return out;
    };
  };
  struct Case {
    const char* what;
    std::function<std::string(const std::string&)> edit_snapshot;
    std::function<std::string(const Node&, const std::string&)> edit_derived;
    Rule rule;
    const char* clause;
  };
  const auto same = [](const Node&, const std::string& t) { return t; };
  const std::vector<Case> cases = {
      {"no crease_edge line", replace("crease_edge \"\" 0\n", ""), same, Rule::InitialCreases, "CREASE-INITIAL-1"},
      {"vertex creases 3", replace("crease_vertex \"\" 0", "crease_vertex \"\" 3"), same, Rule::InitialCreases,
       "CREASE-INITIAL-1"},
      {"no layer 1", replace("layer 1 \"polygon\" POLYGON_CORNER_UINT32 - - -\n", ""), same, Rule::BaseLayers,
       "LAYER-BASE-1"},
      {"layer 0 named crease", replace("\"vertex\"", "\"crease\""), same, Rule::BaseLayers, "LAYER-BASE-1"},
      {"a layer more", replace("crease_vertex", "layer 2 \"crease\" VERTEX_UINT32 - - -\ncrease_vertex"), same,
       Rule::BaseLayers, "LAYER-BASE-1"},
      {"an effective crease on a fresh node", [](const std::string& t) { return t; },
       [](const Node&, const std::string& t) {
         std::string out = t;
         out.insert(out.find("end"), "vertex_crease 0 0\n");
         return out;
       },
       Rule::InitialCreases, "CREASE-INITIAL-1"},
  };
  for (const Case& c : cases) {
    OneFault sut;
    sut.edit_snapshot = c.edit_snapshot;
    sut.edit_derived = c.edit_derived;
    const ReplayResult replayed = replay_program(Program{}, sut);
    ASSERT_TRUE(replayed.failure) << c.what;
    EXPECT_EQ(replayed.failure->clause, c.clause) << c.what << ": " << replayed.failure->message;
    EXPECT_EQ(replayed.failure->rules, std::vector<Rule>{c.rule}) << c.what << ": " << replayed.failure->message;
    EXPECT_NE(replayed.failure->message.find("Blamed on rule " + std::string(rule_name(c.rule))), std::string::npos)
        << c.what << ": " << replayed.failure->message;
    sut.reset();
    const std::optional<Finding> f = check_fresh_state(sut);
    ASSERT_TRUE(f) << c.what;
    EXPECT_EQ(f->message, replayed.failure->message) << c.what;
  }
  OneFault reference;
  EXPECT_FALSE(replay_program(Program{}, reference).failure);
}

// Issue 29, item 4: the derived document's rules (derived_rule.h) are
// named once, in enum order, each with a clause of the catalog.
TEST(Attribution, EveryDerivedRuleHasANameAndAClauseInTheCatalog) {
  std::set<std::string_view> names;
  for (std::size_t i = 1; i < kDerivedRuleCount; ++i) {
    const DerivedRule r = static_cast<DerivedRule>(i);
    EXPECT_EQ(derived_rule_info(r).rule, r) << i;
    EXPECT_TRUE(names.insert(derived_rule_name(r)).second) << derived_rule_name(r);
    EXPECT_EQ(derived_rule_name(r).rfind("derived.", 0), 0u) << derived_rule_name(r);  // apart from the node's
    DerivedRule back = DerivedRule::None;
    EXPECT_TRUE(parse_derived_rule_name(derived_rule_name(r), &back) && back == r) << derived_rule_name(r);
    EXPECT_NE(find_clause(derived_rule_clause(r)), nullptr) << derived_rule_name(r);
    EXPECT_EQ(rule_name_clause(derived_rule_name(r)), derived_rule_clause(r)) << derived_rule_name(r);
  }
  EXPECT_EQ(derived_only_clauses(), (std::vector<std::string_view>{"BONE-PARENT-1", "BONE-DOWNSTREAM-1"}));
}

// Every line of the derived document is decided by the rule the reference
// took to compute it, by provenance: the fresh node's crease setting is
// derived.*.initial, a crease_set with the same constant 0 is
// derived.*.constant; a named layer resolves when read (missing, created,
// re-typed); a bone with parent 0xFFFF, with a parent that names no bone,
// with a live parent; a pose line for an id with no bone.
TEST(Attribution, EveryDerivedLineIsDecidedByANamedRule) {
  Node n;
  for (const char* line : {"vertex_set_xyz_real64 0 0 0 0 0", "vertex_set_xyz_real64 0 1 1 0 0",
                           "vertex_set_xyz_real64 0 2 1 1 0", "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF"})
    ASSERT_EQ(n.apply(test::C(line)), Reason::Ok) << line;
  const auto rules_of = [](const Node& node, const char* kind) {
    std::set<DerivedRule> out;
    for (const auto& l : split_lines(print_derived(node)))
      if (l.rfind(kind, 0) == 0) out.insert(derived_rule_of(node, l));
    return out;
  };
  using S = std::set<DerivedRule>;
  EXPECT_EQ(rules_of(n, "vertex_crease"), S{DerivedRule::VertexCreaseInitial});
  EXPECT_EQ(rules_of(n, "edge_crease"), S{DerivedRule::EdgeCreaseInitial});
  const auto then = [&n](const char* line) {
    EXPECT_EQ(n.apply(test::C(line)), Reason::Ok) << line;
    return n;
  };
  EXPECT_EQ(rules_of(then("crease_set_vertex \"\" 0"), "vertex_crease"), S{DerivedRule::VertexCreaseConstant});
  EXPECT_EQ(rules_of(n, "edge_crease"), S{DerivedRule::EdgeCreaseInitial});
  EXPECT_EQ(rules_of(then("crease_set_edge \"\" 0"), "edge_crease"), S{DerivedRule::EdgeCreaseConstant});
  EXPECT_EQ(rules_of(then("crease_set_vertex \"cv\" 5"), "vertex_crease"), S{DerivedRule::VertexCreaseLayerMissing});
  EXPECT_EQ(rules_of(then("layer_create 2 \"cv\" VERTEX_UINT32 0 0"), "vertex_crease"),
            S{DerivedRule::VertexCreaseLayer});
  EXPECT_EQ(rules_of(then("layer_create 2 \"cv\" VERTEX_REAL 0 0"), "vertex_crease"),
            S{DerivedRule::VertexCreaseLayerMissing});
  EXPECT_EQ(rules_of(then("crease_set_edge \"ce\" 5"), "edge_crease"), S{DerivedRule::EdgeCreaseLayerMissing});
  EXPECT_EQ(rules_of(then("layer_create 3 \"ce\" POLYGON_CORNER_UINT32 0 0"), "edge_crease"),
            S{DerivedRule::EdgeCreaseLayer});
  then("bone_create 0 \"cv\" \"\" 0xFFFF 0 0 0 \"\" 0 0 0 1 \"\"");
  then("bone_create 1 \"cv\" \"\" 0 1 0 0 \"\" 0 0 0 1 \"\"");
  then("bone_create 2 \"cv\" \"\" 77 1 0 0 \"\" 0 0 0 1 \"\"");
  EXPECT_EQ(derived_rule_of(n, "bone_pose 0"), DerivedRule::BonePoseRoot);
  EXPECT_EQ(derived_rule_of(n, "bone_pose 1 1 0 0 0 0 0 1"), DerivedRule::BonePoseChained);
  EXPECT_EQ(derived_rule_of(n, "bone_pose 2"), DerivedRule::BonePoseParentMissing);
  EXPECT_EQ(derived_rule_of(n, "bone_pose 3"), DerivedRule::BonePosePerBone);
  EXPECT_EQ(derived_rule_of(n, "bone_pose x"), DerivedRule::BonePosePerBone);
  EXPECT_EQ(derived_rule_of(n, "end"), DerivedRule::None);
  for (const auto& [id, pose] : bone_world_poses(n)) EXPECT_EQ(pose.rule, bone_pose_rule(n, id)) << id;
  then("bone_destroy 0");  // bone 1's parent is gone: a root now
  EXPECT_EQ(derived_rule_of(n, "bone_pose 1"), DerivedRule::BonePoseParentMissing);
}

// A derived difference is blamed on the rule that decided the model's line,
// and the finding names it. The constant 0 sent by crease_set_vertex is the
// command's constant (CREASE-DEFAULT-1, MUST), not the fresh node's crease
// (CREASE-INITIAL-1, IMPLEMENTATION-DEFINED), which the old shape-based
// attribution took it for (it looked at the value 0).
TEST(Attribution, ADerivedDifferenceIsBlamedOnTheDerivedRuleThatDecidedIt) {
  OneFault sut;
  sut.edit_derived = [](const Node&, const std::string& text) {
    std::string out = text;
    for (const char* from : {"vertex_crease 2 0\n", "vertex_crease 2 5\n"})
      if (const auto at = out.find(from); at != std::string::npos) out.replace(at, 18, "vertex_crease 2 9\n");
    return out;
  };
  struct Case {
    std::vector<std::string> before;
    const char* clause;
    DerivedRule rule;
  };
  const std::vector<Case> cases = {
      {{}, "CREASE-INITIAL-1", DerivedRule::VertexCreaseInitial},
      {{"crease_set_vertex \"\" 0"}, "CREASE-DEFAULT-1", DerivedRule::VertexCreaseConstant},
      {{"crease_set_vertex \"cv\" 0"}, "CREASE-LAYER-MISSING-1", DerivedRule::VertexCreaseLayerMissing},
      {{"layer_create 2 \"cv\" VERTEX_UINT32 5 0", "crease_set_vertex \"cv\" 0"}, "CREASE-VERTEX-LAYER-1",
       DerivedRule::VertexCreaseLayer},
  };
  for (const Case& c : cases) {
    auto lines = c.before;
    lines.insert(lines.end(), kFourVertices.begin(), kFourVertices.end());
    std::string message;
    EXPECT_EQ(first_failure(sut, lines, &message), c.clause) << message;
    EXPECT_NE(message.find("Blamed on derived rule " + std::string(derived_rule_name(c.rule)) + " ("),
              std::string::npos)
        << message;
  }
  // blame_derived itself: a polygon's edges listed otherwise are its corner
  // count (derived.edge_crease.per_corner), a pose of an id with no bone is
  // derived.bone_pose.per_bone.
  Node n;
  for (const auto& line : kFourVertices) ASSERT_EQ(n.apply(test::C(line)), Reason::Ok);
  ASSERT_EQ(n.apply(test::C("polygon_set_corner_uint32 1 5 1 2 3 0")), Reason::Ok);
  DocumentDifference d{"edge_crease 5 3 0", "", "edge_crease"};
  EXPECT_EQ(blame_derived(n, d).rule, DerivedRule::EdgePerCorner);
  EXPECT_EQ(blame_derived(n, d).clause, "POLY-TRIANGLE-1");
  d = DocumentDifference{"edge_crease 5 3 0", "edge_crease 5 3 4", "edge_crease"};
  EXPECT_EQ(blame_derived(n, d).rule, DerivedRule::EdgeCreaseInitial);
  d = DocumentDifference{"", "bone_pose 4 0 0 0 0 0 0 1", "bone_pose"};
  EXPECT_EQ(blame_derived(n, d).rule, DerivedRule::BonePosePerBone);
  EXPECT_EQ(blame_derived(n, d).clause, "BONE-DOWNSTREAM-1");
}

}  // namespace
}  // namespace vgc
