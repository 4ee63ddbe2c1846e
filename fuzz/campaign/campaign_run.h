// campaign_run.h — what the steps of one fuzz campaign share (internal to
// fuzz/campaign*.cpp): the run's state, the crash groups, and the helpers
// more than one step file uses.
//
// Spec: docs/fuzzing.md "Running a campaign".
//
// Rationale: run_campaign (campaign.cpp) is a spine of named steps over one
// CampaignRun; the steps that sign and write findings live in
// campaign_findings.cpp, so the state they share is declared here, once.
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "baseline.h"
#include "campaign.h"
#include "campaign_html.h"
#include "campaign_process.h"
#include "sign_budget.h"

namespace vgc::fuzz::campaign_steps {

namespace fs = std::filesystem;
using clock = std::chrono::steady_clock;

// libFuzzer's figures, from its latest status line (parse_progress).
struct Progress {
  long long execs = 0, exec_s = 0, cov = 0, ft = 0, corp = 0, crashes = 0;
};

// Which implementation a campaign fuzzes (--impl) and the environment
// variables that name it to the target: VGC_FUZZ_PLUGIN for a plugin in
// process; VGC_FUZZ_IMPL (and VGC_FUZZ_TIMEOUT, VGC_FUZZ_VERSE_BONE_FORM,
// VGC_FUZZ_RESTART) for a live one (fuzz/targets/live_implementation.h).
struct ImplementationChoice {
  std::string plugin;             // absolute path, or ""
  std::optional<Route> live;      // exec:CMD or verse:..., or none
  std::vector<std::string> env;   // NAME=value
  std::string spec() const {
    return live ? live->spec : plugin.empty() ? "reference" : route_spec(RouteKind::Plugin, plugin);
  }
  // Whether the live implementation is of `kind`.
  bool live_on(RouteKind kind) const { return live && live->kind == kind; }
};

// What the steps of one campaign share (run_campaign runs them in order).
struct CampaignRun {
  explicit CampaignRun(const CampaignOptions& opts) : o(opts) {}
  const CampaignOptions& o;
  std::string name;  // the target without fuzz_
  bool property = false, mesh = false;
  Baseline baseline;
  fs::path src, binary, dir, corpus, crashes, cex;
  ImplementationChoice impl;             // --impl: a plugin, a live implementation or the reference
  std::string plugin;                    // absolute path, "" for the reference or a live implementation
  std::vector<std::string> env_add;      // what the target runs with beyond this process's environment
  std::vector<std::string> run_env;      // VGC_* of this process, without the plugin (for vgc replay)
  std::vector<std::string> target_env;   // run_env and the plugin (for the target)
  CampaignSummary s;
  clock::time_point t0;
  fs::file_time_type sys0;
  SignBudget sign;                       // the budget of signing, minimizing and replaying crashes
  Progress progress;
  std::vector<CampaignSample> samples;   // for report.html's plots
  ChildRun fuzzed;
  long long execs_before = 0;            // live rounds: executions of the rounds before the last
};

// The crash inputs of one signature.
struct CrashGroup {
  std::map<fs::path, std::string> shown;    // per input: its signature with exact clause ids
  std::vector<fs::path> files;              // smallest first
  std::map<fs::path, std::string> printed;  // the target's own counterexample block, per input
  std::map<fs::path, std::optional<double>> first_seen;
};

bool read_file(const fs::path& p, std::string* out);
// This program's path (/proc/self/exe), or empty.
fs::path self_exe();
bool write_file(const fs::path& p, const std::string& s);
// `NAME='value' ` for each, for the start of a shell command.
std::string env_prefix(const std::vector<std::string>& vars);
// When f was last written, in seconds since `start` (none: unreadable).
std::optional<double> seconds_since(const fs::path& f, fs::file_time_type start);
// ` --timeout T --verse-bone-form F` for `vgc replay` of a live
// implementation's counterexample, as the campaign ran it.
std::string replay_options(const CampaignOptions& o);
// The target's own counterexample block in its output.
std::optional<std::string> printed_block(const CampaignRun& r, const std::string& output);
// Re-runs one input through the target alone (its output, stdout and stderr).
std::string rerun_input(const CampaignRun& r, const fs::path& f);

// The steps of campaign_findings.cpp: the saved crash inputs re-run, signed
// and grouped; then one finding per group, minimized, its counterexample
// written.
std::map<std::string, CrashGroup> sign_crash_inputs(CampaignRun* r);
void write_findings(CampaignRun* r, std::map<std::string, CrashGroup>& unique);

}  // namespace vgc::fuzz::campaign_steps
