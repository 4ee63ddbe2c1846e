// route_limit_clauses.h — which clauses of the catalog each limit of a
// route keeps from being judged.
//
// Spec: the clause catalog (clause.h); the routes' limits
// (implementation.h RouteLimit; docs/adapters.md section 7, "What the wire
// route can and cannot judge").
//
// Rationale: an adapter says what its route does not carry in the route's
// own words (no verdicts, no subscription state, no requests, a bone form
// without rotation); this table is the one place where such a limit meets
// the clauses it hides, as rule_clauses.h is where a rule of the node meets
// its clause. Every limit maps to its clauses in a switch (the compiler
// flags a limit left out). The clauses only the derived document decides
// (a route that carries none, RouteLimits::derived) are
// attribution.h's derived_only_clauses.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "implementation.h"

namespace vgc {

// The clauses `limit` keeps from being judged; every id is in the catalog
// (a test checks).
std::vector<std::string_view> route_limit_clauses(RouteLimit limit);

// Why the route of `limits` cannot judge `clause_id` at all, "" when it
// can: a clause one of its limits hides (the limit's why), or one the
// route names itself (RouteLimits::clauses). Not the derived document's
// clauses: route_limit_of (clause_status.h) adds those.
std::string route_cannot_judge(std::string_view clause_id, const RouteLimits& limits);

}  // namespace vgc
