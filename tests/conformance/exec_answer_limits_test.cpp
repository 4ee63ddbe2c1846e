// exec_answer_limits_test.cpp — issue 28 item 3: an exec implementation's
// derived answer is not cut off by a limit sized for generated cases. With
// expect_answer_bytes the size limit of the next request grows to fit
// (at least 4x the expected size); without it the same answer is too long,
// and the Document says the limit was vgc's (Document::limit), which the
// capability checks report as a timeout, never a fail.
#include <gtest/gtest.h>

#include "command_text.h"
#include "implementation.h"

namespace vgc {
namespace {

std::unique_ptr<Implementation> serve_with_limit(std::size_t max_answer_bytes) {
  OpenOptions o;
  o.max_answer_bytes = max_answer_bytes;
  o.timeout_seconds = 10;
  std::string error;
  auto impl = open_implementation(std::string("exec:") + VGC_BINARY + " serve", o, &error);
  EXPECT_TRUE(impl) << error;
  return impl;
}

void build_grid(Implementation& impl) {
  ASSERT_EQ(impl.reset().status, CallStatus::Ok);
  std::vector<Command> commands;
  std::string text;
  for (int j = 0; j <= 8; ++j)
    for (int i = 0; i <= 8; ++i)
      text += "vertex_set_xyz_real64 0 " + std::to_string(j * 9 + i) + " " + std::to_string(i) + " " +
              std::to_string(j) + " 0\n";
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const int a = j * 9 + i;
      text += "polygon_set_corner_uint32 1 " + std::to_string(j * 8 + i) + " " + std::to_string(a) + " " +
              std::to_string(a + 1) + " " + std::to_string(a + 10) + " " + std::to_string(a + 9) + "\n";
    }
  TextError e;
  ASSERT_TRUE(parse_commands(text, &commands, &e)) << e.message;
  for (const auto& c : commands) ASSERT_EQ(impl.apply(c).status, CallStatus::Ok);
}

TEST(ExecAnswerLimits, AnExpectedLargeAnswerIsReadWhole) {
  auto impl = serve_with_limit(4096);  // far below a level-2 answer on 64 quads
  ASSERT_TRUE(impl);
  build_grid(*impl);
  impl->expect_answer_bytes(64 * 16 * 90);
  const Document d = impl->request("?subdivide 2");
  EXPECT_EQ(d.status, CallStatus::Ok) << d.detail;
  EXPECT_GT(d.text.size(), 4096u);
  EXPECT_TRUE(d.limit.empty());
  // The next request has the options' limit again.
  const Document again = impl->request("?subdivide 2");
  EXPECT_NE(again.status, CallStatus::Ok);
  EXPECT_EQ(again.limit, "the answer size limit") << again.detail;
}

TEST(ExecAnswerLimits, AnUnexpectedLargeAnswerIsVgcsLimitNotAVerdict) {
  auto impl = serve_with_limit(4096);
  ASSERT_TRUE(impl);
  build_grid(*impl);
  const Document d = impl->request("?subdivide 2");
  EXPECT_EQ(d.status, CallStatus::ProtocolError);
  EXPECT_EQ(d.limit, "the answer size limit") << d.detail;
}

}  // namespace
}  // namespace vgc
