// fuzz_differential.cpp — the same command stream into the reference and
// into an implementation under test; the first divergence, named by clause.
//
// Spec: 000 section 2.6 as the reference reads it; the plugin C ABI of
// conformance/adapter/vgc_plugin.h; the clauses of the catalog
// (conformance/clause.h) as check_step attributes them.
//
// The implementation is the plugin named by the environment variable
// VGC_FUZZ_PLUGIN (a path; `vgc fuzz differential --impl plugin:PATH` sets
// it), loaded in process. Unset: the reference behind the same C ABI
// (reference_plugin_table.h), which still checks the text round trip of every
// command. Each command goes to the reference as a value and to the plugin
// as its print_command line.
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
#include <memory>
#include <string>
#include <vector>

#include "clause_finding.h"
#include "command_binary.h"
#include "fast_check.h"
#include "finding.h"
#include "implementation.h"
#include "plugin_implementation.h"
#include "reference_plugin_table.h"
#include "stream_mutator_hooks.h"

namespace {

constexpr const char* kTarget = "fuzz_differential";
std::unique_ptr<vgc::Implementation> g_sut;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* path = std::getenv("VGC_FUZZ_PLUGIN");
  std::string error;
  if (path && *path) {
    vgc::OpenOptions o;
    o.isolate_plugin = false;  // in process: a crash of the plugin is a crash of the fuzzer
    g_sut = vgc::open_implementation(std::string("plugin:") + path, o, &error);
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
  const ReplayResult r = check_program_fast(commands, *g_sut).replay;
  if (r.failure) {
    const std::size_t upto = r.failed_at < 0 ? 0 : static_cast<std::size_t>(r.failed_at) + 1;
    commands.resize(std::min(upto, commands.size()));
    fuzz::report_finding(kTarget, fuzz::describe_clause_finding(*r.failure), commands);
  }
  // Leave nothing behind (see property_target.cpp): a node that outlives
  // the run makes libFuzzer re-run it as a possible leak.
  g_sut->reset();
  return 0;
}
