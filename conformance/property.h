// property.h — the conformance properties: what each one explores and which
// clauses it declares.
//
// Spec: the clause catalog (clause.h).
//
// Rationale: a property is a RapidCheck state machine in the manner of
// rc::state::Command: the reference node is the model (Step::apply), the
// implementation under test is the system (Step::run, which compares the
// two through check_step), and Step::show prints the command line of our
// language, so a shrunk counterexample is a command file. Properties differ
// only in the focus of their command generator (command_gen.h) and in the
// clauses they declare; any divergence they find is attributed to the
// clause it breaks, even one they do not declare.
#pragma once

#include <string_view>
#include <vector>

#include "command_gen.h"

namespace vgc {

struct PropertySpec {
  std::string_view id;     // "layers.stateful"
  std::string_view title;  // one line for reports
  Focus focus;
  std::vector<std::string_view> clauses;  // the clauses this property is meant to check
  // Empty for the core properties. Otherwise an optional capability
  // (capability.h): the property runs only when the implementation claims
  // it, with a quarter of the cases, and after each case's commands calls
  // the registered check for it on the final state.
  std::string_view capability = {};
  // A property at scale (scale_mesh.h): each case builds and edits a mesh of
  // 10^4 to 10^5 elements instead of drawing commands from the focus, and
  // the property runs a fiftieth of the cases (at least 2).
  bool at_scale = false;
  // What a default run of it costs, in seconds of the reference behind
  // exec: on this project's 2-core machine (one default run at seed 1, at
  // load 10-17, rounded): how `--shard` balances the shards (shard_plan.cpp
  // assign_shards; docs/ci.md "Shards"). Only the ratios matter; the
  // balance itself is checked by judged commands per shard
  // (tests/ci/verse_shards_test.sh).
  double cost = 1.0;
};

// How many cases a property runs when the run asks for `cases` per property:
// all of them, a quarter for a capability (at least 1), a fiftieth at
// scale (at least 2).
int property_cases(const PropertySpec& spec, int cases);

// Every property, in run order.
const std::vector<PropertySpec>& property_catalog();
const PropertySpec* find_property(std::string_view id);

}  // namespace vgc
