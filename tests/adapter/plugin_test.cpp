// plugin_test.cpp — the plugin route: loading errors are clear, a plugin
// that crashes is a Crash result when isolated (and the suite survives),
// bad answers are ProtocolErrors in process and isolated alike, and the
// minimal example of docs/adapters.md loads and answers as documented.
#include <gtest/gtest.h>

#include "adapter_test_util.h"
#include "derived_document.h"
#include "node.h"
#include "snapshot.h"

namespace vgc::test {
namespace {

std::unique_ptr<Implementation> open_plugin(const std::string& name, bool isolate, std::string* error,
                                            double timeout = 5.0) {
  OpenOptions o = test_options(timeout);
  o.isolate_plugin = isolate;
  return open_implementation("plugin:" + test_plugin(name), o, error);
}

const Command kCommand = cmd::LayerDestroy{7};

class PluginRoute : public ::testing::TestWithParam<bool> {};  // isolated?

TEST_P(PluginRoute, LoadingErrorsSayWhatIsWrong) {
  const bool isolate = GetParam();
  std::string error;
  EXPECT_EQ(open_plugin("does_not_exist", isolate, &error), nullptr);
  EXPECT_NE(error.find("cannot load the library"), std::string::npos) << error;
  EXPECT_NE(error.find("libdoes_not_exist.so"), std::string::npos) << error;

  EXPECT_EQ(open_plugin("vgc_test_faulty_no_entry", isolate, &error), nullptr);
  EXPECT_NE(error.find("does not export the function vgc_plugin_v1"), std::string::npos) << error;

  EXPECT_EQ(open_plugin("vgc_test_faulty_abi_version_2", isolate, &error), nullptr);
  EXPECT_NE(error.find("plugin ABI version 2; this suite loads ABI version 1"), std::string::npos) << error;
}

TEST_P(PluginRoute, MinimalExampleLoadsAndAnswersAsDocumented) {
  std::string error;
  auto impl = open_plugin("vgc_test_minimal_plugin", GetParam(), &error);
  ASSERT_NE(impl, nullptr) << error;
  EXPECT_EQ(impl->identity(), "minimal example plugin 1.0");
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  const Answer a = impl->apply(cmd::VertexSetXyzReal64{0, 0, 1, 2, 3});
  EXPECT_EQ(a.status, CallStatus::Ok) << a.detail;
  EXPECT_FALSE(a.applied);
  EXPECT_EQ(a.reason, "NO_SUCH_LAYER");
  // Its documents are those of a fresh reference node.
  const Node fresh;
  EXPECT_EQ(impl->snapshot().text, print_snapshot(fresh));
  EXPECT_EQ(impl->derived().text, print_derived(fresh));
}

TEST_P(PluginRoute, AReasonThatIsNotOneWordIsAProtocolError) {
  std::string error;
  auto impl = open_plugin("vgc_test_faulty_bad_reason", GetParam(), &error);
  ASSERT_NE(impl, nullptr) << error;
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  const Answer a = impl->apply(kCommand);
  EXPECT_EQ(a.status, CallStatus::ProtocolError);
  EXPECT_NE(a.detail.find("NO SUCH LAYER"), std::string::npos) << a.detail;
  EXPECT_EQ(impl->apply(kCommand).status, CallStatus::ProtocolError);  // sticky
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  EXPECT_EQ(impl->snapshot().status, CallStatus::Ok);
}

TEST_P(PluginRoute, ADocumentWithoutEndIsAProtocolError) {
  std::string error;
  auto impl = open_plugin("vgc_test_faulty_bad_document", GetParam(), &error);
  ASSERT_NE(impl, nullptr) << error;
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  const Document d = impl->snapshot();
  EXPECT_EQ(d.status, CallStatus::ProtocolError);
  EXPECT_NE(d.detail.find("returned a document that does not end in a line"), std::string::npos) << d.detail;
}

// VGC_DONE (header revision 2, ABI 1): processed, verdict not reported;
// relayed by `vgc serve` as "done" when isolated.
TEST_P(PluginRoute, VgcDoneIsAnAnswerWithoutAVerdict) {
  std::string error;
  auto impl = open_plugin("vgc_test_faulty_all_done", GetParam(), &error);
  ASSERT_NE(impl, nullptr) << error;
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  for (int i = 0; i < 2; ++i) {
    const Answer a = impl->apply(kCommand);
    EXPECT_EQ(a.status, CallStatus::Ok) << a.detail;
    EXPECT_FALSE(a.verdict_reported);
    EXPECT_FALSE(a.applied);
    EXPECT_FALSE(a.malformed);
    EXPECT_EQ(a.reason, "");
  }
  EXPECT_EQ(impl->snapshot().status, CallStatus::Ok);
}

INSTANTIATE_TEST_SUITE_P(Plugin, PluginRoute, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "Isolated" : "InProcess"; });

TEST(PluginIsolation, ACrashingPluginIsACrashAndTheSuiteSurvives) {
  std::string error;
  auto impl = open_plugin("vgc_test_faulty_abort_on_third", true, &error);
  ASSERT_NE(impl, nullptr) << error;
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  EXPECT_EQ(impl->apply(kCommand).reason, "NO_SUCH_LAYER");
  EXPECT_EQ(impl->apply(kCommand).reason, "NO_SUCH_LAYER");
  const Answer crash = impl->apply(kCommand);
  EXPECT_EQ(crash.status, CallStatus::Crash);
  EXPECT_NE(crash.detail.find("SIGABRT"), std::string::npos) << crash.detail;
  EXPECT_EQ(impl->snapshot().status, CallStatus::Crash);
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  EXPECT_EQ(impl->apply(kCommand).reason, "NO_SUCH_LAYER");
}

// Why isolation is the default: in process, the plugin's abort() is ours.
TEST(PluginIsolationDeathTest, InProcessACrashingPluginTakesTheProcessDown) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(
      {
        std::string error;
        auto impl = open_plugin("vgc_test_faulty_abort_on_third", false, &error);
        if (impl)
          for (int i = 0; i < 3; ++i) impl->apply(kCommand);
        std::exit(0);
      },
      "");
}

}  // namespace
}  // namespace vgc::test
