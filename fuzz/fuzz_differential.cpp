// fuzz_differential.cpp — the same command stream into the reference and
// into an implementation under test; stop at the first divergence.
//
// Spec: 000 section 2.6 as the reference reads it; the plugin C ABI of
// conformance/adapter/vgc_plugin.h; snapshot and derived documents of
// reference/snapshot.h ("two conforming nodes fed the same commands print
// the same snapshot byte for byte; their derived documents agree exactly on
// creases").
//
// The implementation is the plugin named by the environment variable
// VGC_FUZZ_PLUGIN (a path; `vgc fuzz differential --impl plugin:PATH` sets
// it), loaded in process. Unset: the reference behind the same C ABI
// (reference_plugin_table.h), which still checks the text round trip of every
// command. Each command goes to the reference as a value and to the plugin
// as its print_command line. After each command: the same applied/rejected
// answer (reasons may differ), the same snapshot text, the same effective
// creases (the vertex_crease and edge_crease lines of the derived
// document). Bone poses are compared by the conformance properties, within
// rounding, not here.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "command_binary.h"
#include "command_text.h"
#include "finding.h"
#include "node.h"
#include "plugin_node.h"
#include "reference_plugin_table.h"
#include "snapshot.h"
#include "stream_mutator_hooks.h"

namespace {

constexpr const char* kTarget = "fuzz_differential";
const vgc_plugin_v1_table* g_impl = nullptr;

// The crease lines of a derived document, in order.
std::string crease_lines(const char* doc) {
  std::string out;
  const std::string_view d(doc ? doc : "");
  std::size_t start = 0;
  while (start < d.size()) {
    std::size_t end = d.find('\n', start);
    if (end == std::string_view::npos) end = d.size();
    const std::string_view line = d.substr(start, end - start);
    if (line.rfind("vertex_crease ", 0) == 0 || line.rfind("edge_crease ", 0) == 0) {
      out += line;
      out += '\n';
    }
    start = end + 1;
  }
  return out;
}

// "line N: reference: ... / implementation: ..." for the first difference.
std::string first_difference(const std::string& a, const std::string& b) {
  std::size_t line = 1, start = 0;
  for (;;) {
    const std::size_t ea = a.find('\n', start), eb = b.find('\n', start);
    const std::string la = start < a.size() ? a.substr(start, ea - start) : "<end of document>";
    const std::string lb = start < b.size() ? b.substr(start, eb - start) : "<end of document>";
    if (la != lb)
      return "line " + std::to_string(line) + ": reference \"" + la + "\", implementation \"" + lb + "\"";
    if (ea == std::string::npos || eb == std::string::npos) return "documents differ";
    start = ea + 1;
    ++line;
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* path = std::getenv("VGC_FUZZ_PLUGIN");
  if (path && *path) {
    std::string error;
    g_impl = vgc::fuzz::load_plugin(path, &error);
    if (!g_impl) {
      std::fprintf(stderr, "fuzz_differential: %s\n", error.c_str());
      std::exit(2);
    }
  } else {
    g_impl = vgc::fuzz::reference_plugin_table(vgc::fuzz::PluginFault::None);
  }
  std::fprintf(stderr, "fuzz_differential: reference vs %s\n", g_impl->name ? g_impl->name : "(unnamed)");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vgc;
  if (!g_impl) LLVMFuzzerInitialize(nullptr, nullptr);
  Node ref;
  vgc_node* impl = g_impl->create();
  if (!impl) fuzz::report_finding(kTarget, "the implementation's create() returned null", {});
  std::vector<Command> done;
  std::size_t pos = 0;
  for (;;) {
    Command c;
    if (decode_command(data, size, &pos, &c) != DecodeStatus::Ok) break;
    done.push_back(c);
    const std::string line = print_command(c);
    const Reason r = ref.apply(c);
    const char* reason = nullptr;
    const int answer = g_impl->apply(impl, line.c_str(), &reason);
    const std::string said = reason ? reason : "";
    if (answer == VGC_MALFORMED)
      fuzz::report_finding(kTarget, "the implementation could not parse a canonical line: " + said, done);
    if (answer != VGC_APPLIED && answer != VGC_REJECTED)
      fuzz::report_finding(kTarget, "the implementation answered " + std::to_string(answer), done);
    if ((r == Reason::Ok) != (answer == VGC_APPLIED))
      fuzz::report_finding(kTarget,
                           std::string("reference ") +
                               (r == Reason::Ok ? "applied" : "rejected (" + std::string(reason_name(r)) + ")") +
                               ", implementation " + (answer == VGC_APPLIED ? "applied" : "rejected (" + said + ")"),
                           done);
    const std::string ref_snapshot = print_snapshot(ref);
    const char* impl_snapshot = g_impl->snapshot(impl);
    if (!impl_snapshot || ref_snapshot != impl_snapshot)
      fuzz::report_finding(kTarget, "snapshots differ, " + first_difference(ref_snapshot, impl_snapshot ? impl_snapshot : ""),
                           done);
    const std::string ref_creases = crease_lines(print_derived(ref).c_str());
    const std::string impl_creases = crease_lines(g_impl->derived(impl));
    if (ref_creases != impl_creases)
      fuzz::report_finding(kTarget, "derived creases differ, " + first_difference(ref_creases, impl_creases), done);
  }
  g_impl->destroy(impl);
  return 0;
}
