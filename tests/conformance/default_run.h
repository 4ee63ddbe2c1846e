// default_run.h — the options of a default `vgc certify` run for tests that
// certify in process.
//
// Spec: none (test support). A default run is 200 cases of size up to 50
// at `seed`, of the clauses `glob` selects, with no budget that load could
// cut short (CTest's TIMEOUT guards a hang; docs/ci.md "On a loaded
// machine").
#pragma once

#include <cstdint>
#include <string>

#include "runner.h"

namespace vgc {

inline RunOptions default_run(std::uint64_t seed, const std::string& glob = "*") {
  RunOptions o;
  o.seed = seed;
  o.cases = 200;
  o.max_size = 50;
  o.clause_glob = glob;
  o.budget_seconds = 3600;
  return o;
}

}  // namespace vgc
