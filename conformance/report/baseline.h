// baseline.h — known deviations, so a project's CI fails only on new ones.
//
// Spec: none (CI practice). Format, one entry per line:
//   # comment
//   CLAUSE-ID   why this deviation is accepted (required)
// An unknown clause id, a missing reason or a repeated id is an error that
// names the line and column and what to do; a baseline that cannot be read
// fails the run (exit 2).
#pragma once

#include <map>
#include <string>

namespace vgc {

struct Baseline {
  std::map<std::string, std::string> reasons;  // clause id -> why it is accepted
};

// Parses baseline text. On error returns false and sets *error to
// "<line>:<column>: <what>: <what to do>" (both 1-based).
bool parse_baseline(const std::string& text, Baseline* out, std::string* error);

// Reads and parses a file; errors name the file and line.
bool load_baseline(const std::string& path, Baseline* out, std::string* error);

}  // namespace vgc
