// clause_status_test.cpp — decide_clause_status and its evidence
// (conformance/clause_status.h), and the costly classes
// (conformance/costly_class.h). Expected values are written by hand from
// docs/certify.md "Clause statuses"; each was seen failing against the
// ladder as it was before issue 31 (a derived-only clause unchecked when no
// case reached it; a shard's property the route cannot run making its
// clauses unchecked).
#include <gtest/gtest.h>

#include "clause_status.h"
#include "costly_class.h"
#include "property.h"

namespace vgc {
namespace {

RouteLimits wire() {
  RouteLimits l;
  l.route = "the Verse wire";
  l.derived = false;
  l.why_no_derived = "the wire carries no derived document";
  l.clauses["REASON-1"] = "a host acknowledges nothing";
  return l;
}

const Clause& clause(const char* id) {
  const Clause* c = find_clause(id);
  EXPECT_NE(c, nullptr) << id;
  return *c;
}

TEST(ClauseStatus, WhatTheRouteCannotJudgeIsNotApplicableWhateverTheCasesDrew) {
  // BONE-DOWNSTREAM-1 is decided by the derived document alone: on a route
  // with none it is not-applicable at a seed whose cases reached it and at
  // one whose cases did not (it was unchecked at seeds 2 and 4 on r6).
  for (long reached : {0L, 7L}) {
    ClauseEvidence e;
    e.route = "the Verse wire";
    e.route_limit = route_limit_of("BONE-DOWNSTREAM-1", wire());
    e.declared_and_ran = true;
    e.derived_only = reached;
    const ClauseDecision d = decide_clause_status(clause("BONE-DOWNSTREAM-1"), e);
    EXPECT_EQ(d.status, ClauseStatus::NotApplicable) << reached;
    EXPECT_NE(d.note.find("derived document"), std::string::npos) << d.note;
  }
  EXPECT_EQ(route_limit_of("BONE-DOWNSTREAM-1", RouteLimits{}), "");  // in process: judged
  EXPECT_NE(route_limit_of("REASON-1", wire()), "");                  // named by the route
  EXPECT_EQ(route_limit_of("VERTEX-SET-1", wire()), "");              // the snapshot shows it
}

TEST(ClauseStatus, APropertyTheRouteCannotRunDoesNotMakeItsClausesUnchecked) {
  ClauseEvidence e;
  e.route = "the Verse wire";
  e.skip = PropertySkip::NotOnRoute;
  e.skip_note = "not run on the Verse wire";
  EXPECT_EQ(decide_clause_status(clause("CREASE-EDGE-LAYER-1"), e).status, ClauseStatus::NotApplicable);
  // Another declaring property runs in another shard: judged there.
  std::vector<PropertyOutcome> outcomes;
  for (const PropertySpec& spec : property_catalog()) {
    PropertyOutcome o;
    o.id = std::string(spec.id);
    o.status = PropertyStatus::Skipped;
    if (spec.at_scale) o.skip = PropertySkip::NotOnRoute, o.note = "not run on the Verse wire";
    else o.skip = PropertySkip::OtherShard, o.note = "in shard 1/2";
    outcomes.push_back(o);
  }
  ClauseEvidence g;
  std::vector<std::string> ran;
  gather_clause_evidence(clause("CREASE-EDGE-LAYER-1"), outcomes, &g, &ran);
  EXPECT_EQ(g.skip, PropertySkip::OtherShard);
  EXPECT_EQ(decide_clause_status(clause("CREASE-EDGE-LAYER-1"), g).status, ClauseStatus::Skipped);
  EXPECT_TRUE(ran.empty());
}

TEST(ClauseStatus, NoReachIsUncheckedInARunAndLeftToTheMergeInAShard) {
  ClauseEvidence e;
  e.declared_and_ran = true;
  EXPECT_EQ(decide_clause_status(clause("LAYER-NAME-2"), e).status, ClauseStatus::Unchecked);
  e.shard_part = true;
  EXPECT_EQ(decide_clause_status(clause("LAYER-NAME-2"), e).status, ClauseStatus::Skipped);
  e.exercised = 3;
  EXPECT_EQ(decide_clause_status(clause("LAYER-NAME-2"), e).status, ClauseStatus::Pass);
}

TEST(ClauseStatus, AFindingDecidesAndAStoppedPropertyLeavesItUnchecked) {
  ClauseEvidence e;
  e.declared_and_ran = true;
  e.exercised = 10;
  e.stopped_note = "its property layers.stateful stopped: the budget ran out";
  EXPECT_EQ(decide_clause_status(clause("LAYER-NAME-1"), e).status, ClauseStatus::Unchecked);
  e.finding = Finding("LAYER-NAME-1", FindingStatus::Crash, "crash");
  EXPECT_EQ(decide_clause_status(clause("LAYER-NAME-1"), e).status, ClauseStatus::Crash);
  ClauseEvidence off;
  off.selected = false;
  EXPECT_FALSE(decide_clause_status(clause("LAYER-NAME-1"), off).status.has_value());  // left out
}

TEST(ClauseStatus, TheWorstKindThenTheShortestProgramWinsTiesToTheEarlierProperty) {
  const Program two({cmd::VertexDelete{1}, cmd::VertexDelete{2}});
  const Program one({cmd::VertexDelete{1}});
  const Finding wrong("X", FindingStatus::Fail, "x");
  const Finding crash("X", FindingStatus::Crash, "crash while applying it");
  const std::optional<Finding> chosen = wrong;
  EXPECT_TRUE(prefer_finding(wrong, one, 5, chosen, two, 1));
  EXPECT_FALSE(prefer_finding(wrong, two, 0, chosen, one, 5));
  EXPECT_TRUE(prefer_finding(wrong, one, 0, chosen, one, 5));
  EXPECT_FALSE(prefer_finding(wrong, one, 5, chosen, one, 0));
  EXPECT_TRUE(prefer_finding(wrong, two, 9, std::nullopt, one, 0));
  // A crash is never hidden behind a wrong answer of the same clause,
  // however much longer its program.
  EXPECT_TRUE(prefer_finding(crash, two, 9, chosen, one, 0));
  EXPECT_FALSE(prefer_finding(wrong, one, 0, std::optional<Finding>(crash), two, 9));
}

TEST(CostlyClass, TheClassIsTheLargestElementIdsKindAndPowerOfTwo) {
  cmd::VertexSetXyzReal64 v;
  v.vertex_id = 4194304 + 17;
  auto k = costly_class_of(Command{v});
  ASSERT_TRUE(k);
  EXPECT_EQ(k->kind, ElementKind::Vertex);
  EXPECT_EQ(k->floor, 4194304u);
  EXPECT_EQ(describe_costly_class(*k), "vertex ids of 2^22 (4194304) or more");
  v.vertex_id = kNone32;  // "pick one" is no id
  EXPECT_FALSE(costly_class_of(Command{v}));
  v.vertex_id = 200;  // below 2^8: no class
  EXPECT_FALSE(costly_class_of(Command{v}));
  cmd::PolygonSetCornerUint32 p;
  p.layer_id = 1;
  p.polygon_id = 3;
  p.v = {1, 2, 1u << 30, kNone32};  // a corner is a vertex id
  k = costly_class_of(Command{p});
  ASSERT_TRUE(k);
  EXPECT_EQ(k->kind, ElementKind::Vertex);
  EXPECT_EQ(k->floor, 1u << 30);
  const std::vector<CostlyClass> avoided = {{ElementKind::Vertex, 4194304u}};
  EXPECT_TRUE(in_costly_class(Command{p}, avoided));
  p.v = {1, 2, 3, kNone32};
  EXPECT_FALSE(in_costly_class(Command{p}, avoided));
  p.layer_id = 5;  // on another layer the corners are values, not vertex ids
  p.v = {1u << 30, 0, 0, 0};
  EXPECT_FALSE(in_costly_class(Command{p}, avoided));
  cmd::PolygonDelete d;
  d.polygon_id = 1u << 28;  // a polygon id is another kind
  EXPECT_FALSE(in_costly_class(Command{d}, avoided));
}

}  // namespace
}  // namespace vgc
