// capability_test.cpp — the optional capabilities (issue 4 item 7): the
// reference claims and passes both on every route, an implementation that
// claims nothing gets "not-claimed" and stays conformant, and the seeded
// capability faults are caught naming their clause. The oracle checks are
// registered for this whole test binary (runner tests included), as
// `vgc certify` registers them.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "capability.h"
#include "capability_checks.h"
#include "command_text.h"
#include "exec_implementation.h"
#include "faulty_implementation.h"
#include "implementation.h"
#include "reference_implementation.h"
#include "report.h"
#include "runner.h"
#include "verdict.h"

namespace vgc {
namespace {

const bool kRegistered = (register_capability_checks(), true);

RunOptions capability_options() {
  RunOptions o;
  o.seed = 7;
  o.cases = 60;  // 15 cases per capability property
  o.budget_seconds = 120;
  o.clause_glob = "MESH-CLASSIFY-1,SUBD-CATMARK-1";
  return o;
}

const ClauseOutcome* clause(const RunResult& run, std::string_view id) {
  for (const auto& co : run.clauses)
    if (co.clause->id == id) return &co;
  return nullptr;
}

std::vector<Command> cube_commands() {
  std::ifstream in(VGC_SOURCE_DIR "/corpora/examples/cube.vgc", std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  std::vector<Command> commands;
  TextError error;
  EXPECT_TRUE(parse_commands(ss.str(), &commands, &error)) << error.to_string();
  return commands;
}

// The reference with the capability requests switched off: an
// implementation that predates them.
class NoCapabilities final : public Implementation {
 public:
  std::string name() const override { return "no-capabilities"; }
  Answer reset() override { return ref_.reset(); }
  Answer apply(const Command& c) override { return ref_.apply(c); }
  Document snapshot() override { return ref_.snapshot(); }
  Document derived() override { return ref_.derived(); }

 private:
  ReferenceImplementation ref_;
};

TEST(Capability, TheReferenceClaimsBothAndPassesBoth) {
  ASSERT_TRUE(kRegistered);
  ReferenceImplementation impl;
  EXPECT_EQ(query_capabilities(impl), (std::vector<std::string>{"manifold", "subdivision"}));
  const RunResult run = run_certification(impl, capability_options());
  for (const char* id : {"MESH-CLASSIFY-1", "SUBD-CATMARK-1"}) {
    const ClauseOutcome* co = clause(run, id);
    ASSERT_NE(co, nullptr) << id;
    EXPECT_EQ(co->status, "pass") << id << ": " << (co->finding ? co->finding->message : co->note);
  }
  EXPECT_TRUE(run.conformant);
  EXPECT_TRUE(run.complete);
}

TEST(Capability, NotClaimedIsNeitherAFailureNorAGap) {
  NoCapabilities impl;
  EXPECT_TRUE(query_capabilities(impl).empty());
  const RunResult run = run_certification(impl, capability_options());
  for (const char* id : {"MESH-CLASSIFY-1", "SUBD-CATMARK-1"}) {
    const ClauseOutcome* co = clause(run, id);
    ASSERT_NE(co, nullptr) << id;
    EXPECT_EQ(co->status, "not-claimed") << id;
    EXPECT_FALSE(co->finding.has_value()) << id;
  }
  for (const auto& po : run.properties)
    if (po.id == "derived.manifold" || po.id == "derived.subdivision") {
      EXPECT_EQ(po.status, "skipped");
      EXPECT_EQ(po.note, "not claimed");
    }
  EXPECT_TRUE(run.conformant);
  EXPECT_TRUE(run.complete);
  const std::string summary = render_summary(run, judge(run, nullptr), ReportContext{});
  EXPECT_NE(summary.find("2 not claimed"), std::string::npos) << summary;
}

TEST(Capability, SeededCapabilityFaultsAreCaughtNamingTheirClause) {
  for (const char* name : {"subdivision-ignores-creases", "classify-misses-boundary"}) {
    const int fault = faults::find_fault(name);
    ASSERT_GE(fault, 0) << name;
    faults::FaultyImplementation impl(fault);
    const RunResult run = run_certification(impl, capability_options());
    const std::string expected(faults::fault_catalog()[static_cast<std::size_t>(fault)].expected_clause);
    const ClauseOutcome* co = clause(run, expected);
    ASSERT_NE(co, nullptr) << name;
    EXPECT_EQ(co->status, "fail") << name;
    EXPECT_FALSE(run.conformant) << name;
    if (co->finding) std::printf("%s: %s\n", name, co->finding->message.c_str());
  }
}

TEST(Capability, ServeAnswersTheRequestsForTheCube) {
  OpenOptions o;
  std::string error;
  auto impl = open_implementation("exec:" + shell_quote(VGC_BINARY) + " serve", o, &error);
  ASSERT_TRUE(impl) << error;
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  EXPECT_EQ(impl->request("?capabilities").text, "capabilities manifold subdivision\nend\n");
  for (const auto& c : cube_commands()) ASSERT_TRUE(impl->apply(c).applied);
  // The spec's cube (000 2.6.4): one closed, oriented surface of genus 0.
  EXPECT_EQ(impl->request("?classify").text,
            "vgc-classify 1\npolygon_mesh yes\nclosed yes\noriented yes\neuler 2\ncomponents 1\nboundary_loops 0\nend\n");
  // One Catmull-Clark step of a cube: 8 + 12 + 6 vertices, 24 quads.
  const Document sub = impl->request("?subdivide 1");
  ASSERT_EQ(sub.status, CallStatus::Ok) << sub.detail;
  std::size_t vertices = 0, pos = 0;
  while ((pos = sub.text.find("\nvertex ", pos)) != std::string::npos) ++vertices, ++pos;
  EXPECT_EQ(vertices, 26u);
  EXPECT_NE(sub.text.find("\nfaces 24\nend\n"), std::string::npos) << sub.text;
  const Document bad = impl->request("?subdivide 9");
  EXPECT_EQ(bad.status, CallStatus::Ok);
  EXPECT_EQ(bad.text.rfind("error ", 0), 0u) << bad.text;
}

TEST(Capability, ThePluginWithoutTheRequestSymbolClaimsNothing) {
  OpenOptions o;
  o.isolate_plugin = false;
  std::string error;
  auto plugin = open_implementation(std::string("plugin:") + VGC_FAULT_PLUGIN, o, &error);
  ASSERT_TRUE(plugin) << error;
  EXPECT_TRUE(query_capabilities(*plugin).empty());
  auto reference = open_implementation(std::string("plugin:") + VGC_REFERENCE_PLUGIN, o, &error);
  ASSERT_TRUE(reference) << error;
  EXPECT_EQ(query_capabilities(*reference), (std::vector<std::string>{"manifold", "subdivision"}));
}

TEST(Capability, ExecAndIsolatedPluginRoutesCertifyTheReferenceWithBoth) {
  OpenOptions o;
  o.vgc_binary = VGC_BINARY;
  for (const std::string spec : {"exec:" + shell_quote(VGC_BINARY) + " serve",
                                 std::string("plugin:") + VGC_REFERENCE_PLUGIN}) {
    std::string error;
    auto impl = open_implementation(spec, o, &error);
    ASSERT_TRUE(impl) << error;
    RunOptions ro = capability_options();
    ro.cases = 20;
    const RunResult run = run_certification(*impl, ro);
    for (const char* id : {"MESH-CLASSIFY-1", "SUBD-CATMARK-1"}) {
      const ClauseOutcome* co = clause(run, id);
      ASSERT_NE(co, nullptr) << spec << " " << id;
      EXPECT_EQ(co->status, "pass") << spec << " " << id << ": " << (co->finding ? co->finding->message : co->note);
    }
    EXPECT_TRUE(run.conformant) << spec;
    EXPECT_TRUE(run.complete) << spec;
  }
}

}  // namespace
}  // namespace vgc
