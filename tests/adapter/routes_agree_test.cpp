// routes_agree_test.cpp — the four routes to our own node (in process,
// exec:'vgc serve', the reference plugin isolated and in process) give the
// same answers and the same snapshot and derived documents, byte for byte,
// on the cube and on random command sequences. Any difference is a bug in
// a route (a codec, the protocol, the adapter), since the node is the same.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "adapter_test_util.h"
#include "arbitrary_command.h"

namespace vgc::test {
namespace {

struct Route {
  std::string label;
  std::unique_ptr<Implementation> impl;
};

// Opened once for the whole test program; reset() between cases.
std::vector<Route>& routes() {
  static std::vector<Route> r = [] {
    std::vector<Route> out;
    const std::vector<std::pair<std::string, bool>> specs = {
        {"reference", true},
        {vgc_serve_spec(), true},
        {"plugin:" + std::string(VGC_REFERENCE_PLUGIN), true},   // isolated: vgc serve --impl plugin:...
        {"plugin:" + std::string(VGC_REFERENCE_PLUGIN), false},  // in process
    };
    for (const auto& [spec, isolate] : specs) {
      OpenOptions o = test_options();
      o.isolate_plugin = isolate;
      std::string error;
      std::unique_ptr<Implementation> impl = open_implementation(spec, o, &error);
      EXPECT_NE(impl, nullptr) << spec << ": " << error;
      if (impl) out.push_back({spec + (isolate ? "" : " (in process)"), std::move(impl)});
    }
    return out;
  }();
  return r;
}

struct Transcript {
  std::vector<std::string> answers;
  std::string snapshot;
  std::string derived;
};

Transcript run(Implementation& impl, const std::vector<Command>& cs) {
  Transcript t;
  t.answers.push_back("reset " + answer_text(impl.reset()));
  for (const Command& c : cs) t.answers.push_back(answer_text(impl.apply(c)));
  const Document s = impl.snapshot();
  const Document d = impl.derived();
  t.snapshot = s.status == CallStatus::Ok ? s.text : std::string(call_status_name(s.status)) + ": " + s.detail;
  t.derived = d.status == CallStatus::Ok ? d.text : std::string(call_status_name(d.status)) + ": " + d.detail;
  return t;
}

TEST(RoutesAgree, AllFourRoutesOpen) { EXPECT_EQ(routes().size(), 4u); }

TEST(RoutesAgree, OnTheCube) {
  const std::vector<Command> cube = cube_commands();
  ASSERT_EQ(cube.size(), 16u);  // 8 vertices, 6 polygons, 2 crease defaults (spec 2.6.4)
  ASSERT_FALSE(routes().empty());
  const Transcript want = run(*routes()[0].impl, cube);
  // The cube applies completely, and its snapshot is the golden one.
  for (std::size_t i = 1; i < want.answers.size(); ++i) EXPECT_EQ(want.answers[i], "ok") << i;
  EXPECT_EQ(want.snapshot, read_text(std::string(VGC_SOURCE_DIR) + "/tests/golden/cube.snapshot"));
  for (std::size_t r = 1; r < routes().size(); ++r) {
    const Transcript got = run(*routes()[r].impl, cube);
    EXPECT_EQ(got.answers, want.answers) << routes()[r].label;
    EXPECT_EQ(got.snapshot, want.snapshot) << routes()[r].label;
    EXPECT_EQ(got.derived, want.derived) << routes()[r].label;
  }
}

RC_GTEST_PROP(RoutesAgree, OnRandomCommandSequences, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(0, 40);
  const std::vector<Command> cs = *gen::gen_command_sequence(n);
  RC_ASSERT(routes().size() == 4u);
  const Transcript want = run(*routes()[0].impl, cs);
  for (std::size_t r = 1; r < routes().size(); ++r) {
    const Transcript got = run(*routes()[r].impl, cs);
    for (std::size_t i = 0; i < want.answers.size(); ++i) {
      if (got.answers[i] != want.answers[i]) {
        RC_FAIL(routes()[r].label + ": answer " + std::to_string(i) + " is '" + got.answers[i] + "', reference '" +
                want.answers[i] + "'" + (i > 0 ? " to " + print_command(cs[i - 1]) : ""));
      }
    }
    RC_ASSERT(got.snapshot == want.snapshot);
    RC_ASSERT(got.derived == want.derived);
  }
}

}  // namespace
}  // namespace vgc::test
