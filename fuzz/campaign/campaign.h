// campaign.h — a libFuzzer campaign on one fuzz target, run and summarized:
// what `vgc fuzz TARGET` does (cli/cmd_fuzz.cpp parses the options and
// calls run_campaign).
//
// Spec: docs/fuzzing.md "Running a campaign"; clause ids and levels of the
// catalog (conformance/clause.h); the baseline format of `vgc certify`
// (conformance/report/baseline.h).
//
// Rationale: a campaign's findings must be triaged like certify's: each
// unique crash is signed from the target's FINDING line, named by the
// clause the target attributed it to (fuzz/targets/clause_finding.h), grouped by
// clause, and marked when the clause is in a --baseline; each gets a
// counterexample and a replay command carrying every VGC_* variable of the
// run. The summary is a plain struct (CampaignSummary) so that other
// renderers (JSON, Markdown here; HTML elsewhere) need nothing but it.
// --time is a wall-clock limit: libFuzzer's -max_total_time is asked for,
// and the whole process group is killed at the deadline if it overruns
// (fork mode with many crashing inputs did); re-running saved crashes to
// sign them and replaying counterexamples has its own budget after it
// (max(10 s, --time / 10), at most 200 inputs; the summary counts the
// inputs not re-run). Nothing here throws for anything
// the target or the implementation does; errors are exit code 2 with a
// message.
#pragma once

#include <cstddef>
#include <optional>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "crash_signature.h"  // clause_of_finding
#include "route.h"

namespace vgc::fuzz {

struct CampaignOptions {
  std::string target;         // stream, text, differential, mesh_*, property_<group> (fuzz_ optional)
  double time_s = 60;         // wall-clock limit of the fuzzing
  // > 0: also stop once libFuzzer and its jobs have used this many CPU
  // seconds (process_cpu.h); time_s is then the wall-clock cap. A soak on
  // a shared machine gets its budget however busy the machine is.
  double cpu_time_s = 0;
  int jobs = 1;               // libFuzzer -fork=N
  // --impl, read (route.h): none (the reference), "reference" or a plugin
  // (differential, property_*; loaded into the target's process), or a route
  // that is not in process, exec:CMD or verse:HOST[:PORT] (differential: a
  // live implementation, fuzz/targets/live_implementation.h).
  std::optional<Route> impl;
  // A live implementation (exec:, verse:): seconds per call (0: 5), the
  // bone_create form of a Verse host ("": auto), and for verse: a shell
  // command that starts a fresh host, run before a finding is confirmed
  // ("": a crash or hang of the host is reported unconfirmed).
  double call_timeout_s = 0;
  std::string verse_bone_form;
  std::string restart;
  // verse: the shell command that runs the host in the foreground
  // (--host-cmd): the target starts the host itself under the reaper, with
  // the shared memory of its coverage, and starts it again to confirm a
  // finding (fuzz/targets/live_implementation.h, launched_host.h); replaces
  // `restart`. One job only (one host on one port).
  std::string host_cmd;
  // A live implementation's own coverage, over exec: or a Verse host vgc
  // starts (--host-cmd) (fuzz/targets/live_coverage.h): "guide"
  // (default: its counters are libFuzzer features when it was built with
  // vgc's coverage runtime: its edges), "guide-counts" (its counters with
  // hit counts), "observe" (counted for the summary, not guiding: an
  // unguided campaign measured alike) or "off".
  std::string impl_coverage = "guide";
  // With an implementation whose coverage is seen and that has a PC table:
  // name every one of its functions and write which no input entered
  // (implementation_functions.md; symbolize_functions.h).
  bool coverage_report = false;
  unsigned seed = 1;
  std::size_t max_len = 1024;
  std::string fuzz_build;     // the clang -DVGC_FUZZ=ON build ("" : $VGC_FUZZ_BUILD_DIR or build-fuzz)
  std::string source_dir;     // corpora/, reports/ ("" : $VGC_SOURCE_DIR or the configured source)
  std::string baseline;       // a certify baseline file; its clauses are marked, not new
  bool empty_corpus = false;  // start from no input at all, not the committed corpus
  bool stop_at_first = false; // stop at the first finding (time to find)
  std::string vgc_binary;     // for replaying counterexamples ("" : this program)
  // More inputs to start from, copied into the run's corpus beside the
  // committed one (a soak's work corpus, fixed crashes); missing ones are skipped.
  std::vector<std::string> extra_corpora;
  // Nothing on stdout and no start line on stderr (a soak runs several
  // campaigns at once and prints its own table); summary files as always.
  bool quiet = false;
  // Seconds libFuzzer may run past time_s before its process group is
  // killed (0: 5 s). In fork mode it checks the time only between jobs,
  // and job k runs min(300, k) s, so the last job can overrun by that much.
  double grace_s = 0;
  // Status while libFuzzer runs ("TARGET for T s: execs ... crashes N"),
  // called on every libFuzzer status line, and once with "" when it has
  // stopped. Unset: a plain line on stderr at most every 10 s (logs).
  std::function<void(const std::string&)> progress;
};

// One unique crash (a signature), its inputs and how to replay it.
struct CampaignCrash {
  std::string signature;      // the smallest input's FINDING line, clause ids exact
  std::vector<std::string> also;  // other exact forms sharing the dedup key
  std::string dedup_key;      // digits folded
  std::string clause;         // the clause the target named, "" when none (sanitizer, mesh)
  std::string level;          // its level (MUST, SHOULD, ...), "" when none
  bool in_baseline = false;
  std::size_t inputs = 0;
  std::string input;          // the smallest input
  std::string counterexample; // command file (or mesh text / the text input)
  std::string replay;         // shell command replaying the counterexample, with its environment
  std::string replay_fuzzer;  // shell command re-running the input through the target
  // `vgc replay` of the counterexample was run: the clause it named ("" if
  // none); only for findings with a clause.
  std::optional<std::string> replayed_clause;
  // A crash or hang of a live implementation (status crash / timeout):
  // whether it was confirmed on a fresh instance, and how (or why not).
  std::string confirmation;
  std::optional<double> first_seen_s;  // seconds from the start to the first input of this crash
  // A raw-bytes finding (one not shrunk as a command program) has its input
  // minimized by libFuzzer's -minimize_crash (minimize_input.h): the
  // minimized input ("" when none was kept; the counterexample and
  // replay_fuzzer use it), its size and the original's, or why not.
  std::string minimized_input;
  std::size_t input_bytes = 0, minimized_bytes = 0;
  std::string minimize_note;
};

// The crashes of one clause ("" groups those without one).
struct CampaignClause {
  std::string clause;
  std::string level;
  bool in_baseline = false;
  std::string baseline_reason;
  std::vector<std::size_t> crashes;  // indices into CampaignSummary::crashes
  std::size_t inputs = 0;
  std::optional<double> first_seen_s;
};

struct CampaignSummary {
  std::string target, run, run_dir, binary, implementation, command;
  std::vector<std::string> environment;  // VGC_* variables of the run, NAME=value
  unsigned seed = 0;
  int jobs = 1;
  double time_s = 0, wall_s = 0;
  // CPU seconds (user + system) of libFuzzer and every job it waited for
  // (fork mode): what the fuzzing cost, whatever else the machine ran.
  double cpu_s = 0;
  bool killed_at_deadline = false;   // libFuzzer overran --time and was killed
  bool cpu_budget_spent = false;     // stopped at its CPU budget (cpu_time_s), not by time
  bool empty_corpus = false, stop_at_first = false;
  std::string baseline;
  long long executions = 0, exec_per_s_last = 0, cov = 0, ft = 0;
  double exec_per_s_mean = 0;
  std::size_t corpus_files = 0, corpus_bytes = 0, seed_files = 0;
  std::size_t crash_inputs = 0, crash_inputs_signed = 0;  // saved, and re-run to sign them
  std::string signing_stopped;  // "" or what stopped the signing early ("the CPU budget", "the wall guard")
  std::optional<double> time_to_first_finding_s;
  std::vector<CampaignCrash> crashes;
  std::vector<CampaignClause> clauses;  // sorted by clause id, "" last
  std::size_t new_crashes = 0;          // crashes whose clause is not in the baseline
  int libfuzzer_exit = 0;
  // An exec: implementation's own coverage (coverage_record.h), merged over
  // the run's processes: recorded when the target looked for it (mode
  // guide or observe), seen when the implementation exported counters.
  std::string impl_coverage_mode;  // guide, guide-counts, observe, off; wire (not taken); "" when not live
  bool impl_coverage_seen = false;
  std::size_t impl_counters = 0, impl_counters_reached = 0, impl_function_entries = 0, impl_functions_entered = 0,
              impl_counters_dropped = 0;
  std::vector<std::string> impl_modules;
  std::vector<std::pair<double, std::size_t>> impl_timeline;  // seconds since the start, counters reached
  // --coverage-report: the file written ("" when none), or why none was.
  std::string coverage_report, coverage_report_note;
  std::vector<std::string> functions_never_entered;  // "name (file:line)", at most 200, by location
  std::size_t functions_never_entered_count = 0;
};

// Runs the campaign, writes reports/fuzz/<target>/<run>/{summary.json,
// summary.md, counterexamples/, corpus/, crashes/, fuzzer.log}, prints the
// Markdown summary on stdout and progress on stderr. Returns the exit code:
// 0 nothing new found, 1 crashes found outside the baseline, 2 usage or
// infrastructure error (message on stderr). *out (optional) gets the summary.
int run_campaign(const CampaignOptions& o, CampaignSummary* out = nullptr);

// The source tree and the libFuzzer build a campaign with these options
// uses (the option, else $VGC_SOURCE_DIR / $VGC_FUZZ_BUILD_DIR, else the
// configured source / build-fuzz beside this program's build).
// The time stamp of run directory names: UTC, YYYYMMDDTHHMMSSZ (a soak's,
// a campaign's and a wire campaign's).
std::string utc_stamp();

std::string campaign_source_dir(const CampaignOptions& o);
std::string campaign_fuzz_build_dir(const CampaignOptions& o);

std::string summary_json(const CampaignSummary& s);
// The summary's "implementation coverage" line: counters reached, or why
// the implementation's coverage is not seen.
std::string implementation_coverage_line(const CampaignSummary& s);
std::string summary_markdown(const CampaignSummary& s);

// A binary stream (reference/node/command_binary.h) as a command file: the
// commands that decode, then a comment naming the bytes that do not.
std::string stream_to_text(const std::string& bytes);


}  // namespace vgc::fuzz
