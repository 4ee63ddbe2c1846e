// soak.h — a soak: every fuzz target run for a given time from its
// committed corpus, several at once, what they learned merged into a work
// corpus, and one table of the whole (`vgc fuzz --all`; cli/cmd_fuzz.cpp
// parses the options and calls run_soak).
//
// Spec: docs/fuzzing.md "Soak"; each target's campaign is campaign.h's.
//
// Rationale: a nightly soak has to answer "did N CPU-hours of fuzzing find
// anything, and what did it cost", for every target, in one table a team
// can compare night to night. So each target is one campaign (libFuzzer
// fork mode with -ignore_crashes: it stops on nothing but its time, a
// finding is counted, signed and given a counterexample by the campaign),
// `jobs` campaigns run at a time, each as one process (so CPU seconds are
// per target, measured from the kernel's rusage, not assumed from the wall
// clock), and after each campaign its corpus is merged (libFuzzer
// -merge=1) into the work corpus, which the next soak starts from together
// with the committed corpus and the fixed crashes. The table is written
// whole or not at all, in a fixed target order whatever order the
// campaigns ended in.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace vgc::fuzz {

struct SoakOptions {
  std::vector<std::string> targets;          // without fuzz_; empty: every target (soak_targets())
  double time_s = 600;                       // fuzzing time of each target: wall-clock, or CPU with cpu_time
  // time_s and target_time_s count CPU seconds of each target (libFuzzer
  // and its jobs, process_cpu.h), not wall-clock: on a shared machine each
  // target still gets its budget. Its wall time is capped at
  // wall_cap_factor times the budget.
  bool cpu_time = false;
  double wall_cap_factor = 6;
  std::map<std::string, double> target_time_s;  // per-target override (name without fuzz_)
  int jobs = 1;                              // campaigns at the same time, one libFuzzer process each
  unsigned seed = 1;
  std::string fuzz_build;                    // as CampaignOptions
  std::string source_dir;                    // as CampaignOptions
  std::string work_corpus;                   // "": <source>/reports/fuzz/work-corpus (one directory per target)
  std::string vgc_binary;                    // as CampaignOptions
};

struct SoakRow {
  std::string target;                  // fuzz_<name>
  double time_s = 0, wall_s = 0, cpu_s = 0;
  long long executions = 0, cov = 0, ft = 0;
  std::size_t start_files = 0;         // inputs it started from (committed + fixed crashes + work corpus)
  std::size_t work_files_before = 0;   // the work corpus before the merge
  std::size_t work_files = 0;          // and after it
  bool merged = false;                 // the merge ran to its end
  double merge_s = 0;                  // its wall time (what corpus minimization costs)
  bool killed = false;                 // libFuzzer overran its time (a fork-mode job still running) and was killed
  bool cpu_budget_spent = false;       // stopped at its CPU budget (cpu_time)
  std::size_t findings = 0;            // unique crashes (signatures)
  std::size_t crash_inputs = 0;
  std::vector<std::string> signatures; // one per finding
  std::string run_dir;
  int campaign_exit = 0;               // run_campaign's: 0, 1 findings, 2 error
};

struct SoakSummary {
  std::string run, run_dir, command;
  unsigned seed = 1;
  bool cpu_time = false;               // the times are CPU budgets
  int jobs = 1;
  double wall_s = 0;
  std::string work_corpus;
  std::vector<SoakRow> rows;           // in soak_targets() order
};

// Every target `vgc fuzz` knows, without fuzz_: stream, text,
// differential, verse_packet, mesh_manifold, mesh_subdivision,
// property_<group> for each group.
std::vector<std::string> soak_targets();

// Runs the soak; writes reports/fuzz/soak/<run>/{soak.md, soak.json}
// (each target's campaign has its own run directory as `vgc fuzz TARGET`
// makes), prints the Markdown table on stdout and a line per campaign
// start and end on stderr. Returns 0 no finding, 1 findings, 2 usage or
// infrastructure error (a target that could not be run, the table not
// written). `command` is the command line shown in the table.
int run_soak(const SoakOptions& o, const std::string& command, SoakSummary* out = nullptr);

std::string soak_markdown(const SoakSummary& s);
std::string soak_json(const SoakSummary& s);

}  // namespace vgc::fuzz
