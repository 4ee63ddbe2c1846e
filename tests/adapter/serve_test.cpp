// serve_test.cpp — `vgc serve`: the exec protocol answered line by line,
// malformed lines answered "error line 1, column N: ..." without stopping.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "adapter_test_util.h"

namespace vgc::test {
namespace {

std::unique_ptr<ExecImplementation> serve() {
  auto impl = std::make_unique<ExecImplementation>(shell_quote(VGC_BINARY) + " serve", test_options(10.0));
  const Answer a = impl->start();
  EXPECT_EQ(a.status, CallStatus::Ok) << a.detail;
  return impl;
}

std::string ask(ExecImplementation& impl, const std::string& line) {
  std::string answer;
  const Answer a = impl.request_line(line, &answer);
  EXPECT_EQ(a.status, CallStatus::Ok) << a.detail;
  return answer;
}

TEST(Serve, HelloNamesTheProtocolVersion) {
  auto impl = serve();
  EXPECT_EQ(ask(*impl, "?hello").rfind("vgc-exec 1 ", 0), 0u);
  EXPECT_EQ(impl->identity(), "reference");
}

TEST(Serve, MalformedLinesAreErrorsWithTheirColumnAndServingGoesOn) {
  auto impl = serve();
  const std::string bad = "vertex_set_xyz_real64 0 0 1 2 x";
  const std::string col = std::to_string(bad.find(" x") + 2);  // 1-based column of "x"
  const std::string a1 = ask(*impl, bad);
  EXPECT_EQ(a1.rfind("error line 1, column " + col + ": ", 0), 0u) << a1;
  EXPECT_EQ(ask(*impl, "layer_create 2 \"uv\" VERTEX_REAL 0 0.5"), "ok");
  EXPECT_EQ(ask(*impl, "no_such_verb 1 2").rfind("error line 1, column 1: ", 0), 0u);
  EXPECT_EQ(ask(*impl, "").rfind("error line 1, column 1: ", 0), 0u);
  EXPECT_EQ(ask(*impl, "?nonsense").rfind("error ", 0), 0u);
  EXPECT_EQ(ask(*impl, "layer_destroy 9"), "rejected NO_SUCH_LAYER");
  EXPECT_EQ(ask(*impl, "layer_destroy 2"), "ok");
  EXPECT_EQ(ask(*impl, "?reset"), "ok");
  const Document s = impl->snapshot();
  EXPECT_EQ(s.status, CallStatus::Ok);
  EXPECT_EQ(s.text.find("\"uv\""), std::string::npos);
}

// `vgc serve` claims `digest` with its capabilities and answers ?digest with
// the digests of the documents it prints (document_digest.h), so checking
// through it costs what each command changed (program_checker.h).
TEST(Serve, ClaimsAndAnswersDigestOfItsDocuments) {
  auto impl = serve();
  EXPECT_TRUE(impl->offers_digest());
  for (const char* line : {"vertex_set_xyz_real64 0 0 1 2 3", "vertex_set_xyz_real64 0 1 1 0 3",
                           "vertex_set_xyz_real64 0 2 0 2 3", "polygon_set_corner_uint32 1 0 0 1 2 4294967295",
                           "layer_create 2 \"sharp\" VERTEX_UINT32 7 0", "crease_set_vertex \"sharp\" 0"}) {
    ASSERT_EQ(ask(*impl, line), "ok") << line;
    const DigestAnswer d = impl->digest();
    ASSERT_EQ(d.status, CallStatus::Ok) << d.detail;
    EXPECT_EQ(d.digests, digests_of(impl->snapshot().text, impl->derived().text)) << line;
  }
  EXPECT_EQ(ask(*impl, "?digest").rfind("digest ", 0), 0u);
}

// `vgc serve --done` answers every command "done" (docs/adapters.md), and
// the exec route reads it as an answer without a verdict.
TEST(Serve, DoneAnswersEveryCommandDone) {
  auto impl = std::make_unique<ExecImplementation>(shell_quote(VGC_BINARY) + " serve --done", test_options(10.0));
  ASSERT_EQ(impl->start().status, CallStatus::Ok);
  EXPECT_EQ(ask(*impl, "layer_create 2 \"uv\" VERTEX_REAL 0 0.5"), "done");
  EXPECT_EQ(ask(*impl, "layer_destroy 9"), "done");
  EXPECT_EQ(ask(*impl, "vertex_set_xyz_real64 0 0 1 2 x").rfind("error line 1, column ", 0), 0u);
  EXPECT_NE(impl->snapshot().text.find("\"uv\""), std::string::npos);  // applied all the same
  const Answer a = impl->apply(cmd::LayerDestroy{2});
  EXPECT_EQ(a.status, CallStatus::Ok) << a.detail;
  EXPECT_FALSE(a.verdict_reported);
  EXPECT_FALSE(a.applied);
  EXPECT_EQ(impl->snapshot().text.find("\"uv\""), std::string::npos);
}

TEST(Serve, QuitEndsItWithStatusZero) {
  const std::string out = std::string(::testing::TempDir()) + "/vgc_serve_quit.txt";
  const std::string cmd = "printf '?hello\\r\\n?quit\\nlayer_destroy 9\\n' | " + shell_quote(VGC_BINARY) +
                          " serve > " + shell_quote(out);
  const int rc = std::system(cmd.c_str());
  EXPECT_EQ(rc, 0);
  const std::string text = read_text(out);
  EXPECT_EQ(text.rfind("vgc-exec 1 ", 0), 0u) << text;
  EXPECT_EQ(text.find('\n'), text.size() - 1) << text;  // one answer: nothing after ?quit
  std::remove(out.c_str());
}

TEST(Serve, AnUnloadablePluginIsExitStatusTwo) {
  const std::string cmd = shell_quote(VGC_BINARY) + " serve --impl plugin:/nonexistent.so </dev/null 2>/dev/null";
  const int rc = std::system(cmd.c_str());
  EXPECT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 2);
}

}  // namespace
}  // namespace vgc::test
