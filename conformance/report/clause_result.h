// clause_result.h — one clause's result, read back from a run directory's
// report.json: what `vgc result RUN_DIR CLAUSE` prints, and the exit code a
// per-clause CTest test (vgc_add_certification) passes or fails on.
//
// Spec: none (CI practice: per-clause test history; docs/ci.md).
//
// Rationale: one certify run judges every clause; a CI wants one test per
// clause so that `ctest -R LAYER-NAME-1` and per-clause history work. The
// run writes report.json once; each clause's test only reads it. The exit
// code follows the verdict's rules: only a gating finding (the run's
// new_failures) fails a clause, an unchecked clause is incomplete, a clause
// the run did not select or another shard ran is skipped.
#pragma once

#include <string>

namespace vgc {

struct ClauseResult {
  // 0 pass (or a finding that does not gate: SHOULD, a profile difference,
  // a known deviation; not-applicable, not-claimed), 1 a gating finding,
  // 2 unchecked or the report cannot be read, 77 not judged in this run
  // (not selected, another shard): CTest's SKIP_RETURN_CODE.
  int exit_code = 2;
  std::string text;  // what to print: status, message, replay command
};

ClauseResult clause_result(const std::string& run_dir, const std::string& clause_id);

}  // namespace vgc
