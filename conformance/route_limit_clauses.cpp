// route_limit_clauses.cpp — see route_limit_clauses.h.
#include "route_limit_clauses.h"

#include <algorithm>

#include "property.h"

namespace vgc {

std::vector<std::string_view> route_limit_clauses(RouteLimit limit) {
  switch (limit) {
    case RouteLimit::NoVerdicts: return {"REASON-1"};
    case RouteLimit::SubscriptionsUnseen: return {"LAYER-SUBSCRIBE-1"};
    case RouteLimit::NoRequests: {
      // The clauses of the properties of an optional capability: each is
      // judged only through its request.
      std::vector<std::string_view> out;
      for (const PropertySpec& p : property_catalog()) {
        if (p.capability.empty()) continue;
        for (std::string_view c : p.clauses)
          if (std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
      }
      return out;
    }
    case RouteLimit::BoneRotationUnsent: return {"BONE-VALUE-1"};
  }
  return {};
}

std::string route_cannot_judge(std::string_view clause_id, const RouteLimits& limits) {
  for (const auto& [limit, why] : limits.cannot) {
    const std::vector<std::string_view> hidden = route_limit_clauses(limit);
    if (std::find(hidden.begin(), hidden.end(), clause_id) != hidden.end()) return why;
  }
  if (auto it = limits.clauses.find(std::string(clause_id)); it != limits.clauses.end()) return it->second;
  return "";
}

}  // namespace vgc
