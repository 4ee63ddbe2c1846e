// campaign.cpp — a libFuzzer campaign's spine (see campaign.h): run_campaign
// and its steps in order (options, run directory, libFuzzer, signing and
// findings, clauses, corpus and speed, coverage, reports). The children it
// starts are campaign_process.h's, crashes are signed by crash_signature.h,
// findings minimized and written by campaign_findings.cpp, the summaries
// rendered by campaign_summary.cpp; campaign_run.h is what the steps share.
//
// Spec: docs/fuzzing.md "Running a campaign".
#include "campaign.h"
#include "campaign_run.h"

#include <charconv>
#include <fmt/core.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <regex>

#include "baseline.h"
#include "clause.h"
#include "command_binary.h"
#include "command_text.h"
#include "display_text.h"
#include "exec_implementation.h"
#include "coverage_record.h"
#include "live_implementation.h"
#include "symbolize_functions.h"
#include "campaign_process.h"
#include "crash_signature.h"

namespace vgc::fuzz {
namespace campaign_steps {


bool read_file(const fs::path& p, std::string* out) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

bool write_file(const fs::path& p, const std::string& s) {
  std::ofstream out(p, std::ios::binary);
  out << s;
  return static_cast<bool>(out);
}

fs::path self_exe() {
  std::error_code ec;
  fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path{} : p;
}

// The build directory this program was built in (…/build/cli/vgc).
fs::path own_build_dir() { return self_exe().parent_path().parent_path(); }

fs::path source_dir(const CampaignOptions& o) {
  if (!o.source_dir.empty()) return o.source_dir;
  if (const char* e = std::getenv("VGC_SOURCE_DIR"); e && *e) return e;
  std::string cache;
  if (read_file(own_build_dir() / "CMakeCache.txt", &cache)) {
    std::smatch m;
    if (std::regex_search(cache, m, std::regex("CMAKE_HOME_DIRECTORY:INTERNAL=([^\n]*)"))) return m[1].str();
  }
  return fs::current_path();
}

fs::path fuzz_build_dir(const CampaignOptions& o) {
  if (!o.fuzz_build.empty()) return o.fuzz_build;
  if (const char* e = std::getenv("VGC_FUZZ_BUILD_DIR"); e && *e) return e;
  return own_build_dir().parent_path() / "build-fuzz";
}


// Reads one libFuzzer status line ("#1234 NEW cov: 5 ft: 6 corp: 7/80b ...
// exec/s: 9", or in fork mode "#1234: cov: 5 ft: 6 corp: 7 exec/s 9
// oom/timeout/crash: 0/0/1 ..."). Returns false for any other line.
bool parse_progress(const std::string& line, Progress* p) {
  if (line.empty() || line[0] != '#') return false;
  static const std::regex head(R"(^#(\d+))");
  std::smatch m;
  if (!std::regex_search(line, m, head)) return false;
  if (line.find("cov: ") == std::string::npos) return false;
  // Digits only (the patterns say so); a number past 64 bits is no status line.
  auto number = [](const std::ssub_match& digits, long long* out) {
    const std::string text = digits.str();
    return std::from_chars(text.data(), text.data() + text.size(), *out).ec == std::errc();
  };
  if (!number(m[1], &p->execs)) return false;
  auto field = [&](const char* re, long long* out) {
    std::smatch f;
    if (std::regex_search(line, f, std::regex(re))) number(f[1], out);
  };
  field(R"(cov: (\d+))", &p->cov);
  field(R"(ft: (\d+))", &p->ft);
  field(R"(corp: (\d+))", &p->corp);
  field(R"(exec/s:? (\d+))", &p->exec_s);
  field(R"(oom/timeout/crash: \d+/\d+/(\d+))", &p->crashes);
  return true;
}

std::string normalize_target(std::string t) {
  if (t.rfind("fuzz_", 0) == 0) t = t.substr(5);
  return t;
}

// NAME=value of every VGC_* variable of this process, sorted.
std::vector<std::string> vgc_environment() {
  std::vector<std::string> vars;
  for (char** e = environ; e && *e; ++e) {
    const std::string entry(*e);
    if (entry.rfind("VGC_", 0) == 0 && entry.find('=') != std::string::npos) vars.push_back(entry);
  }
  std::sort(vars.begin(), vars.end());
  return vars;
}

// `NAME='value' ` for each, for the start of a shell command.
std::string env_prefix(const std::vector<std::string>& vars) {
  std::string out;
  for (const std::string& v : vars) {
    const auto eq = v.find('=');
    out += v.substr(0, eq) + "=" + shell_quote(v.substr(eq + 1)) + " ";
  }
  return out;
}

std::optional<double> seconds_since(const fs::path& f, fs::file_time_type start) {
  std::error_code ec;
  const auto t = fs::last_write_time(f, ec);
  if (ec) return std::nullopt;
  return std::max(0.0, std::chrono::duration<double>(t - start).count());
}

bool is_implementation_variable(const std::string& v) {
  for (const char* n : {"VGC_FUZZ_PLUGIN=", "VGC_FUZZ_IMPL=", "VGC_FUZZ_TIMEOUT=", "VGC_FUZZ_VERSE_BONE_FORM=",
                        "VGC_FUZZ_RESTART=", "VGC_FUZZ_BASELINE=", "VGC_FUZZ_IMPL_COVERAGE=",
                        "VGC_FUZZ_IMPL_COVERAGE_DIR=", "VGC_COVERAGE_SHM=", "VGC_FUZZ_HOST_CMD=",
                        "VGC_FUZZ_HOST_LOG="})
    if (v.rfind(n, 0) == 0) return true;
  return false;
}

bool choose_implementation(const CampaignOptions& o, const std::string& name, bool property,
                           ImplementationChoice* out) {
  const bool live = o.impl && !o.impl->traits().in_process;
  // The implementation's coverage is taken from a program vgc starts: an
  // exec: program, or a Verse host started by --host-cmd.
  const bool exec = o.impl && (o.impl->kind == RouteKind::Exec ||
                               (o.impl->kind == RouteKind::Verse && !o.host_cmd.empty()));
  if (o.impl_coverage != "guide" && o.impl_coverage != "guide-counts" && o.impl_coverage != "observe" &&
      o.impl_coverage != "off") {
    fmt::print(stderr, "vgc fuzz: --impl-coverage takes guide, guide-counts, observe or off, not '{}'\n",
               o.impl_coverage);
    return false;
  }
  if (!o.host_cmd.empty()) {
    if (!o.impl || o.impl->kind != RouteKind::Verse) {
      fmt::print(stderr, "vgc fuzz: --host-cmd is for --impl verse:HOST:PORT (the Verse host vgc starts)\n");
      return false;
    }
    if (!o.restart.empty()) {
      fmt::print(stderr, "vgc fuzz: --host-cmd replaces --restart: vgc starts the host again itself for a fresh "
                         "instance; give one of them\n");
      return false;
    }
    if (o.jobs != 1) {
      fmt::print(stderr, "vgc fuzz: --host-cmd starts one host on the port of --impl: one job only (--jobs 1)\n");
      return false;
    }
  }
  if (o.impl_coverage != "guide" && !exec) {
    fmt::print(stderr, "vgc fuzz: --impl-coverage is for --impl exec:CMD, or verse:HOST:PORT with --host-cmd (a "
                       "program vgc starts)\n");
    return false;
  }
  if (o.coverage_report && (!exec || o.impl_coverage == "off")) {
    fmt::print(stderr, "vgc fuzz: --coverage-report is for --impl exec:CMD, or verse:HOST:PORT with --host-cmd, "
                       "with its coverage on (not --impl-coverage off)\n");
    return false;
  }
  if (!live && (o.call_timeout_s > 0 || !o.verse_bone_form.empty() || !o.restart.empty())) {
    fmt::print(stderr, "vgc fuzz: --timeout, --verse-bone-form and --restart are for --impl exec:CMD or verse:HOST\n");
    return false;
  }
  if (!o.restart.empty() && o.impl->traits().restartable) {
    fmt::print(stderr, "vgc fuzz: --restart is for --impl verse:HOST (an exec: program is restarted by vgc)\n");
    return false;
  }
  if (!o.impl || o.impl->kind == RouteKind::Reference) return true;
  if (live) {
    if (name != "differential") {
      fmt::print(stderr, "vgc fuzz: --impl {} (a live implementation) is for the differential target only\n",
                 o.impl->form());
      return false;
    }
    out->live = o.impl;
    out->env.push_back("VGC_FUZZ_IMPL=" + o.impl->spec);
    if (o.call_timeout_s > 0) out->env.push_back(fmt::format("VGC_FUZZ_TIMEOUT={}", o.call_timeout_s));
    if (!o.verse_bone_form.empty()) out->env.push_back("VGC_FUZZ_VERSE_BONE_FORM=" + o.verse_bone_form);
    if (!o.restart.empty()) out->env.push_back("VGC_FUZZ_RESTART=" + o.restart);
    if (!o.host_cmd.empty()) out->env.push_back("VGC_FUZZ_HOST_CMD=" + o.host_cmd);
    // The implementation's own coverage (live_coverage.h; a program vgc starts).
    if (o.impl_coverage != "guide" && exec)
      out->env.push_back("VGC_FUZZ_IMPL_COVERAGE=" + o.impl_coverage);
    // Known deviations do not stop libFuzzer (live_implementation.h).
    if (!o.baseline.empty()) out->env.push_back("VGC_FUZZ_BASELINE=" + fs::absolute(o.baseline).string());
    return true;
  }
  if ((name != "differential" && !property) || o.impl->kind != RouteKind::Plugin) {
    fmt::print(stderr,
               "vgc fuzz: --impl takes plugin:PATH (or reference) for the differential and property targets, or "
               "exec:CMD / verse:HOST[:PORT] for the differential target\n");
    return false;
  }
  out->plugin = fs::absolute(o.impl->target).string();
  if (!fs::exists(out->plugin)) {
    fmt::print(stderr, "vgc fuzz: no such plugin {}: give --impl plugin:PATH the path of your plugin's shared library\n",
               out->plugin);
    return false;
  }
  out->env.push_back("VGC_FUZZ_PLUGIN=" + out->plugin);
  return true;
}

// ` --timeout T --verse-bone-form F` for `vgc replay` of a live
// implementation's counterexample, as the campaign ran it.
std::string replay_options(const CampaignOptions& o) {
  std::string out;
  if (o.call_timeout_s > 0) out += fmt::format(" --timeout {}", o.call_timeout_s);
  if (!o.verse_bone_form.empty()) out += " --verse-bone-form " + shell_quote(o.verse_bone_form);
  if (!o.host_cmd.empty()) out += " --host-cmd " + shell_quote(o.host_cmd);
  return out;
}

// libFuzzer's exit status when the target stopped at a finding (its default
// -error_exitcode).
constexpr int kLibFuzzerFindingExit = 77;

// Plain-mode rounds of a live implementation's campaign (see run_campaign):
// while libFuzzer stopped at a finding and a second or more of --time
// is left, it runs again on the same corpus with the next seed. Returns
// the last round's result with the CPU time of all of them.
ChildRun run_more_rounds(std::vector<std::string> argv, const std::vector<std::string>& env_add,
                          std::chrono::steady_clock::time_point deadline,
                          const std::function<void(const std::string&)>& on_line, const CampaignOptions& o,
                          std::chrono::steady_clock::time_point t0, ChildRun rr, Progress* p,
                          long long* execs_before, std::ofstream* log) {
  using clock = std::chrono::steady_clock;
  for (unsigned round = 1; !rr.killed && rr.exit != 0; ++round) {
    const double left = o.time_s - std::chrono::duration<double>(clock::now() - t0).count();
    // No time left, or the round could not start: it ran nothing and did not
    // stop at a finding. A round that stopped at a finding before its first
    // progress line (an input of the corpus's first pass failing: a live
    // host's failure that depends on its history) did run: go on.
    if (left < 1 || (p->execs == 0 && rr.exit != kLibFuzzerFindingExit)) break;
    *execs_before += p->execs;
    p->execs = 0;
    for (std::string& a : argv) {
      if (a.rfind("-max_total_time=", 0) == 0) a = "-max_total_time=" + std::to_string(std::max(1LL, static_cast<long long>(left)));
      if (a.rfind("-seed=", 0) == 0) a = "-seed=" + std::to_string(o.seed + round);
    }
    *log << "vgc fuzz: libFuzzer stopped (exit " << rr.exit << ", a finding): round " << round + 1 << ", seed "
         << o.seed + round << ", " << static_cast<long long>(left) << " s left\n";
    const double cpu = rr.cpu_s;
    rr = run_streaming(argv, env_add, deadline, on_line, {});
    rr.cpu_s += cpu;
  }
  return rr;
}

}  // namespace campaign_steps

using namespace campaign_steps;

std::string stream_to_text(const std::string& bytes) {
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  std::vector<Command> cs;
  std::size_t pos = 0;
  DecodeStatus s = DecodeStatus::End;
  for (;;) {
    Command c;
    s = decode_command(data, bytes.size(), &pos, &c);
    if (s != DecodeStatus::Ok) break;
    cs.push_back(std::move(c));
  }
  std::string out = print_commands(cs);
  if (s != DecodeStatus::End)
    out += fmt::format("# the last {} bytes do not decode ({}) and were not run\n", bytes.size() - pos,
                       decode_status_name(s));
  return out;
}

std::string campaign_source_dir(const CampaignOptions& o) { return source_dir(o).string(); }
std::string campaign_fuzz_build_dir(const CampaignOptions& o) { return fuzz_build_dir(o).string(); }

namespace campaign_steps {


// The target's own counterexample block ("----8<---- counterexample.vgc"
// or, for the mesh targets, "----8<---- mesh.txt") in its output.
std::optional<std::string> printed_block(const CampaignRun& r, const std::string& output) {
  const std::string open = r.mesh ? "----8<---- mesh.txt\n" : "----8<---- counterexample.vgc\n";
  if (auto a = output.find(open); a != std::string::npos)
    if (auto b = output.find("----8<----\n", a + open.size()); b != std::string::npos)
      return output.substr(a + open.size(), b - a - open.size());
  return std::nullopt;
}

// Re-runs one input through the target alone (its output, stdout and stderr).
std::string rerun_input(const CampaignRun& r, const fs::path& f) {
  // A live implementation's input also starts it (a process, a login) and
  // confirms a crash on a fresh instance inside the target: more time.
  return run_capture(std::string(!r.impl.live ? "timeout 5" : "timeout 60") + " env " +
                     env_prefix(r.target_env) + shell_quote(r.binary.string()) + " " + shell_quote(f.string()) +
                     " 2>&1");
}

// The target's name, --time, --baseline, the binary and --impl, checked
// before anything runs; fills the run's name, paths and environments.
// Returns 0, or the exit code 2 with a message on stderr.
int check_campaign_options(CampaignRun* r) {
  const CampaignOptions& o = r->o;
  r->name = normalize_target(o.target);
  const std::string& name = r->name;
  r->property = name.rfind("property_", 0) == 0;
  static const char* const kGroups[] = {"layers", "polygons", "creases", "bones", "values", "ids", "commands"};
  bool known_group = false;
  for (const char* g : kGroups) known_group = known_group || name == std::string("property_") + g;
  r->mesh = name == "mesh_manifold" || name == "mesh_subdivision";
  if (name != "stream" && name != "text" && name != "differential" && name != "verse_packet" && !r->mesh &&
      !known_group) {
    fmt::print(stderr,
               "vgc fuzz: unknown target '{}': expected stream, text, differential, verse_packet, mesh_manifold, "
               "mesh_subdivision or property_<group> "
               "(layers, polygons, creases, bones, values, ids, commands)\n",
               o.target);
    return 2;
  }
  if (!(o.time_s > 0)) {
    fmt::print(stderr, "vgc fuzz: --time must be a positive number of seconds\n");
    return 2;
  }
  if (!o.baseline.empty()) {
    std::string error;
    if (!load_baseline(o.baseline, &r->baseline, &error)) {
      fmt::print(stderr, "vgc fuzz: --baseline: {}\n", escape_unprintable(error));
      return 2;
    }
  }
  const std::string target = "fuzz_" + name;
  r->src = fs::absolute(source_dir(o));
  const fs::path fbuild = fuzz_build_dir(o);
  r->binary = fbuild / "fuzz" / target;
  if (!fs::exists(r->binary)) {
    fmt::print(stderr,
               "vgc fuzz: no libFuzzer binary {}\n"
               "  `./vgc fuzz ...` builds it; by hand: CC=clang CXX=clang++ cmake -S {} -B {} -DVGC_FUZZ=ON"
               " && cmake --build {} --target {}\n",
               r->binary.string(), r->src.string(), fbuild.string(), fbuild.string(), target);
    return 2;
  }
  // The implementation under test and the variables that tell the target.
  if (!choose_implementation(o, name, r->property, &r->impl)) return 2;
  r->plugin = r->impl.plugin;
  r->env_add = r->impl.env;
  // Every VGC_* variable the target runs with: ours (VGC_FAULT,
  // VGC_FUZZ_MESH_FAULT, ...) and the implementation's (the plugin's path,
  // a live implementation's spec and options).
  r->run_env = vgc_environment();
  r->run_env.erase(std::remove_if(r->run_env.begin(), r->run_env.end(), is_implementation_variable), r->run_env.end());
  r->target_env = r->run_env;
  r->target_env.insert(r->target_env.end(), r->env_add.begin(), r->env_add.end());
  std::sort(r->target_env.begin(), r->target_env.end());
  CampaignSummary& s = r->s;
  s.target = target;
  s.seed = o.seed;
  s.jobs = std::max(1, o.jobs);
  s.time_s = o.time_s;
  s.binary = r->binary.string();
  s.implementation = r->impl.spec();
  s.environment = r->target_env;
  s.empty_corpus = o.empty_corpus;
  s.stop_at_first = o.stop_at_first;
  s.baseline = o.baseline;
  return 0;
}

// The run's directory, claimed with one mkdir: two campaigns of the same
// target and seed started in the same second (a script running seeds or
// faults side by side) get -2, -3, ... instead of sharing one directory
// (they did, and one of them aborted). Then its corpus: the committed one
// and the extra corpora. Returns 0, or 2 with a message.
int claim_run_directory(CampaignRun* r) {
  const CampaignOptions& o = r->o;
  CampaignSummary& s = r->s;
  const fs::path runs = r->src / "reports" / "fuzz" / s.target;
  const std::string stamp = utc_stamp() + "-seed" + std::to_string(o.seed);
  std::error_code ec;
  fs::create_directories(runs, ec);
  s.run = stamp;
  for (int k = 2; !ec && !fs::create_directory(runs / s.run, ec) && !ec; ++k) s.run = stamp + "-" + std::to_string(k);
  if (ec) {
    fmt::print(stderr, "vgc fuzz: cannot create a run directory under {}: {}\n", runs.string(), ec.message());
    return 2;
  }
  r->dir = runs / s.run;
  s.run_dir = r->dir.string();
  r->corpus = r->dir / "corpus", r->crashes = r->dir / "crashes", r->cex = r->dir / "counterexamples";
  fs::create_directories(r->corpus, ec);
  if (!ec) fs::create_directories(r->crashes, ec);
  if (!ec) fs::create_directories(r->cex, ec);
  if (ec) {
    fmt::print(stderr, "vgc fuzz: cannot create {}: {}\n", r->dir.string(), ec.message());
    return 2;
  }
  const fs::path committed = r->src / "corpora" / "fuzz" / s.target;
  if (!o.empty_corpus && fs::is_directory(committed))
    for (const auto& e : fs::directory_iterator(committed))
      if (e.is_regular_file()) {
        fs::copy_file(e.path(), r->corpus / e.path().filename(), fs::copy_options::overwrite_existing, ec);
        ++s.seed_files;
      }
  for (const std::string& extra : o.extra_corpora)
    if (fs::is_directory(extra, ec))
      for (const auto& e : fs::directory_iterator(extra, ec))
        if (e.is_regular_file())
          fs::copy_file(e.path(), r->corpus / e.path().filename(), fs::copy_options::skip_existing, ec);
  return 0;
}

// A live implementation the target starts itself: an exec: program, or a
// Verse host with --host-cmd (its coverage can be taken).
bool started_by_vgc(const CampaignRun& r) {
  return r.impl.live_on(RouteKind::Exec) || (r.impl.live_on(RouteKind::Verse) && !r.o.host_cmd.empty());
}

// A live implementation with one job runs libFuzzer's plain mode in
// rounds: restarted on the same corpus after each finding until --time is
// spent (a fork-mode job logs in again every few seconds and first re-runs
// its share of the corpus: 50 instead of 140 exec/s against `vgc serve
// --verse`; docs/fuzzing.md "Throughput of a live implementation").
bool live_rounds(const CampaignRun& r) { return r.impl.live && r.s.jobs == 1 && !r.o.stop_at_first; }

// libFuzzer's command line. One job stopping at the first finding runs
// libFuzzer in its plain mode, which stops there by itself (so do the
// rounds of a live implementation); otherwise fork mode (-fork=N).
std::vector<std::string> libfuzzer_argv(const CampaignRun& r) {
  const CampaignOptions& o = r.o;
  const bool rounds = live_rounds(r);
  const bool plain = (o.stop_at_first && r.s.jobs == 1) || rounds;
  std::vector<std::string> argv = {r.binary.string(),
                                   plain ? "-runs=-1" : "-fork=" + std::to_string(r.s.jobs),
                                   "-max_total_time=" + std::to_string(std::max(1LL, static_cast<long long>(o.time_s))),
                                   "-seed=" + std::to_string(o.seed),
                                   "-artifact_prefix=" + r.crashes.string() + "/",
                                   "-print_final_stats=1",
                                   "-max_len=" + std::to_string(o.max_len),
                                   // An input still running after 10 s is a hang, saved as
                                   // a timeout-* finding (libFuzzer's default waits 20 min,
                                   // longer than most campaigns). A live implementation's
                                   // own hangs are bounded by the call time-out and
                                   // confirmed on a fresh instance inside the input: more time.
                                   !r.impl.live ? "-timeout=10" : "-timeout=120"};
  if (!o.stop_at_first && !rounds) argv.insert(argv.begin() + 2, "-ignore_crashes=1");
  // A live implementation runs in its own process: what LeakSanitizer could
  // find in the fuzzer is the adapter's state, which outlives every input
  // on purpose (its process or session, the recent history for confirming
  // a crash), so libFuzzer saw more mallocs than frees on nearly every
  // input and ran a leak scan each time: 27% of the time against `vgc
  // serve --verse`, 206 instead of 1200 exec/s against `vgc serve` over
  // exec (docs/fuzzing.md "Throughput of a live implementation").
  if (r.impl.live) argv.push_back("-detect_leaks=0");
  const fs::path dict = r.src / "corpora" / "fuzz" / (r.s.target + ".dict");
  if (fs::exists(dict)) argv.push_back("-dict=" + dict.string());
  argv.push_back(r.corpus.string());
  return argv;
}

// Runs libFuzzer until --time (and its grace) with progress on stderr or
// o.progress, its output into fuzzer.log.
void run_libfuzzer(CampaignRun* r) {
  const CampaignOptions& o = r->o;
  CampaignSummary& s = r->s;
  const std::vector<std::string> argv = libfuzzer_argv(*r);
  // --stop-at-first in fork mode: the campaign stops the jobs itself once
  // a crash input is saved (one plain job stops there by itself). Saved
  // means written whole: not empty and untouched for a second. Stopping at
  // the first directory entry killed libFuzzer between its fopen and its
  // fwrite now and then, which left an empty input that replayed to
  // nothing ("did not reproduce").
  std::function<bool()> stop_now;
  if (o.stop_at_first && !(s.jobs == 1))
    stop_now = [crashes = r->crashes] {
      std::error_code e;
      const auto now = fs::file_time_type::clock::now();
      for (const auto& f : fs::directory_iterator(crashes, e)) {
        std::error_code fe;
        if (!f.is_regular_file(fe) || f.file_size(fe) == 0 || fe) continue;
        const auto written = f.last_write_time(fe);
        if (!fe && now - written >= std::chrono::seconds(1)) return true;
      }
      return false;
    };
  std::string cmdline;
  for (const auto& a : argv) cmdline += (cmdline.empty() ? "" : " ") + shell_quote(a);
  cmdline = env_prefix(r->target_env) + cmdline;
  s.command = cmdline;
  if (!o.quiet)
    fmt::print(stderr, "vgc fuzz: {} for {} s, {} job(s), seed {}, {} seed inputs\n  run: {}\n  {}\n", s.target,
               o.time_s, s.jobs, o.seed, s.seed_files, r->dir.string(), cmdline);

  std::ofstream log(r->dir / "fuzzer.log");
  Progress& p = r->progress;
  r->t0 = clock::now();
  r->sys0 = fs::file_time_type::clock::now();
  const auto t0 = r->t0;
  // libFuzzer is asked to stop at --time; it gets 5 s (grace_s) more to
  // write its final stats, then its process group is killed.
  const double grace = o.grace_s > 0 ? o.grace_s : 5;
  const auto deadline = t0 + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(o.time_s + grace));
  auto last_print = t0 - std::chrono::seconds(60);
  const auto on_line = [&](const std::string& line) {
    log << line << '\n';
    if (!parse_progress(line, &p)) return;
    const auto now = clock::now();
    const double t = std::chrono::duration<double>(now - t0).count();
    r->samples.push_back({t, p.execs + r->execs_before, p.cov, p.ft, p.corp});
    const std::string figures = fmt::format("execs {}  exec/s {}  cov {}  ft {}  corpus {}  crashes {}",
                                            p.execs + r->execs_before, p.exec_s, p.cov, p.ft, p.corp, p.crashes);
    if (o.progress) {
      o.progress(fmt::format("{} for {:.0f} s: {}", s.target, o.time_s, figures));
    } else if (!o.quiet && now - last_print >= std::chrono::seconds(10)) {
      fmt::print(stderr, "[{:5.0f}/{:.0f} s] {}\n", t, o.time_s, figures);
      last_print = now;
    }
  };
  // The coverage records of an implementation vgc starts go to the run's
  // directory (for the fuzzing only: a re-run of a saved input adds nothing
  // to them); so does the output of a host started by --host-cmd.
  std::vector<std::string> env = r->env_add;
  if (started_by_vgc(*r) && o.impl_coverage != "off") {
    std::error_code ec;
    fs::create_directories(r->dir / "implementation_coverage", ec);
    env.push_back("VGC_FUZZ_IMPL_COVERAGE_DIR=" + (r->dir / "implementation_coverage").string());
  }
  if (!o.host_cmd.empty()) env.push_back("VGC_FUZZ_HOST_LOG=" + (r->dir / "host.log").string());
  r->fuzzed = run_streaming(argv, env, deadline, on_line, stop_now, o.cpu_time_s);
  if (live_rounds(*r))
    r->fuzzed = run_more_rounds(argv, env, deadline, on_line, o, t0, r->fuzzed, &p, &r->execs_before, &log);
  const ChildRun& rr = r->fuzzed;
  if (rr.killed) log << "vgc fuzz: still running " << o.time_s + grace << " s after the start: process group killed\n";
  log.close();
  if (o.progress) o.progress("");
  s.libfuzzer_exit = rr.exit;
  s.killed_at_deadline = rr.killed;
  s.cpu_s = rr.cpu_s;
  s.cpu_budget_spent = rr.cpu_spent;
  if (rr.killed) fmt::print(stderr, "vgc fuzz: libFuzzer overran --time {} s: killed\n", o.time_s);
}

// The findings grouped by clause ("" last), and the count of new ones.
void group_by_clause(CampaignRun* r) {
  CampaignSummary& s = r->s;
  std::map<std::string, CampaignClause> by_clause;
  for (std::size_t i = 0; i < s.crashes.size(); ++i) {
    const CampaignCrash& c = s.crashes[i];
    CampaignClause& g = by_clause[c.clause];
    g.clause = c.clause;
    g.level = c.level;
    g.in_baseline = c.in_baseline;
    if (c.in_baseline) g.baseline_reason = r->baseline.reasons.at(c.clause);
    g.crashes.push_back(i);
    g.inputs += c.inputs;
    if (c.first_seen_s && (!g.first_seen_s || *c.first_seen_s < *g.first_seen_s)) g.first_seen_s = c.first_seen_s;
    if (!c.in_baseline) ++s.new_crashes;
  }
  for (auto& [id, g] : by_clause)
    if (!id.empty()) s.clauses.push_back(std::move(g));
  if (by_clause.count("")) s.clauses.push_back(std::move(by_clause[""]));
}

// The corpus and speed figures of the summary.
void count_corpus_and_speed(CampaignRun* r) {
  CampaignSummary& s = r->s;
  const Progress& p = r->progress;
  for (const auto& e : fs::directory_iterator(r->corpus))
    if (e.is_regular_file()) {
      ++s.corpus_files;
      s.corpus_bytes += e.file_size();
    }
  s.wall_s = std::chrono::duration<double>(clock::now() - r->t0).count();
  s.executions = p.execs + r->execs_before;
  s.exec_per_s_last = p.exec_s;
  s.cov = p.cov;
  s.ft = p.ft;
  const double grace = r->o.grace_s > 0 ? r->o.grace_s : 5;
  const double fuzz_wall = std::min(s.wall_s, r->o.time_s + grace);
  s.exec_per_s_mean = fuzz_wall > 0 ? static_cast<double>(s.executions) / fuzz_wall : 0.0;
}

// --coverage-report: the implementation's functions named
// (symbolize_functions.h), implementation_functions.md written, the ones
// never entered kept for the summary.
void write_function_report(CampaignRun* r, const CoverageTotals& t) {
  CampaignSummary& s = r->s;
  if (!t.seen) {
    s.coverage_report_note = "no report: the implementation's coverage was not seen";
    return;
  }
  if (t.functions.empty()) {
    s.coverage_report_note = "no report: the implementation has no PC table (build it with "
                             "-fsanitize-coverage=inline-8bit-counters,pc-table)";
    return;
  }
  std::string note;
  const std::vector<NamedFunction> named = symbolize_functions(t.functions, &note);
  const fs::path file = r->dir / "implementation_functions.md";
  if (!write_file(file, format_function_report(named, note))) {
    s.coverage_report_note = "cannot write " + file.string();
    return;
  }
  s.coverage_report = file.string();
  std::vector<const NamedFunction*> never;
  for (const NamedFunction& f : named)
    if (!f.entered) never.push_back(&f);
  std::sort(never.begin(), never.end(), [](const NamedFunction* a, const NamedFunction* b) { return place_before(*a, *b); });
  s.functions_never_entered_count = never.size();
  for (std::size_t i = 0; i < never.size() && i < 200; ++i)
    s.functions_never_entered.push_back(never[i]->name +
                                        (never[i]->location.empty() ? "" : " (" + never[i]->location + ")"));
  if (!note.empty()) s.coverage_report_note = note;
}

// The implementation's own coverage, from the records of the run's
// processes (coverage_record.h).
void count_implementation_coverage(CampaignRun* r) {
  CampaignSummary& s = r->s;
  if (r->impl.live_on(RouteKind::Verse)) s.impl_coverage_mode = "wire";
  if (!started_by_vgc(*r)) return;
  s.impl_coverage_mode = r->o.impl_coverage;
  if (r->o.impl_coverage == "off") return;
  const CoverageTotals t = merge_coverage_records((r->dir / "implementation_coverage").string());
  s.impl_coverage_seen = t.seen;
  s.impl_counters = t.counters;
  s.impl_counters_reached = t.reached;
  s.impl_function_entries = t.function_entries;
  s.impl_functions_entered = t.functions_entered;
  s.impl_counters_dropped = t.dropped;
  s.impl_modules = t.modules;
  // The records' clock (the epoch) on the campaign's (seconds since its start).
  const double now_epoch =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  const double start_epoch = now_epoch - std::chrono::duration<double>(clock::now() - r->t0).count();
  for (const auto& [when, n] : t.timeline) s.impl_timeline.emplace_back(std::max(0.0, when - start_epoch), n);
  if (r->o.coverage_report) write_function_report(r, t);
}

// summary.json and summary.md (each written whole or not at all: a
// temporary file, then renamed) and report.html. Returns 0, or 2.
int write_campaign_reports(CampaignRun* r) {
  const CampaignSummary& s = r->s;
  const std::string json = summary_json(s), md = summary_markdown(s);
  std::error_code ec;
  for (const auto& [file, text] : {std::pair{r->dir / "summary.json", json}, std::pair{r->dir / "summary.md", md}}) {
    fs::path tmp = file;
    tmp += ".tmp";
    if (!write_file(tmp, text)) {
      fmt::print(stderr, "vgc fuzz: cannot write {}\n", file.string());
      return 2;
    }
    fs::rename(tmp, file, ec);
  }
  // report.html: the same figures as a page, with coverage and corpus over time.
  CampaignReport page;
  page.target = s.target, page.run = s.run, page.command = s.command, page.implementation = s.implementation;
  page.seed = s.seed, page.jobs = s.jobs, page.time_s = s.time_s, page.wall_s = s.wall_s;
  page.executions = s.executions, page.exec_per_s_last = s.exec_per_s_last, page.exec_per_s_mean = s.exec_per_s_mean;
  page.coverage = s.cov, page.features = s.ft, page.corpus_files = s.corpus_files, page.corpus_bytes = s.corpus_bytes;
  page.seed_files = s.seed_files, page.crash_inputs = s.crash_inputs, page.samples = std::move(r->samples);
  if (!s.impl_coverage_mode.empty()) page.implementation_coverage = implementation_coverage_line(s);
  page.function_report = s.coverage_report;
  page.functions_never_entered = s.functions_never_entered;
  page.functions_never_entered_count = s.functions_never_entered_count;
  for (const auto& [t, n] : s.impl_timeline) {
    CampaignSample p;
    p.seconds = t;
    p.coverage = static_cast<long long>(n);
    page.implementation_samples.push_back(p);
  }
  for (const CampaignCrash& c : s.crashes) {
    CampaignFinding f;
    f.signature = c.signature, f.also = c.also, f.inputs = c.inputs, f.counterexample = c.counterexample;
    f.replay = c.replay, f.replay_fuzzer = c.replay_fuzzer;
    std::ifstream in(c.counterexample, std::ios::binary);
    f.counterexample_text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    page.findings.push_back(std::move(f));
  }
  if (std::string error; !write_campaign_html(r->dir.string(), page, &error)) fmt::print(stderr, "vgc fuzz: {}\n", error);
  if (!r->o.quiet) {
    fmt::print("{}", md);
    fmt::print("summary: {}\n", (r->dir / "summary.json").string());
  }
  return 0;
}

}  // namespace campaign_steps

int run_campaign(const CampaignOptions& o, CampaignSummary* out) {
  CampaignRun r(o);
  if (int rc = check_campaign_options(&r)) return rc;
  if (int rc = claim_run_directory(&r)) return rc;
  run_libfuzzer(&r);
  std::map<std::string, CrashGroup> unique = sign_crash_inputs(&r);
  write_findings(&r, unique);
  group_by_clause(&r);
  count_corpus_and_speed(&r);
  count_implementation_coverage(&r);
  if (int rc = write_campaign_reports(&r)) return rc;
  const bool ran_nothing = r.progress.execs == 0 && r.s.crash_inputs == 0;
  if (out) *out = r.s;
  if (ran_nothing) {
    fmt::print(stderr, "vgc fuzz: libFuzzer ran no inputs (exit {}); see {}\n", r.fuzzed.exit,
               (r.dir / "fuzzer.log").string());
    return 2;
  }
  return r.s.new_crashes == 0 ? 0 : 1;
}

// The run directories' time stamp (UTC, to the second).
std::string utc_stamp() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%dT%H%M%SZ", &tm);
  return buf;
}

}  // namespace vgc::fuzz
