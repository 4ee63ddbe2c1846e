// capability.h — the optional capabilities an implementation may claim
// (?capabilities, docs/adapters.md "Optional capabilities") and the checks
// that judge them.
//
// Spec: clauses MESH-CLASSIFY-1 ("manifold") and SUBD-CATMARK-1
// ("subdivision"), group "derived"; NORMALS-SPLIT-1 ("normals"),
// LOOP-TRIANGLE-1 ("loop"), EDIT-HIERARCHY-1 ("edits"), each its own group.
//
// Rationale: the checks compare with oracles (CGAL, OpenSubdiv), and the
// conformance layer must not depend on the oracle layer. So the oracle
// layer registers its checks here (oracles/capability_checks.h,
// register_capability_checks) and the runner looks them up by capability
// name. A claimed capability with no registered check cannot be judged:
// its properties are skipped ("no oracle linked") and the run is incomplete.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "finding.h"
#include "implementation.h"
#include "node.h"

namespace vgc {

struct CapabilityCheck {
  std::string capability;  // "manifold", "subdivision", "normals", "loop", "edits"
  // Compares the implementation (holding the state of `model`) with the
  // oracle; `variant` picks a sub-case (e.g. the subdivision level) and is
  // chosen by the runner from the case. nullopt when they agree.
  std::function<std::optional<Finding>(const Node& model, Implementation& sut, int variant)> check;
  // Optional; when set the runner calls it instead of `check`, with `draw`,
  // a value RapidCheck draws for the case (so it is deterministic from the
  // seed and shrinks towards 0), for checks that choose more than a variant
  // (the edit of "edits").
  std::function<std::optional<Finding>(const Node& model, Implementation& sut, int variant, std::uint32_t draw)>
      check_drawn;
};

// Adds or replaces the check for check.capability. Not thread-safe: call
// before running.
void register_capability_check(CapabilityCheck check);
// The registered check for `capability`, or nullptr.
const CapabilityCheck* find_capability_check(const std::string& capability);

// Asks sut "?capabilities" and returns the names it claims. Any failure or
// an "error ..." answer claims none. Never throws.
std::vector<std::string> query_capabilities(Implementation& sut);

}  // namespace vgc
