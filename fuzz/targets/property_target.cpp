// property_target.cpp — a conformance property as a coverage-guided fuzz target.
//
// Spec: the clauses the property checks (conformance/property.h,
// docs/clauses.md).
//
// Rationale: RapidCheck draws a property's choices from a seeded random
// source; libFuzzer evolves byte strings by coverage. conformance/byte_cases.h
// joins them: every 9 bytes of input are the seed and size from which the
// property's own state-aware generator draws the next command, so a campaign
// explores exactly the command sequences the property would, steered by
// coverage. Each command is checked against the reference as certify checks
// it (check_step: applied or rejected, snapshot, derived document); the
// first MUST-level finding prints the command sequence as a command file
// and aborts. That file replays like any certify counterexample:
//   vgc replay FILE --impl plugin:PATH
//
// One binary per property: VGC_FUZZ_PROPERTY names it ("layers.stateful").
// The implementation under test is the plugin named by VGC_FUZZ_PLUGIN,
// loaded in process (no isolation: libFuzzer records its crashes); unset,
// it is the reference itself, and the target checks the reference and the
// check machinery for crashes and undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "byte_cases.h"
#include "clause.h"
#include "report_finding.h"
#include "implementation.h"
#include "reference_implementation.h"
#include "route.h"

#if !defined(VGC_FUZZ_PROPERTY) || !defined(VGC_FUZZ_TARGET)
#error "VGC_FUZZ_PROPERTY must name a property of conformance/property_catalog.cpp, VGC_FUZZ_TARGET the binary"
#endif

namespace {

constexpr const char* kProperty = VGC_FUZZ_PROPERTY;
std::unique_ptr<vgc::Implementation> g_sut;
vgc::Focus g_focus = vgc::Focus::Anything;
vgc::DrawMemo g_memo;  // the previous input's draws (byte_cases.h): same commands, drawn once

void init() {
  if (!vgc::focus_of_property(kProperty, &g_focus)) {
    std::fprintf(stderr, "vgc-fuzz: unknown property %s\n", kProperty);
    std::abort();
  }
  const char* plugin = std::getenv("VGC_FUZZ_PLUGIN");
  if (plugin && *plugin) {
    vgc::OpenOptions o;
    o.isolate_plugin = false;
    std::string error;
    g_sut = vgc::open_implementation(vgc::route_spec(vgc::RouteKind::Plugin, plugin), o, &error);
    if (!g_sut) {
      std::fprintf(stderr, "vgc-fuzz: %s\n", error.c_str());
      std::exit(2);
    }
  } else {
    g_sut = std::make_unique<vgc::ReferenceImplementation>();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (!g_sut) init();
  std::vector<vgc::Command> program;
  if (auto f = vgc::check_byte_case(data, size, g_focus, *g_sut, &program, &g_memo)) {
    const vgc::Clause* clause = vgc::find_clause(f->clause);
    const std::string what = std::string(kProperty) + ": " + f->clause + " (" +
                             std::string(clause ? vgc::clause_level_name(clause->level) : "?") + ", " +
                             vgc::finding_status_name(f->status) + "): " + f->message;
    vgc::fuzz::report_finding(VGC_FUZZ_TARGET, what, program);
  }
  // Leave nothing behind: the implementation's node would outlive the run,
  // and libFuzzer takes a run that ends with more allocations than frees
  // for a possible leak, runs it again and asks LeakSanitizer (up to 1,000
  // times a campaign: a fifth of the CPU, measured).
  g_sut->reset();
  return 0;
}
