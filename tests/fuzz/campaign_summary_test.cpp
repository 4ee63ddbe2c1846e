// campaign_summary_test.cpp — a campaign's summary files carry an
// implementation's bytes (crash signatures, messages): summary.md shows a
// control byte escaped, never raw, and summary.json survives invalid UTF-8
// (issue 19 item 5: escape what is not ours).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "campaign.h"

namespace vgc::fuzz {
namespace {

CampaignSummary summary_with_foreign_bytes() {
  CampaignSummary s;
  s.target = "differential";
  s.run = "run";
  CampaignCrash c;
  c.signature = "FINDING LAYER-NAME-1: \x1b]0;pwned\x07\x1b[31mred \xff\xfe";
  c.dedup_key = c.signature;
  c.clause = "LAYER-NAME-1";
  c.level = "MUST";
  c.inputs = 1;
  s.crashes.push_back(c);
  CampaignClause g;
  g.clause = c.clause;
  g.level = c.level;
  g.crashes = {0};
  g.inputs = 1;
  s.clauses.push_back(g);
  return s;
}

TEST(CampaignSummary, MarkdownShowsNoRawControlByte) {
  const std::string md = summary_markdown(summary_with_foreign_bytes());
  EXPECT_EQ(md.find('\x1b'), std::string::npos) << md;
  EXPECT_EQ(md.find('\x07'), std::string::npos) << md;
  EXPECT_NE(md.find("\\x1b]0;pwned"), std::string::npos) << md;
}

TEST(CampaignSummary, JsonIsWrittenWhateverTheBytes) {
  std::string json;
  ASSERT_NO_THROW(json = summary_json(summary_with_foreign_bytes()));
  nlohmann::json parsed;
  EXPECT_NO_THROW(parsed = nlohmann::json::parse(json)) << json;
  EXPECT_TRUE(parsed.is_object()) << json;
}

}  // namespace
}  // namespace vgc::fuzz
