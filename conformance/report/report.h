// report.h — what `vgc certify` writes: report.json, junit.xml, summary.md,
// report.html, one replayable counterexample command file per failing
// clause, and the final mesh of each counterexample that holds one (OBJ).
//
// Spec: none (CI practice); docs/certify.md "What a run writes"
// describes every file and field.
//
// Rationale: CI reads the JSON and the JUnit XML; a person reads the
// summary first, at 2 a.m., so it starts with the verdict, then each
// failure with its clause, the spec sentence, what was expected and seen,
// the shrunk command file inline, and the one line that replays it. A run
// directory is written under a temporary name and renamed into place, so
// it is whole or absent; reports/latest then points at it.
#pragma once

#include <optional>
#include <string>

#include "baseline.h"
#include "run_result.h"
#include "verdict.h"

namespace vgc {

struct ReportContext {
  std::string implementation_spec;  // "reference", "exec:...", "plugin:..." as given
  // What the implementation says it is (Implementation::identity()): for
  // verse: the host, its release and the bone_create form used. Empty: none.
  std::string implementation_identity;
  // Implementation::merge_identity(): shards whose keys are equal merge.
  // Empty: implementation_spec is the key.
  std::string merge_identity;
  std::string command_line;         // the certify command that re-runs this run
  std::string started;              // UTC, ISO 8601
  std::string run_dir;              // where the run's files end up (final path)
  const Baseline* baseline = nullptr;
  std::string baseline_path;
  // The VGC_* variables the run's implementation ran with, as a command
  // prefix ("VGC_FAULT='a,b' "; vgc_environment_prefix()), for the replay
  // commands; unset: this process's. `vgc merge` sets the shards' own.
  std::optional<std::string> environment_prefix;
};

// "reports/<implementation slug>/<started>-seed<seed>[-shard<i>of<n>]"
std::string default_run_dir(const std::string& reports_root, const RunResult& run, const ReportContext& ctx);
// Claims a run directory of this run's own, with one mkdir: the default
// name, or it followed by -2, -3, ... when another run (same second, same
// seed) has it. Sets ctx->run_dir to the new, empty directory.
bool claim_run_dir(const std::string& reports_root, const RunResult& run, ReportContext* ctx, std::string* error);

// File name, relative to the run directory, of a clause's counterexample.
std::string counterexample_path(const ClauseOutcome& co);
// The counterexample's program as summary.md and report.html show it
// inline: the whole of it up to kInlineCommands commands; beyond (a user's
// mesh, `certify --mesh`), its first and last commands and a line naming
// the file that holds all of it.
inline constexpr std::size_t kInlineCommands = 200;
std::string inline_program(const ClauseOutcome& co);
// What the inline program is, for its heading: "Shrunk counterexample",
// the first program a tolerated clause was seen on, or program_origin.
std::string counterexample_heading(const ClauseOutcome& co);
// "1 command" or "N commands": the counterexample's length as the report
// pages and the .vgc file's header say it.
std::string commands_counted(std::size_t n);
// The one-line command that replays a counterexample file.
std::string replay_command(const std::string& file, const std::string& implementation_spec);
// The same for this run's implementation and environment (ctx).
std::string replay_command(const std::string& file, const ReportContext& ctx);
// "VGC_FAULT='a,b' " for every VGC_* variable of this process's environment
// (sorted), so a printed command repeats the run with what the
// implementation under test may read; empty when there is none.
std::string vgc_environment_prefix();

std::string render_counterexample(const ClauseOutcome& co, const ReportContext& ctx);
std::string render_report_json(const RunResult& run, const Verdict& v, const ReportContext& ctx);
std::string render_junit(const RunResult& run, const Verdict& v, const ReportContext& ctx);
std::string render_summary(const RunResult& run, const Verdict& v, const ReportContext& ctx);
// report.html (report_html.cpp): summary.md's content as a self-contained
// page, with a picture of each counterexample's final mesh.
std::string render_report_html(const RunResult& run, const Verdict& v, const ReportContext& ctx);
// File name, relative to the run directory, of a counterexample's final
// mesh ("counterexamples/<CLAUSE>.obj"), written when it holds a vertex.
std::string counterexample_obj_path(const ClauseOutcome& co);

// Writes every file into ctx.run_dir (via a temporary sibling directory and
// one rename; ctx.run_dir is absent or empty, as claim_run_dir leaves it)
// and points <reports_root>/latest at it. On failure nothing is left behind
// and *error says why.
bool write_report(const std::string& reports_root, const RunResult& run, const Verdict& v,
                  const ReportContext& ctx, std::string* error);

}  // namespace vgc
