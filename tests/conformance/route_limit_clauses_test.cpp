// route_limit_clauses_test.cpp — the one table from a route's limits, said
// in the route's words, to the clauses each keeps from being judged
// (conformance/route_limit_clauses.h), and the Verse wire route's limits
// read through it.
//
// Spec: docs/adapters.md section 7 ("What the wire route can and cannot
// judge"); the clause catalog.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "clause.h"
#include "clause_status.h"
#include "route_limit_clauses.h"
#include "verse_implementation.h"

namespace vgc {
namespace {

constexpr RouteLimit kEveryLimit[] = {RouteLimit::NoVerdicts, RouteLimit::SubscriptionsUnseen,
                                      RouteLimit::NoRequests, RouteLimit::BoneRotationUnsent};

TEST(RouteLimitClauses, EveryLimitHidesClausesOfTheCatalog) {
  for (RouteLimit l : kEveryLimit) {
    const auto clauses = route_limit_clauses(l);
    EXPECT_FALSE(clauses.empty()) << static_cast<int>(l);
    for (std::string_view id : clauses) EXPECT_NE(find_clause(id), nullptr) << id;
  }
}

// The wire's limits name the clauses docs/adapters.md section 7 lists, and
// nothing the snapshot shows.
TEST(RouteLimitClauses, TheVerseWireCannotJudgeWhatItsLimitsHide) {
  const RouteLimits wire = verse_route_limits();
  std::set<std::string> hidden;
  for (const Clause& c : clause_catalog())
    if (!route_cannot_judge(c.id, wire).empty()) hidden.insert(std::string(c.id));
  EXPECT_EQ(hidden, (std::set<std::string>{"REASON-1", "LAYER-SUBSCRIBE-1", "MESH-CLASSIFY-1", "SUBD-CATMARK-1",
                                           "NORMALS-SPLIT-1", "LOOP-TRIANGLE-1", "EDIT-HIERARCHY-1"}));
  EXPECT_EQ(route_limit_of("REASON-1", wire),
            "not judgeable over the Verse wire: " + wire.cannot.at(RouteLimit::NoVerdicts));
  RouteLimits r6 = wire;
  r6.cannot[RouteLimit::BoneRotationUnsent] = "no rotation";
  EXPECT_EQ(route_limit_of("BONE-VALUE-1", r6), "not judgeable over the Verse wire: no rotation");
  EXPECT_EQ(route_limit_of("BONE-VALUE-1", wire), "");
  EXPECT_EQ(route_limit_of("VERTEX-SET-1", wire), "");
}

}  // namespace
}  // namespace vgc
