// cmd_fuzz.cpp — `vgc fuzz`: the options of a libFuzzer campaign on one fuzz
// target (run and summarized by fuzz/campaign/campaign.h), and conversions between
// binary streams and command files.
//
//   vgc fuzz TARGET [--time S] [--jobs N] [--impl plugin:PATH] [--seed N]
//                   [--baseline FILE] [--empty-corpus] [--stop-at-first]
//   vgc fuzz differential --impl exec:CMD|verse:HOST[:PORT] [--timeout S]
//                   [--verse-bone-form F] [--restart CMD | --host-cmd CMD]
//                   [--impl-coverage guide|guide-counts|observe|off] ...
//                                      a live implementation, through the
//                                      adapters certify uses
//   vgc fuzz wire --impl verse:HOST[:PORT] [--time S] [--seed N] [--restart CMD | --host-cmd CMD]
//                   [--max-inputs N] [--stop-at-first]
//                                      hostile wire traffic (fuzz/wire/wire_fuzz.h)
//   vgc fuzz wire --write-seeds DIR [--seed N] [--max-inputs N]
//                                      its inputs as fuzz_verse_packet seeds
//   vgc fuzz --all [--time S] [--target-time NAME=S]... [--jobs N] [--seed N]
//                  [--targets A,B] [--work-corpus DIR]
//                                      a soak of every target (fuzz/campaign/soak.h)
//   vgc fuzz --to-text STREAM          binary stream -> command file (stdout)
//   vgc fuzz --to-binary FILE -o OUT   command file -> binary stream
//
// Spec: docs/fuzzing.md. Exit codes: 0 the campaign ran and found nothing
// new; 1 it found crashes outside the baseline (each deduplicated one has a
// counterexample and a replay command); 2 usage or infrastructure error.
// --all (docs/fuzzing.md "Soak"): 0 no finding in any target, 1 findings,
// 2 a target could not be run or the table not written.
#include <fmt/core.h>

#include <climits>
#include <cstdint>
#include <cstdlib>
#include <map>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "campaign.h"
#include "soak.h"
#include "wire_fuzz.h"
#include "command_binary.h"
#include "command_text.h"
#include "open_impl.h"
#include "option_values.h"
#include "progress_line.h"
#include "read_file.h"
#include "subcommand.h"
#include "terminal_text.h"

namespace vgc::cli {
namespace {

struct FuzzArgs {
  fuzz::CampaignOptions campaign;
  ImplOptions impl;  // --impl and its family (open_impl.h), passed to the campaign as given
  std::string to_text, to_binary, output;
  bool all = false;
  bool cpu_time = false;                  // --cpu-time
  double wall_cap = 0;                    // --wall-cap (0: SoakOptions' default)
  std::vector<std::string> target_times;  // NAME=S
  std::vector<std::string> only;          // --targets
  std::string work_corpus;
  std::uint64_t max_inputs = 0;  // wire
  std::string write_seeds;       // wire
};

// `vgc fuzz wire`: hostile Verse traffic against a running host.
int run_wire(const FuzzArgs& a) {
  const fuzz::CampaignOptions& c = a.campaign;
  if (!a.write_seeds.empty()) {
    const std::size_t n = fuzz::write_wire_seeds(c.seed, a.max_inputs ? a.max_inputs : 3, a.write_seeds);
    say("vgc fuzz wire: {} packets written to {}\n", n, a.write_seeds);
    return n ? 0 : 2;
  }
  if (c.jobs != 1 || !c.baseline.empty() || c.empty_corpus) {
    say(stderr, "vgc fuzz wire: one host, one campaign: --jobs, --baseline and --empty-corpus do not apply\n");
    return 2;
  }
  if (c.coverage_report) {
    say(stderr, "vgc fuzz wire: --coverage-report is for vgc fuzz differential (--impl exec:CMD, or verse: with "
                "--host-cmd)\n");
    return 2;
  }
  if (c.host_cmd.empty() && c.impl_coverage != "guide") {
    say(stderr, "vgc fuzz wire: --impl-coverage is for a host vgc starts (--host-cmd CMD)\n");
    return 2;
  }
  if (!c.host_cmd.empty() && !c.restart.empty()) {
    say(stderr, "vgc fuzz wire: --host-cmd replaces --restart: vgc starts the host again itself; give one of them\n");
    return 2;
  }
  fuzz::WireFuzzOptions o;
  if (c.impl) o.impl = *c.impl;
  o.time_s = c.time_s;
  o.seed = c.seed;
  o.max_inputs = a.max_inputs;
  if (c.call_timeout_s > 0) o.timeout_s = c.call_timeout_s;
  o.verse_bone_form = c.verse_bone_form;
  o.restart = c.restart;
  o.host_cmd = c.host_cmd;
  o.impl_coverage = c.impl_coverage;
  o.source_dir = fuzz::campaign_source_dir(c);
  o.stop_at_first = c.stop_at_first;
  return fuzz::run_wire_campaign(o);
}

// `vgc fuzz --all`: the campaign options that apply to a soak, and the
// per-target times.
int run_all(const FuzzArgs& a) {
  const fuzz::CampaignOptions& c = a.campaign;
  if (!c.target.empty() || c.impl || !c.baseline.empty() || c.empty_corpus || c.stop_at_first ||
      c.coverage_report) {
    fmt::print(stderr, "vgc fuzz --all: runs every target on the reference from its committed corpus; a target, "
                       "--impl, --baseline, --empty-corpus, --stop-at-first and --coverage-report are for one campaign\n");
    return 2;
  }
  fuzz::SoakOptions o;
  o.time_s = c.time_s;
  o.cpu_time = a.cpu_time;
  if (a.wall_cap != 0) {
    if (!a.cpu_time || !(a.wall_cap >= 1)) {
      fmt::print(stderr, "vgc fuzz --all: --wall-cap takes a factor of at least 1, with --cpu-time\n");
      return 2;
    }
    o.wall_cap_factor = a.wall_cap;
  }
  o.jobs = c.jobs;
  o.seed = c.seed;
  o.fuzz_build = c.fuzz_build;
  o.source_dir = c.source_dir;
  o.work_corpus = a.work_corpus;
  o.targets = a.only;
  std::string command = fmt::format("vgc fuzz --all --time {}", c.time_s);
  if (!a.only.empty()) {
    command += " --targets ";
    for (std::size_t i = 0; i < a.only.size(); ++i) command += (i ? "," : "") + a.only[i];
  }
  for (const std::string& nt : a.target_times) {
    const auto eq = nt.find('=');
    double t = 0;
    if (eq == std::string::npos || eq == 0 || !parse_decimal(std::string_view(nt).substr(eq + 1), &t) || !(t > 0) ||
        t > kMaxSeconds) {
      fmt::print(stderr, "vgc fuzz --all: --target-time takes NAME=SECONDS (e.g. verse_packet=3600), not '{}'\n", nt);
      return 2;
    }
    std::string name = nt.substr(0, eq);
    if (name.rfind("fuzz_", 0) == 0) name = name.substr(5);
    o.target_time_s[name] = t;
    command += " --target-time " + nt;
  }
  command += fmt::format(" --jobs {} --seed {}", c.jobs, c.seed);
  if (a.cpu_time) command += " --cpu-time";
  if (a.wall_cap != 0) command += fmt::format(" --wall-cap {}", a.wall_cap);
  if (!a.work_corpus.empty()) command += " --work-corpus " + a.work_corpus;
  return fuzz::run_soak(o, command);
}

bool write_file(const std::string& p, const std::string& s) {
  std::ofstream out(p, std::ios::binary);
  out << s;
  return static_cast<bool>(out);
}

int run_fuzz(const FuzzArgs& a) {
  if (!a.to_text.empty()) {
    std::string bytes;
    if (!read_file(a.to_text, &bytes)) {
      say(stderr, "vgc fuzz: cannot read {}\n", a.to_text);
      return 2;
    }
    const std::string text = fuzz::stream_to_text(bytes);
    if (a.output.empty()) {
      say("{}", text);
    } else if (!write_file(a.output, text)) {
      say(stderr, "vgc fuzz: cannot write {}\n", a.output);
      return 2;
    }
    return 0;
  }
  if (!a.to_binary.empty()) {
    std::string text;
    if (!read_file(a.to_binary, &text)) {
      say(stderr, "vgc fuzz: cannot read {}\n", a.to_binary);
      return 2;
    }
    std::vector<Command> cs;
    TextError e;
    if (!parse_commands(text, &cs, &e)) {
      say(stderr, "{}:{}:{}: error: {}\n", a.to_binary, e.line, e.column, e.message);
      return 2;
    }
    std::string bytes;
    for (const Command& c : cs)
      if (!encode_command(c, &bytes)) {
        say(stderr, "vgc fuzz: a name is too long to encode: {}\n", print_command(c));
        return 2;
      }
    if (a.output.empty()) {
      say(stderr, "vgc fuzz: --to-binary needs -o OUT\n");
      return 2;
    }
    return write_file(a.output, bytes) ? 0 : 2;
  }
  if (a.all) return run_all(a);
  if (a.cpu_time || a.wall_cap != 0) {
    say(stderr, "vgc fuzz: --cpu-time and --wall-cap are for a soak (--all); one campaign's --time is wall-clock\n");
    return 2;
  }
  if (a.campaign.target == "wire") return run_wire(a);
  if (a.campaign.target.empty()) {
    say(stderr, "vgc fuzz: name a target (stream, text, differential, verse_packet, mesh_manifold, mesh_subdivision, "
                       "property_<group>) or use --to-text / --to-binary\n");
    return 2;
  }
  // On a terminal redrawn in place with its elapsed time at least twice a
  // second; in a log a line every 10 s (progress_line.h).
  ProgressLine status(true);
  fuzz::CampaignOptions o = a.campaign;
  status.update(fmt::format("{} for {:.0f} s: starting libFuzzer", o.target, o.time_s), true);
  o.progress = [&status](const std::string& line) {
    if (line.empty())
      status.finish();
    else
      status.update(line);
  };
  return fuzz::run_campaign(o);
}

void add_fuzz(CLI::App& app, int* exit_code) {
  auto a = std::make_shared<FuzzArgs>();
  fuzz::CampaignOptions& o = a->campaign;
  CLI::App* sub = app.add_subcommand("fuzz", "Run a libFuzzer campaign on a fuzz target, or convert fuzz inputs");
  sub->add_option("target", o.target,
                  "stream, text, differential, verse_packet, mesh_manifold, mesh_subdivision, property_<group>, or "
                  "wire (hostile traffic against a running Verse host, --impl verse:HOST[:PORT])");
  sub->add_option("--time", o.time_s, "Campaign length in seconds, a wall-clock limit (default 60)")
      ->transform(seconds("for the campaign (each target with --all)"));
  sub->add_option("--jobs", o.jobs,
                  "Parallel fuzzing jobs (libFuzzer -fork=N, default 1); with --all, targets fuzzed at a time")
      ->transform(whole_number(1, 1024, "jobs"));
  sub->add_flag("--all", a->all,
                "Soak: every target for --time seconds each from its committed corpus, --jobs at a time; "
                "merges into a work corpus and writes a table (docs/fuzzing.md \"Soak\")");
  sub->add_option("--target-time", a->target_times,
                  "With --all: NAME=SECONDS for one target instead of --time (repeatable)");
  sub->add_flag("--cpu-time", a->cpu_time,
                "With --all: --time and --target-time are CPU seconds of each target (libFuzzer and its jobs), "
                "not wall-clock, so a soak on a busy machine still gets its budget (wall capped at --wall-cap x)");
  sub->add_option("--wall-cap", a->wall_cap,
                  "With --all --cpu-time: stop a target starved of CPU after FACTOR times its budget of wall "
                  "clock (default 6)")
      ->transform(decimal_in(1, 1000, "(a factor)"));
  sub->add_option("--targets", a->only, "With --all: only these targets (comma-separated)")->delimiter(',');
  sub->add_option("--work-corpus", a->work_corpus,
                  "With --all: the work corpus directory (default reports/fuzz/work-corpus)");
  add_impl_options(sub, &a->impl, kTimeout | kBoneForm | kRestart | kHostCmd,
                   "differential, property_<group>: the implementation under test, plugin:PATH; differential also "
                   "exec:CMD or verse:[NAME@]HOST[:PORT], a running implementation (docs/fuzzing.md)");
  sub->add_option("--impl-coverage", o.impl_coverage,
                  "exec: an implementation built with vgc's coverage runtime: guide (default; its edges steer "
                  "libFuzzer), guide-counts (edges and hit counts), observe (counted, not steering) or off")
      ->check(CLI::IsMember({"guide", "guide-counts", "observe", "off"}));
  sub->add_flag("--coverage-report", o.coverage_report,
                "exec: with an implementation built with vgc's coverage runtime and a PC table: name each of its "
                "functions (llvm-symbolizer) and write which no input entered (implementation_functions.md)");
  sub->add_option("--seed", o.seed, "libFuzzer seed (default 1)")
      ->transform(whole_number(0, UINT_MAX, "the libFuzzer seed"));
  sub->add_option("--max-len", o.max_len, "Longest input in bytes (libFuzzer -max_len, default 1024)")
      ->transform(whole_number(1, std::uint64_t{1} << 24, "bytes"));
  sub->add_option("--baseline", o.baseline,
                  "Known deviations (the certify baseline format): their clauses are marked, not new; with "
                  "--impl exec:/verse: the target also passes over them (a crash or hang excepted)");
  sub->add_flag("--empty-corpus", o.empty_corpus, "Start from no input, not the committed corpus");
  sub->add_flag("--stop-at-first", o.stop_at_first, "Stop at the first finding (time to find)");
  sub->add_option("--fuzz-build", o.fuzz_build, "The clang -DVGC_FUZZ=ON build directory");
  sub->add_option("--source-dir", o.source_dir, "The vgc source tree (corpora/, reports/)");
  sub->add_option("--max-inputs", a->max_inputs, "wire: stop after this many inputs (default: only --time)")
      ->transform(whole_number(1, UINT64_MAX, "inputs"));
  sub->add_option("--write-seeds", a->write_seeds,
                  "wire: write the first inputs of every kind (--max-inputs per kind, default 3) as fuzz_verse_packet "
                  "seeds into DIR; no host needed");
  sub->add_option("--to-text", a->to_text, "Print the binary stream FILE as a command file");
  sub->add_option("--to-binary", a->to_binary, "Encode the command file FILE as a binary stream (-o OUT)");
  sub->add_option("-o,--output", a->output, "Output file of --to-text / --to-binary");
  sub->callback([a, exit_code] {
    // The family's values as the campaign takes them: only what was given.
    fuzz::CampaignOptions& c = a->campaign;
    if (a->impl.impl_given) c.impl = a->impl.route;
    if (a->impl.timeout_given) c.call_timeout_s = a->impl.timeout;
    if (a->impl.bone_form_given) c.verse_bone_form = a->impl.verse_bone_form;
    c.restart = a->impl.restart;
    c.host_cmd = a->impl.host_cmd;
    *exit_code = run_fuzz(*a);
  });
}

const Subcommand kFuzz{add_fuzz};

}  // namespace

}  // namespace vgc::cli
