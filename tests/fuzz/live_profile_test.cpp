// live_profile_test.cpp — `vgc fuzz differential` over exec follows the
// profile a live program declares in its ?capabilities answer
// (declared_profile.h): open_live_implementation asks it when it opens the
// program, so the first input is already judged by those limits, as
// certify judges.
//
// Spec: docs/adapters.md section 1 ("A declared profile"); docs/fuzzing.md
// "Fuzzing a running implementation"; issue 27, Deliver item 4.
#include <gtest/gtest.h>

#include <string>

#include "live_implementation.h"

namespace vgc::fuzz {
namespace {

// A program that answers ?hello, declares `words` and answers every
// command `done`.
LiveOptions options(const std::string& words) {
  LiveOptions o;
  o.spec = "exec:sh -c 'while read l; do case \"$l\" in \"?hello\") echo \"vgc-exec 1 profile test\";; "
           "\"?capabilities\") printf \"capabilities " + words + "\\nend\\n\";; \"?quit\") exit 0;; *) echo done;; "
           "esac; done'";
  std::string error;
  o.route = parse_route(o.spec, &error);
  EXPECT_TRUE(o.route) << error;
  return o;
}

TEST(LiveProfile, TheDeclaredProfileIsKnownFromTheStart) {
  std::string error;
  auto sut = open_live_implementation(options("profile:no-derived profile:subscriptions-unseen"), &error);
  ASSERT_TRUE(sut) << error;
  EXPECT_FALSE(sut->limits().derived);
  EXPECT_FALSE(sut->limits().subscriptions);
  EXPECT_NE(sut->limits().route.find("profile:no-derived"), std::string::npos) << sut->limits().route;
}

TEST(LiveProfile, NoProfileNoLimits) {
  std::string error;
  auto sut = open_live_implementation(options("manifold"), &error);
  ASSERT_TRUE(sut) << error;
  EXPECT_TRUE(sut->limits().derived);
  EXPECT_TRUE(sut->limits().route.empty());
}

}  // namespace
}  // namespace vgc::fuzz
