// readme_facts_test.cpp — the README's figures that the code can count stay
// true: "N faults across ..." (README "Does it have teeth?") is the number
// of seeded faults in tests/conformance/faults/ (faults::fault_catalog()),
// computed here, so adding a fault without updating the README fails.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "faulty_node.h"

namespace vgc {
namespace {

// Named faults (a bug of a kind a real host has) and the generated
// "rule:<name>" faults (one per node rule, the fault matrix) are counted
// apart, as the README gives them.
TEST(ReadmeFacts, TheFaultCountIsTheFaultCatalogs) {
  std::ifstream in(std::string(VGC_SOURCE_DIR) + "/README.md");
  ASSERT_TRUE(in) << "cannot read README.md";
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::size_t named = 0, generated = 0;
  for (const auto& f : faults::fault_catalog()) ++(f.generated ? generated : named);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex(R"((\d+) faults across)")))
      << "README.md no longer says \"N faults across ...\": update this test with it";
  EXPECT_EQ(std::stoul(m[1].str()), named)
      << "README.md says " << m[1].str() << " faults; tests/conformance/faults/ has " << named
      << " named faults: update the README";
  ASSERT_TRUE(std::regex_search(text, m, std::regex(R"((\d+) generated faults)")))
      << "README.md no longer says \"N generated faults\": update this test with it";
  EXPECT_EQ(std::stoul(m[1].str()), generated)
      << "README.md says " << m[1].str() << " generated faults; tests/conformance/faults/ has " << generated;
}

}  // namespace
}  // namespace vgc
