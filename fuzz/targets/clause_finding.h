// clause_finding.h — a conformance finding as the one line a fuzz target
// reports (finding.h).
//
// Spec: the clause catalog (conformance/clause.h).
//
// Rationale: the differential and property targets name every divergence
// by its clause, in one form that `vgc fuzz` groups by (campaign.h reads
// the clause id back from it): "CLAUSE (LEVEL, status): message".
#pragma once

#include <string>

#include "finding.h"
#include "clause.h"

namespace vgc::fuzz {

inline std::string describe_clause_finding(const Finding& f) {
  const Clause* clause = find_clause(f.clause);
  return f.clause + " (" + std::string(clause ? clause_level_name(clause->level) : "?") + ", " +
         finding_status_name(f.status) + "): " + f.message;
}

}  // namespace vgc::fuzz
