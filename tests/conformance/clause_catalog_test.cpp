// clause_catalog_test.cpp — the clause catalog is well formed and closed:
// ids are unique and spelled UPPER-WORDS-N, every clause is declared by a
// property, every clause a property declares exists, and every id the
// attribution functions (attribution.h) can return — for every command
// kind, every reason, every snapshot and derived line kind, on several node
// states — is in the catalog. A clause id that is not in the catalog would
// be a finding no report could explain and no baseline could name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <set>
#include <sstream>
#include <type_traits>
#include <utility>

#include "attribution.h"
#include "rule_clauses.h"
#include "clause.h"
#include "command_fields.h"
#include "command_text.h"
#include "faulty_node.h"
#include "property.h"

namespace vgc {
namespace {

const std::regex& id_pattern() {
  // Upper-case words joined by '-', the last one a number: "LAYER-BASE-1", "REAL-32BIT-1".
  static const std::regex re("^[A-Z][A-Z0-9]*(-[A-Z0-9]+)*-[1-9][0-9]*$");
  return re;
}

TEST(ClauseCatalog, IdsAreUniqueAndWellFormed) {
  const auto& catalog = clause_catalog();
  ASSERT_GE(catalog.size(), 30u);
  std::set<std::string_view> seen;
  const std::set<std::string_view> groups = {"layers", "vertices", "polygons", "creases", "bones", "commands",
                                                 "derived", "normals", "loop", "edits"};
  for (const Clause& c : catalog) {
    EXPECT_TRUE(std::regex_match(std::string(c.id), id_pattern())) << "malformed id '" << c.id << "'";
    EXPECT_TRUE(seen.insert(c.id).second) << "duplicate id " << c.id;
    EXPECT_TRUE(groups.count(c.group)) << c.id << ": unknown group '" << c.group << "'";
    EXPECT_FALSE(c.source.empty()) << c.id;
    EXPECT_FALSE(c.text.empty()) << c.id;
    EXPECT_FALSE(c.reading.empty()) << c.id;
    EXPECT_EQ(find_clause(c.id), &c) << c.id;
  }
  EXPECT_EQ(find_clause("NO-SUCH-CLAUSE-1"), nullptr);
  EXPECT_EQ(find_clause(""), nullptr);
}

TEST(ClauseCatalog, EveryClauseIsDeclaredByAProperty) {
  for (const Clause& c : clause_catalog()) {
    int declared = 0;
    for (const PropertySpec& p : property_catalog())
      for (auto id : p.clauses) declared += id == c.id;
    EXPECT_GE(declared, 1) << c.id << " is declared by no property, so no run can ever pass it";
  }
}

TEST(ClauseCatalog, EveryDeclaredClauseExistsAndPropertiesAreDistinct) {
  std::set<std::string_view> property_ids;
  for (const PropertySpec& p : property_catalog()) {
    EXPECT_TRUE(property_ids.insert(p.id).second) << "duplicate property " << p.id;
    EXPECT_EQ(find_property(p.id), &p);
    EXPECT_FALSE(p.clauses.empty()) << p.id;
    std::set<std::string_view> own;
    for (auto id : p.clauses) {
      EXPECT_NE(find_clause(id), nullptr) << p.id << " declares unknown clause " << id;
      EXPECT_TRUE(own.insert(id).second) << p.id << " declares " << id << " twice";
    }
  }
  EXPECT_EQ(find_property("no.such.property"), nullptr);
}

// Every clause id spelled as a string literal in the conformance sources
// (check_step.cpp, runner.cpp, ... and the seeded faults) is in the catalog.
TEST(ClauseCatalog, EveryClauseIdLiteralInTheSourcesExists) {
  namespace fs = std::filesystem;
  const fs::path root = VGC_SOURCE_DIR;
  std::vector<fs::path> files;
  for (const auto& dir : {root / "conformance", root / "conformance" / "report", root / "tests" / "conformance" / "faults"})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".cpp" && e.path().filename() != "clause_catalog.cpp") files.push_back(e.path());
  ASSERT_GE(files.size(), 5u);
  const std::regex literal("\"([A-Z][A-Z0-9]*(-[A-Z0-9]+)*-[1-9][0-9]*)\"");
  const std::set<std::string> not_clauses = {"UTF-8"};  // other upper-case literals of that shape
  int found = 0;
  for (const auto& f : files) {
    std::ifstream in(f);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    for (std::sregex_iterator it(text.begin(), text.end(), literal), end; it != end; ++it) {
      if (not_clauses.count((*it)[1].str())) continue;
      ++found;
      EXPECT_NE(find_clause((*it)[1].str()), nullptr) << f.filename() << " names unknown clause " << (*it)[1];
    }
  }
  EXPECT_GE(found, 60);  // rule_clauses.cpp alone has dozens
  for (const auto& fault : faults::fault_catalog())
    if (!fault.expected_clause.empty()) {
      EXPECT_NE(find_clause(fault.expected_clause), nullptr) << "fault " << fault.name;
    }
}

// Levels follow the spec's words (issue "Certify to the end", item 5): MUST
// only where 000 2.6 or a README wire fact makes it a rule; SHOULD where the
// text says "typically"; IMPLEMENTATION-DEFINED where it is silent, and then
// the reading says it is the suite's.
TEST(ClauseCatalog, LevelsFollowTheSpecsWords) {
  const std::vector<std::pair<std::string_view, ClauseLevel>> expected = {
      // "This slot is typically initialized with a default value"
      {"LAYER-DEFAULT-1", ClauseLevel::Should},
      // "Bones are typically numbered from zero and upwards ... kept tight"
      {"BONE-ID-PICK-1", ClauseLevel::Should},
      // "asks the host to pick a free id": which one is not said
      {"LAYER-ID-PICK-1", ClauseLevel::ImplementationDefined},
      {"VERTEX-ID-PICK-1", ClauseLevel::ImplementationDefined},
      // the r6 host's behaviour is "one implementation-defined profile, not the rule"
      {"POLY-DISTINCT-1", ClauseLevel::ImplementationDefined},
      // the text says what a VERTEX_UINT32 reference layer does, nothing about another
      {"BONE-REFERENCE-1", ClauseLevel::ImplementationDefined},
      // rules of the text or the wire facts
      {"LAYER-BASE-1", ClauseLevel::Must},
      {"POLY-CORNERS-1", ClauseLevel::Must},
      {"POLY-VERTEX-REF-1", ClauseLevel::Must},
      {"VERTEX-DELETE-1", ClauseLevel::Must},
      {"LAYER-SUBSCRIBE-1", ClauseLevel::Must},
      {"ATOMIC-1", ClauseLevel::Must},  // "a command is applied ... or dropped silently"
      {"REASON-1", ClauseLevel::Should},
  };
  for (const auto& [id, level] : expected) {
    const Clause* c = find_clause(id);
    ASSERT_NE(c, nullptr) << id;
    EXPECT_EQ(clause_level_name(c->level), clause_level_name(level)) << id;
  }
  for (const Clause& c : clause_catalog()) {
    const std::string reading(c.reading);
    if (c.level == ClauseLevel::ImplementationDefined && c.group != "derived") {
      EXPECT_NE(reading.find("suite's reading"), std::string::npos)
          << c.id << ": an IMPLEMENTATION-DEFINED clause says that its reading is the suite's";
    }
    if (c.level == ClauseLevel::Should && c.id != "REASON-1") {
      EXPECT_NE(std::string(c.text).find("typically"), std::string::npos) << c.id << ": SHOULD, but no \"typically\"";
    }
  }
}

// ---- attribution ------------------------------------------------------------

template <std::size_t... I> std::vector<Command> one_of_each(std::index_sequence<I...>) {
  return {Command(std::in_place_index<I>)...};
}

// Sets every field of every command kind from one "profile" of values: ids
// at their edges (0, small, live, large, 0xFFFF / 0xFFFFFFFF), names empty,
// short, naming live layers and too long, floats normal and special.
struct FieldFiller {
  int profile;
  template <class T> void operator()(const char* name, T& field, FieldHint hint) const {
    using U = std::decay_t<T>;
    const std::string n = name;
    if constexpr (std::is_same_v<U, std::string>) {
      static const char* names[] = {"", "vu", "pc", "vr", "nolayer", "a name too long for it", "w"};
      field = names[profile % 7];
    } else if constexpr (std::is_same_v<U, float> || std::is_same_v<U, double>) {
      const U values[] = {U(0), U(1.5), std::numeric_limits<U>::max(), std::numeric_limits<U>::quiet_NaN(),
                          std::numeric_limits<U>::infinity(), U(-0.0), U(-2)};
      field = values[profile % 7];
    } else if constexpr (std::is_integral_v<U>) {
      if (hint == FieldHint::LayerType) {
        const std::uint8_t types[] = {0, 1, 2, 128, 129, 130, 131, 132, 3, 200};
        field = static_cast<U>(types[profile % 10]);
      } else if (hint == FieldHint::RealFormat) {
        field = static_cast<U>(profile % 3);
      } else if (n == "layer_id") {
        const std::uint32_t ids[] = {0, 1, 2, 3, 5, 7, 0xFFFF, 9, 400};
        field = static_cast<U>(ids[profile % 9]);
      } else {
        const std::uint32_t ids[] = {0, 3, 1u << 24, 0xFFFFFFFEu, 0xFFFFFFFFu, 7, 4000000000u, 1, 2};
        field = static_cast<U>(ids[profile % 9]);  // uint16 fields see 0, 3, 0, 0xFFFE, 0xFFFF, ...
      }
    } else {  // std::array
      for (std::size_t i = 0; i < field.size(); ++i) {
        using E = typename U::value_type;
        if constexpr (std::is_integral_v<E>) {
          const std::uint32_t corner_sets[][4] = {{0, 1, 2, 3}, {0, 1, 2, 0xFFFFFFFFu}, {0xFFFFFFFFu, 1, 2, 3},
                                                  {0, 0, 1, 2}, {0, 0xFFFFFFFFu, 2, 3}, {0, 1, 99, 3},
                                                  {4, 5, 6, 7}, {1u << 24, 1, 2, 3}};
          field[i] = corner_sets[profile % 8][i];
        } else {
          const E values[] = {E(0), E(1), std::numeric_limits<E>::quiet_NaN(), E(0.5),
                              std::numeric_limits<E>::max(), E(-3), E(0)};
          field[i] = values[(static_cast<std::size_t>(profile) + i) % 7];
        }
      }
    }
  }
};

std::vector<Command> commands_to_attribute() {
  std::vector<Command> out;
  const auto defaults = one_of_each(std::make_index_sequence<kCommandKinds>{});
  for (const Command& d : defaults) {
    out.push_back(d);
    for (int profile = 0; profile < 12; ++profile) {
      Command c = d;
      std::visit([&](auto& x) { visit_fields(x, FieldFiller{profile}); }, c);
      out.push_back(c);
    }
  }
  // The wire's overloaded forms and the "pick an id" values, spelled out.
  out.push_back(cmd::LayerCreate{5, "", 1, 0, 0});                        // = layer_destroy
  out.push_back(cmd::LayerCreate{0xFFFF, "picked", 2, 7, 0.5});           // pick a layer id
  out.push_back(cmd::LayerCreate{0, "vertex", 0, 0, 0});                  // base layer
  out.push_back(cmd::LayerCreate{1, "polygon", 128, 0, 0});
  out.push_back(cmd::LayerCreate{2, "vu", 2, 0, 0});                      // re-type a live layer
  for (int axis = 0; axis < 3; ++axis) {
    cmd::VertexSetXyzReal32 f{0, 1, 0, 0, 0};
    cmd::VertexSetXyzReal64 d{0, 1, 0, 0, 0};
    (axis == 0 ? f.x : axis == 1 ? f.y : f.z) = FLT_MAX;                 // = vertex_delete
    (axis == 0 ? d.x : axis == 1 ? d.y : d.z) = DBL_MAX;
    out.push_back(f);
    out.push_back(d);
    f.layer_id = 4, d.layer_id = 4;                                      // on another XYZ layer
    out.push_back(f);
    out.push_back(d);
  }
  out.push_back(cmd::VertexSetXyzReal64{0, 0xFFFFFFFFu, 1, 2, 3});        // pick a vertex id
  out.push_back(cmd::VertexSetXyzReal32{0, 0xFFFFFFFFu, 1, 2, 3});
  out.push_back(cmd::VertexSetXyzReal64{0, 4000000000u, 1, 2, 3});        // large id
  out.push_back(cmd::VertexSetXyzReal64{0, 3, std::nan(""), 0, 0});       // not a position
  out.push_back(cmd::PolygonSetCornerUint32{1, 0, {kNone32, 0, 0, 0}});   // = polygon_delete
  out.push_back(cmd::PolygonSetCornerUint32{1, kNone32, {0, 1, 2, 3}});   // pick a polygon id
  out.push_back(cmd::PolygonSetCornerUint32{1, 1u << 24, {0, 1, 2, kNone32}});
  out.push_back(cmd::PolygonSetCornerUint32{5, 0, {1, 2, 3, 4}});         // a crease layer write
  out.push_back(cmd::CreaseSetVertex{"", 0xFFFFFFFFu});
  out.push_back(cmd::CreaseSetEdge{"pc", 0});
  out.push_back(cmd::BoneCreate{0xFFFF, "vr", "", 0, {1, 2, 3}, "", {0, 0, 0, 1}, ""});  // pick a bone id
  out.push_back(cmd::BoneCreate{0, "", "", 0, {}, "", {0, 0, 0, 1}, ""});                // = bone_destroy
  out.push_back(cmd::BoneCreate{0, "vr", "", 2, {}, "", {0, 0, 0, 1}, ""});              // closes a cycle
  out.push_back(cmd::BoneCreate{1, "vr", "", 1, {}, "", {0, 0, 0, 1}, ""});              // its own parent
  out.push_back(cmd::BoneCreate{9, "vr", "vu", 0xFFFF, {}, "", {0, 0, 0, 0}, ""});       // zero rotation
  out.push_back(cmd::BoneDestroy{0xFFFF});
  return out;
}

Node must_build(const std::vector<Command>& commands) {
  Node n;
  for (const Command& c : commands) {
    const Reason r = n.apply(c);
    EXPECT_EQ(r, Reason::Ok) << "setup command rejected: " << print_command(c) << " (" << reason_name(r) << ")";
  }
  return n;
}

std::vector<Command> cube() {
  std::vector<Command> out;
  const double p[8][3] = {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, {-1, -1, -1}};
  for (std::uint32_t v = 0; v < 8; ++v) out.push_back(cmd::VertexSetXyzReal64{0, v, p[v][0], p[v][1], p[v][2]});
  const std::uint32_t q[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {3, 2, 5, 4}, {2, 1, 6, 5}, {1, 0, 7, 6}, {0, 3, 4, 7}};
  for (std::uint32_t f = 0; f < 6; ++f) out.push_back(cmd::PolygonSetCornerUint32{1, f, {q[f][0], q[f][1], q[f][2], q[f][3]}});
  return out;
}

// Node states the attribution sees: fresh; the cube with constant creases;
// every layer type, crease layers named, a bone chain and an orphan; crease
// names that resolve to no layer or a wrong-typed one, and very large ids.
std::vector<Node> node_states() {
  std::vector<Node> states;
  states.push_back(Node{});
  auto c = cube();
  c.push_back(cmd::CreaseSetVertex{"", 0xFFFFFFFFu});
  c.push_back(cmd::CreaseSetEdge{"", 0xFFFFFFFFu});
  states.push_back(must_build(c));

  auto rich = cube();
  const std::pair<const char*, std::uint8_t> layers[] = {{"vu", 1},  {"vr", 2},   {"vx", 0},   {"pc", 128},
                                                         {"pcr", 129}, {"pf8", 130}, {"pf32", 131}, {"pfr", 132}};
  std::uint16_t id = 2;
  for (const auto& [name, type] : layers) rich.push_back(cmd::LayerCreate{id++, name, type, 3, 0.25});
  rich.push_back(cmd::VertexSetUint32{2, 1, 17});
  rich.push_back(cmd::PolygonSetCornerUint32{5, 0, {1, 2, 3, 4}});
  rich.push_back(cmd::CreaseSetVertex{"vu", 0});
  rich.push_back(cmd::CreaseSetEdge{"pc", 5});
  rich.push_back(cmd::BoneCreate{0, "vr", "vu", 0xFFFF, {1, 0, 0}, "", {0, 0, 0, 1}, ""});
  rich.push_back(cmd::BoneCreate{1, "vr", "", 0, {0, 1, 0}, "px", {0, 0, 0.7071067811865476, 0.7071067811865476}, ""});
  rich.push_back(cmd::BoneCreate{2, "vu", "", 1, {0, 0, 2}, "", {0, 0, 0, 1}, "rx"});
  rich.push_back(cmd::BoneCreate{3, "vr", "", 77, {5, 5, 5}, "", {1, 0, 0, 0}, ""});  // parent missing: a root
  rich.push_back(cmd::LayerSubscribe{3, 1});
  states.push_back(must_build(rich));

  auto odd = rich;
  odd.push_back(cmd::CreaseSetVertex{"vr", 4});       // wrong type: the constant applies
  odd.push_back(cmd::CreaseSetEdge{"nolayer", 3});    // names no layer
  odd.push_back(cmd::VertexSetXyzReal64{0, 4000000000u, 0, 0, 9});
  odd.push_back(cmd::PolygonSetCornerUint32{1, 1u << 24, {4000000000u, 1, 2, kNone32}});
  odd.push_back(cmd::LayerDestroy{2});               // bone 0's reference layer is gone
  states.push_back(must_build(odd));
  return states;
}

// Every rule of the node has a name, a table entry in enum order, and a
// clause in the catalog; every clause a rule maps to lists that rule.
TEST(Attribution, EveryRuleHasOneClauseInTheCatalog) {
  std::set<std::string_view> names;
  std::set<std::string> clauses;
  for (std::size_t i = 1; i < kRuleCount; ++i) {
    const Rule r = static_cast<Rule>(i);
    EXPECT_EQ(static_cast<std::size_t>(rule_info(r).rule), i) << "rule table out of enum order at " << i;
    EXPECT_TRUE(names.insert(rule_name(r)).second) << "duplicate rule name " << rule_name(r);
    Rule back = Rule::None;
    EXPECT_TRUE(parse_rule_name(rule_name(r), &back) && back == r) << rule_name(r);
    EXPECT_NE(find_clause(rule_clause(r)), nullptr) << rule_name(r) << " maps to " << rule_clause(r);
    const auto listed = rules_of_clause(rule_clause(r));
    EXPECT_NE(std::find(listed.begin(), listed.end(), r), listed.end());
    clauses.insert(std::string(rule_clause(r)));
  }
  // The rules spread over most of the catalog's node clauses.
  EXPECT_GE(clauses.size(), 40u);
}

// Applying any command to any state records at least one rule; a refusal
// records its deciding guard first, whose reason is the verdict (then any
// other guard that also refuses it), and the atomic
// rule; every blame names a catalog clause.
TEST(Attribution, EveryCommandRecordsItsRules) {
  const auto commands = commands_to_attribute();
  const auto states = node_states();
  std::set<std::size_t> kinds;
  std::set<std::string> returned;
  for (const Node& before : states) {
    for (const Command& c : commands) {
      kinds.insert(c.index());
      const std::string text = print_command(c);
      Node after = before;
      RuleTrace trace;
      const Reason verdict = after.apply(c, &trace);
      ASSERT_GT(trace.count, 0) << text;
      int guards = 0;
      for (Rule r : trace)
        if (rule_info(r).role == RuleRole::Guard) {
          // The first guard decides the verdict; later ones also refuse it.
          if (++guards == 1) {
            EXPECT_TRUE(rule_info(r).reason == verdict ||
                        (r == Rule::WriteNoSuchElement && verdict == Reason::NoSuchPolygon))
                << text << ": guard " << rule_name(r) << " with verdict " << reason_name(verdict);
          }
        }
      EXPECT_EQ(guards > 0, verdict != Reason::Ok) << text;
      EXPECT_EQ(trace.has(Rule::RejectedChangesNothing), verdict != Reason::Ok) << text;
      const Blame b = blame_verdict(c, verdict, trace);
      EXPECT_NE(find_clause(b.clause), nullptr) << text << " blamed on '" << b.clause << "'";
      returned.insert(b.clause);
    }
  }
  EXPECT_EQ(kinds.size(), kCommandKinds) << "not every command kind was attributed";
  EXPECT_GE(returned.size(), 30u);
}

// A few blames checked against the rule they must name (the same
// situations node.cpp decides), so that "exists" is not met by a
// function that answers one valid id for everything.
TEST(Attribution, NamesTheRuleOfTheSituation) {
  const auto states = node_states();
  const Node& rich = states[2];
  const auto verdict_blame = [&](const Node& state, const Command& c) {
    Node n = state;
    RuleTrace t;
    const Reason r = n.apply(c, &t);
    return blame_verdict(c, r, t);
  };
  const cmd::BoneCreate cycle{0, "vr", "", 2, {}, "", {0, 0, 0, 1}, ""};
  EXPECT_EQ(verdict_blame(rich, cycle).clause, "BONE-FOREST-1");
  // Refusing to delete a used vertex breaks the delete itself (MUST), not
  // only the cascade (IMPLEMENTATION-DEFINED), which is named too.
  const Blame used = verdict_blame(rich, cmd::VertexDelete{1});
  EXPECT_EQ(used.clause, "VERTEX-DELETE-1");
  EXPECT_NE(std::find(used.rules.begin(), used.rules.end(), Rule::PolygonCascadeDelete), used.rules.end());
  EXPECT_EQ(verdict_blame(rich, cmd::VertexSetXyzReal64{0, 4000000000u, 1, 1, 1}).clause, "ID-BOUND-1");
  EXPECT_EQ(verdict_blame(rich, cmd::PolygonSetCornerUint32{1, 9, {0, 0, 1, 2}}).clause, "POLY-DISTINCT-1");
  EXPECT_EQ(verdict_blame(rich, cmd::LayerCreate{2, "abcdefghijklmno", 1, 0, 0}).clause, "LAYER-NAME-1");
  EXPECT_EQ(clause_for_derived(rich, "edge_crease", -1), "CREASE-EDGE-LAYER-1");
  EXPECT_EQ(clause_for_derived(states[0], "vertex_crease", -1), "CREASE-INITIAL-1");
  EXPECT_EQ(clause_for_derived(states[3], "edge_crease", -1), "CREASE-LAYER-MISSING-1");
  EXPECT_EQ(clause_for_derived(rich, "bone_pose", 3), "BONE-PARENT-1");
  EXPECT_EQ(clause_for_derived(rich, "bone_pose", 2), "BONE-DOWNSTREAM-1");
}

}  // namespace
}  // namespace vgc
