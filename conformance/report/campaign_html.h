// campaign_html.h — report.html of a `vgc fuzz` campaign: the same kind of
// page as a certify run's (report_html.cpp), from a plain struct: what ran,
// coverage and corpus size over time as plots, and the findings with their
// counterexamples and replay commands.
//
// Spec: none (reporting); docs/fuzzing.md describes the campaign and its
// files (summary.json, summary.md), whose figures this page shows.
//
// Rationale: the campaign runner (cli/cmd_fuzz.cpp) knows libFuzzer's
// status lines and crash files; this file knows neither, only the struct,
// so the page does not change when the runner does. The plots are SVG
// polylines written with pugixml, the page has no script and loads nothing
// (self-contained, readable from disk).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace vgc {

struct CampaignSample {
  double seconds = 0;        // since the campaign started
  long long executions = 0;
  long long coverage = 0;    // libFuzzer "cov"
  long long features = 0;    // libFuzzer "ft"
  long long corpus = 0;      // inputs in the corpus
};

struct CampaignFinding {
  std::string signature;               // as summary.md shows it
  std::vector<std::string> also;       // other forms in the same group
  std::size_t inputs = 0;              // crash inputs with this signature
  std::string counterexample;          // file path
  std::string counterexample_text;     // its content (shown inline when short)
  std::string replay;                  // command
  std::string replay_fuzzer;           // command
};

struct CampaignReport {
  std::string target, run, implementation, command;
  unsigned long long seed = 0;
  int jobs = 1;
  double time_s = 0, wall_s = 0;
  long long executions = 0, exec_per_s_last = 0;
  double exec_per_s_mean = 0;
  long long coverage = 0, features = 0;
  std::size_t corpus_files = 0, corpus_bytes = 0, seed_files = 0, crash_inputs = 0;
  std::vector<CampaignSample> samples;  // in time order
  std::vector<CampaignFinding> findings;
  // A live implementation's own coverage (docs/fuzzing.md "Coverage of the
  // implementation"): the summary's line ("" : no row), and the counters
  // reached over time (`coverage` of each sample; plotted from two points).
  std::string implementation_coverage;
  std::vector<CampaignSample> implementation_samples;
  // --coverage-report: the implementation's functions no input entered
  // ("name (file:line)", by place, at most 200), how many there are in
  // all, and the file that lists every function ("" : no such section).
  std::vector<std::string> functions_never_entered;
  std::size_t functions_never_entered_count = 0;
  std::string function_report;
};

// The page. Plots are drawn when there are at least two samples (else a
// sentence says there is nothing to plot); at most 1000 points each (evenly
// thinned, the last sample always kept).
std::string render_campaign_html(const CampaignReport& report);

// Writes `dir`/report.html whole or not at all (a temporary file renamed
// into place). false and *error set on failure.
bool write_campaign_html(const std::string& dir, const CampaignReport& report, std::string* error);

}  // namespace vgc
