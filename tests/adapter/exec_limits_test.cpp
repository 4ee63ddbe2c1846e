// exec_limits_test.cpp — the exec adapter's limits (issue 31): starting a
// program has its own limit (OpenOptions::start_timeout_seconds, the
// --start-timeout option), separate from the per-call one, and each limit
// is named in the message that reports it; what the adapter keeps of a
// huge answer line is cut to a few KiB, with its size said
// (bounded_text.h). The program is tests/adapter/faulty/slow_or_huge.py.
#include <gtest/gtest.h>

#include <chrono>

#include "adapter_test_util.h"
#include "bounded_text.h"

namespace vgc::test {
namespace {

const Command kCommand = cmd::LayerDestroy{7};

TEST(ExecLimits, AProgramSlowToStartStartsWithinTheStartLimitNotTheCallLimit) {
  OpenOptions o = test_options(0.5);  // half a second per call
  o.start_timeout_seconds = 30;       // ?hello takes 1.5 s
  std::string error;
  auto impl = open_implementation(faulty_spec("slow_or_huge.py", "slow_hello 1.5"), o, &error);
  ASSERT_NE(impl, nullptr) << error;
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  EXPECT_TRUE(impl->apply(kCommand).applied);
  // A restart is a start too: the same limit.
  EXPECT_EQ(impl->restart().status, CallStatus::Ok);
}

TEST(ExecLimits, AStartPastTheStartLimitSaysWhichLimit) {
  OpenOptions o = test_options(30);
  o.start_timeout_seconds = 0.5;
  std::string error;
  auto impl = open_implementation(faulty_spec("slow_or_huge.py", "slow_hello 3"), o, &error);
  EXPECT_EQ(impl, nullptr);
  EXPECT_NE(error.find("no complete answer to ?hello within 0.5 s (--start-timeout)"), std::string::npos) << error;
}

TEST(ExecLimits, ACallPastTheCallLimitSaysWhichLimit) {
  std::string error;
  auto impl = open_implementation(faulty_spec("hang_on_command.sh"), test_options(0.5), &error);
  ASSERT_NE(impl, nullptr) << error;
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  const Answer a = impl->apply(kCommand);
  EXPECT_EQ(a.status, CallStatus::Timeout);
  EXPECT_NE(a.detail.find("within 0.5 s (--timeout)"), std::string::npos) << a.detail;
}

TEST(ExecLimits, HugeAnswersAreKeptCutWithTheirSize) {
  const std::size_t n = 3u << 20;  // 3 MiB per answer line
  std::string error;
  auto impl = open_implementation(faulty_spec("slow_or_huge.py", "huge " + std::to_string(n)), test_options(30), &error);
  ASSERT_NE(impl, nullptr) << error;
  const std::string said = "(3,145,728 bytes, first 4 KiB shown)";
  EXPECT_LT(impl->identity().size(), kShownBytes + 100);
  EXPECT_NE(impl->identity().find(said), std::string::npos);
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  const Answer a = impl->apply(kCommand);
  ASSERT_EQ(a.status, CallStatus::Ok) << a.detail;
  EXPECT_FALSE(a.applied);
  EXPECT_LT(a.reason.size(), kShownBytes + 100);
  EXPECT_EQ(a.reason.rfind("AAAA", 0), 0u);
  EXPECT_NE(a.reason.find(said), std::string::npos);
  const Document d = impl->snapshot();
  ASSERT_EQ(d.status, CallStatus::Ok) << d.detail;
  EXPECT_LT(d.text.size(), kShownBytes + 200);
  EXPECT_NE(d.text.find(said), std::string::npos);
  EXPECT_EQ(d.text.substr(d.text.size() - 4), "end\n");
}

TEST(BoundedText, KeepsShortTextAndCutsLongTextOnACharacterBoundary) {
  EXPECT_EQ(bounded_text("short"), "short");
  EXPECT_EQ(bounded_text(std::string(4096, 'x')), std::string(4096, 'x'));
  EXPECT_EQ(bounded_text(std::string(4097, 'x')), std::string(4096, 'x') + "\u2026 (4,097 bytes, first 4 KiB shown)");
  // "é" is two bytes: a cut after 5 bytes of "aaaaé..." must not keep half of it.
  const std::string s = "aaaa\u00e9\u00e9\u00e9";
  EXPECT_EQ(bounded_text(s, 5), "aaaa\u2026 (10 bytes, first 5 bytes shown)");
  EXPECT_EQ(grouped_count(52428800), "52,428,800");
  EXPECT_EQ(grouped_count(999), "999");
}

}  // namespace
}  // namespace vgc::test
