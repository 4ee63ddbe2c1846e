// fuzz_differential.cpp — the same command stream into the reference and
// into an implementation under test; the first divergence, named by clause.
//
// Spec: 000 section 2.6 as the reference reads it; the plugin C ABI of
// conformance/adapter/vgc_plugin.h; the clauses of the catalog
// (conformance/clause.h) as check_step attributes them.
//
// The implementation is the plugin named by the environment variable
// VGC_FUZZ_PLUGIN (a path; `vgc fuzz differential --impl plugin:PATH` sets
// it), loaded in process; or a live one, VGC_FUZZ_IMPL=exec:CMD or
// verse:HOST[:PORT] (`--impl exec:...|verse:...`, live_implementation.h),
// driven through the adapter `vgc certify` uses. Unset: the reference
// behind the same C ABI (reference_plugin_table.h), which still checks the
// text round trip of every command. Each command goes to the reference as a
// value and to the implementation as its print_command line (exec, plugin)
// or its wire encoding (verse).
//
// A crash or hang of a live implementation (a call answered Crash or
// Timeout; check_step names it "CLAUSE (MUST, crash)") is confirmed before
// it is reported, as certify confirms one (confirm_finding.h): the program
// is run again on a fresh instance (a new process; for a wire host, after
// VGC_FUZZ_RESTART). If it does not fail there, the finding is STABLE-1,
// history-dependent, its program the recent history of the instance
// reduced. A wire host with no restart command cannot be confirmed: the
// finding says so. A finding in a clause of VGC_FUZZ_BASELINE (a known
// deviation; not a crash or hang) is passed over. After a finding the
// input aborts (libFuzzer saves it);
// `vgc fuzz` runs libFuzzer with -fork and -ignore_crashes, so the
// campaign goes on with a new job and, for exec:, a new process.
//
// Coverage of the implementation (live_coverage.h): an exec: program, or
// a Verse host the target starts itself (VGC_FUZZ_HOST_CMD), built
// with clang's inline 8-bit counters and vgc's coverage runtime maps its
// counters into shared memory; they are cleared before each input and,
// after it, folded into g_implementation_counters, an array in libFuzzer's
// extra-counters section (its edges; with VGC_FUZZ_IMPL_COVERAGE=guide-counts
// their hit counts), so that an input reaching new code in the
// implementation is kept as one reaching new code in the reference is.
// Without such a program nothing is folded and everything is as before.
//
// Fast path, exact slow path (conformance/fast_check.h): per input, the
// answers are compared after every command (the call answered, the line was
// read, applied or rejected as the reference says) and the snapshot and
// derived documents once, at the end. Only on a difference is the input
// re-run step by step by check_step, the comparison `vgc certify` and `vgc
// replay` make, which names the first divergent command and the clause it
// breaks: the finding line is "CLAUSE (LEVEL, status): message" and the
// printed command file replays with `vgc replay FILE --impl plugin:PATH`
// to the same clause.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "clause_finding.h"
#include "command_binary.h"
#include "confirm_finding.h"
#include "fast_check.h"
#include "report_finding.h"
#include "implementation.h"
#include "live_coverage.h"
#include "live_implementation.h"
#include "plugin_implementation.h"
#include "reference_plugin_table.h"
#include "stream_mutator_hooks.h"

// libFuzzer reads every byte of this section after each input as a
// counter, beside the inline counters of the instrumented code, and
// clears it before the next (FuzzerExtraCounters.cpp, TracePC::ResetMaps).
// 64 Ki slots: an implementation with more counters shares slots
// (coverage_region.h); a larger array costs libFuzzer a scan per input.
__attribute__((section("__libfuzzer_extra_counters"), used)) std::uint8_t g_implementation_counters[1 << 16];

namespace {

constexpr const char* kTarget = "fuzz_differential";
std::unique_ptr<vgc::fuzz::LiveCoverage> g_coverage;  // a live exec: implementation's own coverage
std::unique_ptr<vgc::Implementation> g_sut;
vgc::fuzz::LiveOptions g_live;  // spec empty: a plugin or the reference, in process

// The inputs run on the live instance since it started (the last kHistory),
// for a crash that only its history explains (confirm_call_failure).
constexpr std::size_t kHistory = 64;
std::deque<std::vector<vgc::Command>> g_history;
std::uint64_t g_instance = 0;

void remember(const std::vector<vgc::Command>& commands) {
  if (g_sut->instance() != g_instance) {
    g_instance = g_sut->instance();
    g_history.clear();
  }
  g_history.push_back(commands);
  if (g_history.size() > kHistory) g_history.pop_front();
}

// A crash, hang or protocol error of a live implementation, confirmed on a
// fresh instance or rewritten as history-dependent (confirm_finding.h); on
// a route that cannot give a fresh instance, said to be unconfirmed.
void confirm(vgc::Finding* f, std::vector<vgc::Command>* commands) {
  using namespace vgc;
  if (g_live.spec.empty() || !is_call_failure(*f)) return;
  if (!fuzz::can_confirm_on_fresh_instance(g_live)) {
    f->message += " [not confirmed on a fresh instance: a Verse host is restarted only by the command given "
                  "with --restart CMD, or started by vgc with --host-cmd CMD]";
    return;
  }
  PropertyFinding pf;
  pf.finding = *f;
  pf.program = Program{*commands, std::nullopt};
  const std::vector<std::vector<Command>> history(g_history.begin(), g_history.end());
  if (confirm_call_failure(*g_sut, &pf, history, std::chrono::steady_clock::now() + std::chrono::seconds(30), 40))
    pf.finding.message += " [confirmed: the same on a fresh instance]";
  *f = pf.finding;
  *commands = pf.program.commands;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* path = std::getenv("VGC_FUZZ_PLUGIN");
  std::string error;
  g_live = vgc::fuzz::live_options_from_environment();
  if (!g_live.spec.empty()) {
    if (g_live.route)
      g_coverage = vgc::fuzz::LiveCoverage::for_implementation(*g_live.route, !g_live.host_cmd.empty(), kTarget);
    g_sut = vgc::fuzz::open_live_implementation(g_live, &error);
    if (g_sut && g_coverage) g_coverage->started();
  } else if (path && *path) {
    vgc::OpenOptions o;
    o.isolate_plugin = false;  // in process: a crash of the plugin is a crash of the fuzzer
    g_sut = vgc::open_implementation(vgc::route_spec(vgc::RouteKind::Plugin, path), o, &error);
  } else {
    g_sut = vgc::PluginImplementation::wrap(vgc::fuzz::reference_plugin_table(vgc::fuzz::PluginFault::None),
                                            "reference-plugin-table", &error);
  }
  if (!g_sut) {
    std::fprintf(stderr, "fuzz_differential: %s\n", error.c_str());
    std::exit(2);
  }
  std::fprintf(stderr, "fuzz_differential: reference vs %s\n", g_sut->identity().c_str());
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vgc;
  if (!g_sut) LLVMFuzzerInitialize(nullptr, nullptr);
  std::vector<Command> commands;
  std::size_t pos = 0;
  for (;;) {
    Command c;
    if (decode_command(data, size, &pos, &c) != DecodeStatus::Ok) break;
    commands.push_back(std::move(c));
  }
  if (!g_live.spec.empty()) remember(commands);
  if (g_coverage) g_coverage->before_input();
  // A route that carries no derived document (a host on the Verse wire) is
  // checked step by step from the start: the fast path compares a derived
  // document, which the route does not carry (RouteLimits), so every input
  // would take the exact path anyway, and after a host that died in the
  // fast pass there would be no host left to re-run on (the finding would be
  // the next login's timeout, unattributed).
  const bool exact = g_live.route && !g_live.route->traits().derived_documents;
  const ReplayResult r = exact ? check_program_exact(commands, *g_sut) : check_program_fast(commands, *g_sut).replay;
  if (r.failure) {
    const std::size_t upto = r.failed_at < 0 ? 0 : static_cast<std::size_t>(r.failed_at) + 1;
    commands.resize(std::min(upto, commands.size()));
    Finding f = *r.failure;
    // A known deviation of a live implementation (--baseline) is not a
    // finding to stop at: the input goes no further (the model and the
    // implementation disagree from here), and fuzzing goes on.
    const bool tolerated = g_live.tolerated.count(f.clause) > 0 && !is_call_failure(f);
    if (!tolerated) {
      confirm(&f, &commands);
      if (g_coverage) g_coverage->finish();  // the process ends in report_finding
      fuzz::report_finding(kTarget, fuzz::describe_clause_finding(f), commands);
    }
  }
  // The implementation's counters are the input's own: folded before the
  // reset, whose work (a fresh node; on the Verse wire a login again after
  // an input that broke the session) is the same for every input and is
  // cleared before the next one. Folded after it, r6's login and big-number
  // code looked new whenever an input broke the session, and guidance
  // steered towards inputs that do (docs/fuzzing.md, r6 measurements).
  if (g_coverage) g_coverage->after_input(g_implementation_counters, sizeof g_implementation_counters);
  // Leave nothing behind (see property_target.cpp): a node that outlives
  // the run makes libFuzzer re-run it as a possible leak.
  g_sut->reset();
  return 0;
}
