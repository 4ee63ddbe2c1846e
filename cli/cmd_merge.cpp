// cmd_merge.cpp — `vgc merge RUN_DIR... [--reports DIR]`: the shards of one
// certify run (--shard I/N) as one run directory, with the verdict,
// summary.md, report.json, report.html and junit.xml of the unsharded run
// (merge_runs.h). The last job of a CI matrix runs it.
//
// Exit codes: those of `vgc certify` for the merged verdict (0 conformant,
// 1 not conformant, 2 incomplete), and 2 when the shards are refused
// (different runs, a shard missing or given twice) or nothing can be written.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "merge_runs.h"
#include "report.h"
#include "subcommand.h"
#include "terminal_text.h"
#include "verdict.h"

namespace vgc::cli {
namespace {

struct MergeOptions {
  std::vector<std::string> run_dirs;
  std::string reports = "reports";
};

int run_merge(const MergeOptions& o) {
  MergedRun m;
  std::string error;
  if (!merge_runs(o.run_dirs, &m, &error)) {
    say(stderr, "vgc merge: {}\n", error);
    return 2;
  }
  if (m.has_baseline) m.ctx.baseline = &m.baseline;
  const Verdict verdict = judge(m.run, m.has_baseline ? &m.baseline : nullptr, m.strict);
  if (!claim_run_dir(o.reports, m.run, &m.ctx, &error) || !write_report(o.reports, m.run, verdict, m.ctx, &error)) {
    say(stderr, "vgc merge: {}: no report was written\n", error);
    return 2;
  }
  say("{}: {} ({} shards merged)\n", m.ctx.implementation_spec, verdict.name, o.run_dirs.size());
  for (const auto& co : m.run.clauses)  // the finding lines certify prints (CI annotations read them)
    if (co.finding && std::find(verdict.new_failures.begin(), verdict.new_failures.end(), co.clause->id) !=
                          verdict.new_failures.end())
      say("  {:<8} {:<24} {}\n", clause_status_name(co.status), co.clause->id, co.finding->message);
  for (const auto& id : verdict.unchecked) say("  unchecked {}\n", id);
  say("report: {}/summary.md\n", m.ctx.run_dir);
  return verdict.exit_code;
}

void add_merge(CLI::App& app, int* exit_code) {
  auto o = std::make_shared<MergeOptions>();
  auto* sub = app.add_subcommand("merge", "Merge the run directories of a sharded certify run into one run");
  sub->add_option("run_dirs", o->run_dirs, "The run directory of every shard (--shard I/N, I = 1..N)")->required();
  sub->add_option("--reports", o->reports, "Directory for the merged run's reports")->capture_default_str();
  sub->callback([o, exit_code] { *exit_code = run_merge(*o); });
}

const Subcommand kMerge{add_merge};

}  // namespace
}  // namespace vgc::cli
