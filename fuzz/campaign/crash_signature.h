// crash_signature.h — how a fuzz campaign signs a crash from the output of
// re-running its input, so that one bug is one finding.
//
// Spec: docs/fuzzing.md "Running a campaign" (findings deduplicated by
// signature, named by clause); the FINDING line of fuzz/targets/clause_finding.h
// ("CLAUSE (LEVEL, status): ..."); clause ids of the catalog
// (conformance/clause.h).
//
// Rationale: the same bug reached with other ids, counts or values must
// group as one crash, so the grouping key folds every digit, clause ids
// included; the text the summary shows keeps clause ids exact
// (BONE-FOREST-1 stays BONE-FOREST-1). A finding named by clause is
// grouped by target, clause and status, not by its message; otherwise the
// sanitizer's error kind and first frame of ours, else UBSan's "runtime
// error", else "unknown".
#pragma once

#include <string>

namespace vgc::fuzz {

// `key` groups crashes (digits folded everywhere); `shown` is what the
// summary prints, the same text with clause ids exact.
struct CrashSignature {
  std::string key, shown;
};

CrashSignature crash_signature(const std::string& output);

// Digits folded to N, except inside clause ids, which stay exact.
std::string fold_digits_keep_clauses(const std::string& s);

// The status a finding line names ("CLAUSE (LEVEL, status): ..."), or "".
std::string status_of_finding(const std::string& line);

// The clause id a FINDING line names ("fuzz_x: [property: ]CLAUSE (LEVEL,
// status): ..."), if it is one of the catalog; "" otherwise.
std::string clause_of_finding(const std::string& finding_line);

}  // namespace vgc::fuzz
