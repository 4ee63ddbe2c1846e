// default_run.h — the options of the certification runs tests make in
// process: a default `vgc certify` run, and smaller runs of the same kind.
//
// Spec: none (test support). Every run here has a budget no load can use
// up (3600 CPU seconds): a test must give the same verdict on a busy
// machine, and CTest's TIMEOUT guards a hang (docs/ci.md "On a loaded
// machine").
#pragma once

#include <cstdint>
#include <string>

#include "runner.h"

namespace vgc {

// `cases` cases a property, command sequences up to `max_size` long, at
// `seed`, of the clauses `glob` selects (RunOptions::clause_glob).
inline RunOptions unhurried_run(std::uint64_t seed, int cases, int max_size = 40, const std::string& glob = "*") {
  RunOptions o;
  o.seed = seed;
  o.cases = cases;
  o.max_size = max_size;
  o.clause_glob = glob;
  o.budget_seconds = 3600;
  return o;
}

// A default `vgc certify` run: 200 cases of size up to 50.
inline RunOptions default_run(std::uint64_t seed, const std::string& glob = "*") {
  return unhurried_run(seed, 200, 50, glob);
}

}  // namespace vgc
