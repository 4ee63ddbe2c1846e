// unused_defaults_test.cpp — a layer's snapshot line is compared on the
// default its type uses only (LAYER-DEFAULT-1, docs/commands.md 6.1): an
// implementation that prints something else for the unused default (the
// old format's numbers, the value it was sent) certifies; one whose used
// default is wrong is still caught.
//
// Spec: 000 2.6.1 ("This slot is typically initialized with a default
// value"; Table 2-1 gives each type one value type).
#include <gtest/gtest.h>

#include <string>

#include "document_diff.h"
#include "verdict.h"
#include "reference_implementation.h"
#include "reference_wrapper.h"
#include "runner.h"

namespace vgc {
namespace {

// The reference, with its snapshot's layer lines rewritten: an unused
// default ("-") printed as `unused`; with wrong_used, a used def_uint
// printed one higher.
class RewrittenDefaults final : public test::ReferenceWrapper {
 public:
  RewrittenDefaults(std::string unused, bool wrong_used) : unused_(std::move(unused)), wrong_used_(wrong_used) {}
  std::string name() const override { return "rewritten-defaults"; }
  Document snapshot() override {
    Document d = inner_.snapshot();
    std::string out;
    for (const std::string& line : split_lines(d.text)) out += rewrite(line) + "\n";
    d.text = out;
    return d;
  }

 private:
  std::string rewrite(const std::string& line) const {
    if (line.rfind("layer ", 0) != 0) return line;
    // ... <TYPE> <def_uint> <def_real> <sub>: the last four words (a name may hold blanks).
    std::size_t cut[3];
    std::size_t at = line.size();
    for (int i = 0; i < 3; ++i) at = cut[i] = line.rfind(' ', at - 1);
    std::string du = line.substr(cut[2] + 1, cut[1] - cut[2] - 1);
    std::string dr = line.substr(cut[1] + 1, cut[0] - cut[1] - 1);
    if (du == "-") du = unused_;
    else if (wrong_used_) du = std::to_string(std::stoull(du, nullptr, 0) + 1);
    if (dr == "-") dr = unused_;
    return line.substr(0, cut[2] + 1) + du + " " + dr + line.substr(cut[0]);
  }
  std::string unused_;
  bool wrong_used_;
};

RunOptions options() {
  RunOptions o;
  o.seed = 5;
  o.cases = 60;
  o.clause_glob = "LAYER-*";
  return o;
}

TEST(UnusedDefaults, AnotherUnusedDefaultIsNoFinding) {
  for (const char* unused : {"0", "7", "nan"}) {
    RewrittenDefaults sut(unused, false);
    const RunResult run = run_certification(sut, options());
    for (const ClauseOutcome& co : run.clauses)
      EXPECT_TRUE(co.status == ClauseStatus::Pass) << unused << ": " << co.clause->id << " " << co.status << ": "
                                       << (co.finding ? co.finding->message : "");
    EXPECT_TRUE(judge(run, nullptr).new_failures.empty()) << unused;
  }
}

TEST(UnusedDefaults, AWrongUsedDefaultIsStillAFinding) {
  RewrittenDefaults sut("-", true);
  const RunResult run = run_certification(sut, options());
  bool found = false;
  for (const ClauseOutcome& co : run.clauses)
    if (co.finding && co.finding->message.find("snapshot") != std::string::npos &&
        co.finding->message.find("layer ") != std::string::npos)
      found = true;
  EXPECT_TRUE(found) << "a wrong def_uint on an integer layer's line was not reported";
  EXPECT_FALSE(judge(run, nullptr).new_failures.empty());
}

}  // namespace
}  // namespace vgc
