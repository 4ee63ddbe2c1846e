// merge_runs.h — the shards of one certify run (--shard I/N), read back from
// their report.json files, as one run: what `vgc merge` writes.
//
// Spec: none (CI practice: a sharded run has one verdict; docs/ci.md
// "Shards, and how their reports combine").
//
// Rationale: each property runs in exactly one shard, with the seed the
// unsharded run gives it, so the shards together hold every property's
// outcome. Per clause, the merge does what the runner does over the
// properties: the finding of the property that comes first in the catalog,
// exercised counts summed, unchecked when a shard that judged it could not.
// Shards of different seeds, cases, sizes, budgets, clause selections,
// strictness or implementations are refused, and so is a set with a shard
// missing or given twice. report.json keeps what report.html and summary.md
// need of a shard: the document an implementation showed for a finding
// (the picture is drawn from it), the rules used, the VGC_* environment of
// the replay commands. What it does not keep (per-property exercised
// counts) is not in the merged run either.
#pragma once

#include <string>
#include <vector>

#include "baseline.h"
#include "report.h"
#include "run_result.h"

namespace vgc {

struct MergedRun {
  RunResult run;
  Baseline baseline;      // rebuilt from the shards' baseline reasons
  bool has_baseline = false;
  bool strict = false;
  ReportContext ctx;      // implementation, re-run command (unsharded), started; run_dir unset
};

// Reads <dir>/report.json of every shard. On a refusal returns false and
// says why in *error (naming the missing shard, or the differing field).
bool merge_runs(const std::vector<std::string>& run_dirs, MergedRun* out, std::string* error);

}  // namespace vgc
