// clause.h — the clause catalog: every normative statement the suite judges.
//
// Spec: 000 section 2.6 and the protocol facts of docs/spec_facts.md.
//
// Rationale: a verdict is only useful if it says which sentence of the spec
// an implementation broke. Each clause has a stable id (never reused, never
// renumbered), a level, the spec text it comes from, and — where the text
// is silent — the suite's reading and the latitude an implementation has.
// Properties name the clauses they check (property.h); a failure is always
// attributed to exactly one clause (attribution.h). `vgc clauses` prints
// this catalog; docs/clauses.md is generated from it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace vgc {

enum class ClauseLevel {
  Must,                   // a failure makes the implementation non-conformant
  Should,                 // a failure is reported, the verdict stays conformant
  ImplementationDefined,  // the spec leaves it open; the suite's reading is checked,
                          // within the latitude the clause states
};
std::string_view clause_level_name(ClauseLevel level);  // "MUST", "SHOULD", "IMPLEMENTATION-DEFINED"

struct Clause {
  std::string_view id;       // "LAYER-BASE-1"
  std::string_view group;    // "layers", "vertices", "polygons", "creases", "bones", "commands"
  ClauseLevel level;
  std::string_view source;   // "000 2.6.1" or "README (r6 protocol)"
  std::string_view text;     // the spec sentence, quoted
  std::string_view reading;  // what the suite checks; for silent or open points, why and the latitude
};

// All clauses, in catalog order (by group, then id).
const std::vector<Clause>& clause_catalog();
// The clause with `id`, or nullptr.
const Clause* find_clause(std::string_view id);

}  // namespace vgc
