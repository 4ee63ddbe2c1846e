// finding_cause_test.cpp — findings with one cause are grouped for the
// reports (conformance/report/finding_cause.h; issue 27 item 5), and
// findings of different checks on the same command kind are not.
#include <gtest/gtest.h>

#include "clause.h"
#include "finding_cause.h"
#include "report.h"
#include "run_result.h"
#include "verdict.h"

namespace vgc {
namespace {

ClauseOutcome outcome(const char* id, Command last, const std::string& message) {
  ClauseOutcome co;
  co.clause = find_clause(id);
  co.status = ClauseStatus::Fail;
  co.finding = Finding(id, FindingStatus::Fail, message);
  co.program = Program({std::move(last)});
  return co;
}

// r6's storage bound as a default run over the wire shows it (seed 1,
// issue 27): three MUST clauses, one cause; LAYER-BASE-2 and LAYER-NAME-1
// both end in a layer_create the host applied, but for two checks it lacks.
// Seen to fail: without the large-id key POLY-TRIANGLE-1 stood alone.
// r6's storage bound as a default run over the wire shows it (seed 1,
// issue 27), and two findings on the same command kind that are two
// missing checks (LAYER-BASE-2, LAYER-NAME-1).
RunResult storage_bound_run() {
  const std::string dropped = "expected ok, observed done, and the state is unchanged (dropped).";
  const std::string applied = "expected rejected BASE_LAYER, observed done, and the state changed (applied).";
  RunResult run;
  run.clauses.push_back(outcome("LAYER-BASE-2", cmd::LayerCreate{0, "edges", 129, 0, -2}, "`x`: " + applied));
  run.clauses.push_back(outcome("LAYER-NAME-1", cmd::LayerCreate{2, "sixteen_bytes_xx", 2, 0, 0.5}, "`x`: " + applied));
  run.clauses.push_back(outcome("VERTEX-SET-1", cmd::VertexSetXyzReal32{0, 8191, -4, -4, -4}, "`x`: " + dropped));
  run.clauses.push_back(outcome("ID-BOUND-1", cmd::VertexSetXyzReal32{0, 536870913, -4, -4, -4}, "`x`: " + dropped));
  run.clauses.push_back(
      outcome("POLY-TRIANGLE-1", cmd::PolygonSetCornerUint32{1, 2097152, {0, 1, 2, kNone32}}, "`x`: " + dropped));
  return run;
}

TEST(FindingCause, OneStorageBoundIsOneGroupAndTwoMissingChecksAreNot) {
  const RunResult run = storage_bound_run();
  const auto groups = group_findings_by_cause(run);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].clauses, (std::vector<std::string>{"VERTEX-SET-1", "ID-BOUND-1", "POLY-TRIANGLE-1"}));
  EXPECT_NE(groups[0].cause.find("storage bound"), std::string::npos) << groups[0].cause;
  EXPECT_EQ(cause_group_of(groups, "LAYER-BASE-2"), nullptr);
  EXPECT_EQ(cause_group_of(groups, "LAYER-NAME-1"), nullptr);
  // Statuses are the reports' business, untouched by grouping.
  for (const auto& co : run.clauses) EXPECT_EQ(co.status, ClauseStatus::Fail);
}

// report.html, as summary.md: each grouped finding's section names the
// others of its cause, linked to theirs; an ungrouped one names none.
// Seen to fail before: only the list at the top named the group.
TEST(FindingCause, EachGroupedFindingOnThePageNamesTheOthers) {
  const RunResult run = storage_bound_run();
  ReportContext ctx;
  ctx.implementation_spec = "verse:127.0.0.1:47500";
  ctx.run_dir = "/nonexistent/run";
  const std::string html = render_report_html(run, judge(run, nullptr), ctx);
  const auto section = [&html](const std::string& id) {
    const auto at = html.find("id=\"finding-" + id + "\"");
    if (at == std::string::npos) return std::string();
    return html.substr(at, html.find("</section>", at) - at);
  };
  const std::string vertex = section("VERTEX-SET-1"), bound = section("ID-BOUND-1"), base = section("LAYER-BASE-2");
  ASSERT_FALSE(vertex.empty());
  EXPECT_NE(vertex.find("One cause with <a href=\"#finding-ID-BOUND-1\">ID-BOUND-1</a>, "
                        "<a href=\"#finding-POLY-TRIANGLE-1\">POLY-TRIANGLE-1</a>"),
            std::string::npos)
      << vertex;
  EXPECT_NE(bound.find("One cause with <a href=\"#finding-VERTEX-SET-1\">VERTEX-SET-1</a>, "
                       "<a href=\"#finding-POLY-TRIANGLE-1\">POLY-TRIANGLE-1</a>"),
            std::string::npos)
      << bound;
  EXPECT_NE(vertex.find("href=\"#cause-groups\""), std::string::npos);
  EXPECT_NE(html.find("id=\"cause-groups\""), std::string::npos);
  ASSERT_FALSE(base.empty());
  EXPECT_EQ(base.find("One cause with"), std::string::npos) << base;
}

// The in-process form of a dropped command (a missing line after an ok):
// a node that answers ok to real32 writes and stores nothing.
TEST(FindingCause, DroppedCommandsOfOneKindAreOneGroup) {
  RunResult run;
  run.clauses.push_back(outcome("VERTEX-SET-1", cmd::VertexSetXyzReal32{0, 3, 1, 2, 3},
                                "after `x` (ok), snapshot: missing line: expected \"vertex 3 1 2 3\"."));
  run.clauses.push_back(outcome("ID-BOUND-1", cmd::VertexSetXyzReal32{0, 16777216, -4, -4, -4},
                                "after `x` (ok), snapshot: missing line: expected \"vertex 16777216 -4 -4 -4\"."));
  const auto groups = group_findings_by_cause(run);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].clauses.size(), 2u);
}

// r6's grown polygon storage as the two routes showed it at seed 2 (issue
// 27 item 4): the exec wrapper's POLY-DELETE-1 (a delete of polygon 503,
// which no command created, applied) and the wire's LAYER-STACK-1 (a slot
// of polygon 33, which no command created, sent) are one cause; a delete
// applied on a fresh node (no polygon past the first 32) is not of it.
// Seen to fail: without the "unused" key the two stood alone.
TEST(FindingCause, UnusedPolygonIdsTakenForLiveOnesAreOneGroup) {
  const std::vector<Command> stack{cmd::VertexSetXyzReal32{0, kNone32, -4, -4, -4}, cmd::VertexSetXyzReal32{0, 1, -4, -4, -4},
                                   cmd::VertexSetXyzReal32{0, 2, -4, -4, -4},
                                   cmd::PolygonSetCornerUint32{1, 32, {0, 1, 2, kNone32}},
                                   cmd::LayerCreate{2, "crease", 130, 256, 0}};
  const std::vector<Command> del{cmd::VertexSetXyzReal32{0, 0, -4, -4, -4}, cmd::VertexSetXyzReal32{0, 1, -4, -4, -4},
                                 cmd::VertexSetXyzReal32{0, 8, -4, -4, -4},
                                 cmd::PolygonSetCornerUint32{1, 511, {0, 1, 8, kNone32}}, cmd::PolygonDelete{503}};
  RunResult run;
  ClauseOutcome s = outcome("LAYER-STACK-1", stack.back(), "after `x` (done), snapshot: unexpected line: \"slot 2 33 0\".");
  s.program = Program(stack);
  s.finding->observed_line = "slot 2 33 0";
  ClauseOutcome d = outcome("POLY-DELETE-1", del.back(), "`polygon_delete 503`: expected rejected NO_SUCH_POLYGON, observed ok.");
  d.program = Program(del);
  run.clauses.push_back(s);
  run.clauses.push_back(d);
  auto groups = group_findings_by_cause(run);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].clauses, (std::vector<std::string>{"LAYER-STACK-1", "POLY-DELETE-1"}));
  EXPECT_NE(groups[0].cause.find("no command created"), std::string::npos) << groups[0].cause;
  // A delete applied with no polygon past the first 32 is a missing check,
  // not grown storage: LAYER-STACK-1 then stands alone.
  run.clauses[1].program = Program({cmd::PolygonDelete{40}});
  EXPECT_TRUE(group_findings_by_cause(run).empty());
  // Nor is a slot line of a polygon that was live.
  run.clauses[1].program = Program(del);
  run.clauses[0].finding->observed_line = "slot 2 32 0";
  EXPECT_TRUE(group_findings_by_cause(run).empty());
}

}  // namespace
}  // namespace vgc
