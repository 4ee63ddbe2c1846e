// done_answers_test.cpp — implementations that answer `done` (processed,
// verdict not reported), as a host on the Verse wire does (README: "Hosts on
// the wire send no acknowledgement and no error: a command is applied ... or
// dropped silently"). check_step (check_step.h) reads applied or dropped from
// the state, so the reference behind `done` answers certifies with no clause
// failed, and a faulty one is still caught.
//
// Spec: the clauses judged (ATOMIC-1, POLY-DELETE-1, ...); docs/adapters.md
// "done answers".
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "check_step.h"
#include "command_text.h"
#include "reference_implementation.h"
#include "reference_wrapper.h"
#include "../reference/test_util.h"  // test::C, one command from its text
#include "runner.h"
#include "verdict.h"
#include "snapshot.h"
#include "default_run.h"

namespace vgc {
namespace {

using test::C;

// An implementation behind `done` answers: every ok / rejected answer of
// `inner` is reported as done. With drop_polygon_deletes it also silently
// drops every polygon delete (polygon_delete, and its wire alias
// polygon_set_corner_uint32 on layer 1 with v0 = 0xFFFFFFFF) and still
// answers done: a fault that nothing but the state shows.
class DoneAnswers final : public test::ReferenceWrapper {
 public:
  explicit DoneAnswers(bool drop_polygon_deletes = false) : drop_(drop_polygon_deletes) {}
  std::string name() const override { return drop_ ? "done:drop-polygon-deletes" : "done:reference"; }
  Answer apply(const Command& c) override {
    Answer a;
    if (drop_ && is_polygon_delete(c)) {
      a.verdict_reported = false;
      return a;
    }
    a = inner_.apply(c);
    if (a.status == CallStatus::Ok && !a.malformed) {
      a.applied = false;
      a.reason.clear();
      a.verdict_reported = false;
    }
    return a;
  }
  Document request(const std::string& line) override { return inner_.request(line); }

 private:
  static bool is_polygon_delete(const Command& c) {
    if (std::holds_alternative<cmd::PolygonDelete>(c)) return true;
    const auto* x = std::get_if<cmd::PolygonSetCornerUint32>(&c);
    return x && x->layer_id == Node::kPolygonLayer && x->v[0] == kNone32;
  }
  bool drop_;
};

// Runs `lines` through check_step from a fresh node; the first failure.
StepResult run_steps(Implementation& sut, const std::vector<std::string>& lines) {
  Node model;
  EXPECT_EQ(sut.reset().status, CallStatus::Ok);
  StepResult last;
  for (const auto& l : lines) {
    Node after;
    last = check_step(model, C(l), sut, &after);
    if (last.failure) return last;
    model = after;
  }
  return last;
}

TEST(DoneAnswers, AppliedAndDroppedAreReadFromTheState) {
  DoneAnswers sut;
  const StepResult r = run_steps(sut, {
                                          "vertex_set_xyz_real64 0 0 0 0 0",
                                          "vertex_set_xyz_real64 0 1 1 0 0",
                                          "vertex_set_xyz_real64 0 2 0 1 0",
                                          "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF",
                                          "polygon_set_corner_uint32 1 1 0 0 2 0xFFFFFFFF",  // rejected: dropped
                                          "layer_destroy 7",                                  // rejected: dropped
                                          "vertex_set_xyz_real64 0 1 1 0 0",  // applied, the state unchanged
                                          "crease_set_edge \"\" 0",           // applied, the state unchanged
                                          "polygon_delete 0",
                                      });
  EXPECT_FALSE(r.failure) << r.failure->clause << ": " << r.failure->message;
  EXPECT_FALSE(r.verdict_reported);
  EXPECT_TRUE(r.notes.empty());  // no reason to compare: REASON-1 is not judged
}

TEST(DoneAnswers, AnApplyTheStateDoesNotShowIsTheAcceptanceClause) {
  DoneAnswers sut(true);
  const StepResult r = run_steps(sut, {
                                          "vertex_set_xyz_real64 0 0 0 0 0",
                                          "vertex_set_xyz_real64 0 1 1 0 0",
                                          "vertex_set_xyz_real64 0 2 0 1 0",
                                          "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF",
                                          "polygon_delete 0",
                                      });
  ASSERT_TRUE(r.failure);
  EXPECT_EQ(r.failure->clause, "POLY-DELETE-1");
  EXPECT_NE(r.failure->message.find("expected ok, observed done, and the state is unchanged"), std::string::npos)
      << r.failure->message;
}

// An implementation that answers done and changes the state on a command
// the reference rejects: the rejection clause, as for an `ok` answer.
class DoneButAppliesRejected final : public test::ReferenceWrapper {
 public:
  std::string name() const override { return "done:applies-rejected"; }
  Answer apply(const Command& c) override {
    Answer a;
    a.verdict_reported = false;
    if (const auto* x = std::get_if<cmd::LayerCreate>(&c); x && x->layer_id == 0 && !x->name.empty()) {
      inner_.apply(cmd::LayerCreate{0xFFFF, x->name, x->type, x->def_uint, x->def_real});  // r6: another id
      return a;
    }
    inner_.apply(c);
    return a;
  }
};

TEST(DoneAnswers, AChangeOnACommandTheReferenceRejectsIsTheRejectionClause) {
  DoneButAppliesRejected sut;
  const StepResult r = run_steps(sut, {"layer_create 0 \"uv\" VERTEX_REAL 0 0"});
  ASSERT_TRUE(r.failure);
  EXPECT_EQ(r.failure->clause, "LAYER-BASE-2");
  EXPECT_NE(r.failure->message.find("expected rejected BASE_LAYER, observed done, and the state changed"),
            std::string::npos)
      << r.failure->message;
}

RunOptions options() { return unhurried_run(3, 60, 40); }

TEST(DoneAnswers, TheReferenceBehindDoneAnswersCertifiesWithNoClauseFailed) {
  DoneAnswers sut;
  const RunResult run = run_certification(sut, options());
  for (const ClauseOutcome& co : run.clauses)
    EXPECT_TRUE(co.status != ClauseStatus::Fail && co.status != ClauseStatus::Crash && co.status != ClauseStatus::Timeout)
        << co.clause->id << " " << co.status << ": " << (co.finding ? co.finding->message : "");
  EXPECT_TRUE(judge(run, nullptr).new_failures.empty());
  EXPECT_TRUE(run.complete);
  // Nothing reported a verdict, so reason codes cannot be judged: REASON-1
  // is not-applicable (not failed, not unchecked); every other clause passes.
  EXPECT_GT(run.unreported_verdicts, 0);
  for (const ClauseOutcome& co : run.clauses) {
    if (co.clause->id == "REASON-1") {
      EXPECT_EQ(co.status, ClauseStatus::NotApplicable) << co.note;
      EXPECT_EQ(co.exercised, 0);
    } else if (co.status != ClauseStatus::NotClaimed) {
      EXPECT_EQ(co.status, ClauseStatus::Pass) << co.clause->id << ": " << co.note;
    }
  }
  EXPECT_EQ(judge(run, nullptr).name, "conformant");
}

TEST(DoneAnswers, ADoneImplementationThatDropsPolygonDeletesIsCaught) {
  DoneAnswers sut(true);
  RunOptions o = options();
  o.clause_glob = "POLY-*";
  const RunResult run = run_certification(sut, o);
  bool found = false;
  for (const ClauseOutcome& co : run.clauses)
    if (co.clause->id == "POLY-DELETE-1" && co.status == ClauseStatus::Fail && co.finding) found = true;
  EXPECT_TRUE(found) << "the dropped polygon deletes were not found";
  EXPECT_FALSE(judge(run, nullptr).new_failures.empty());
}

// The exec route: `vgc serve --done` is the reference answering `done` to
// every command over the exec protocol.
TEST(DoneAnswers, VgcServeDoneCertifiesThroughTheExecRoute) {
  OpenOptions open;
  open.timeout_seconds = 10;
  open.vgc_binary = VGC_BINARY;
  std::string error;
  auto sut = open_implementation(std::string("exec:") + VGC_BINARY + " serve --done", open, &error);
  ASSERT_NE(sut, nullptr) << error;
  ASSERT_EQ(sut->reset().status, CallStatus::Ok);
  const Answer a = sut->apply(C("layer_destroy 7"));
  EXPECT_EQ(a.status, CallStatus::Ok) << a.detail;
  EXPECT_FALSE(a.verdict_reported);
  RunOptions o = options();
  o.cases = 30;
  o.clause_glob = "POLY-*,VERTEX-*,ATOMIC-1";
  const RunResult run = run_certification(*sut, o);
  for (const ClauseOutcome& co : run.clauses)
    EXPECT_TRUE(co.status != ClauseStatus::Fail && co.status != ClauseStatus::Crash && co.status != ClauseStatus::Timeout)
        << co.clause->id << " " << co.status << ": " << (co.finding ? co.finding->message : "");
  EXPECT_TRUE(judge(run, nullptr).new_failures.empty());
}

}  // namespace
}  // namespace vgc
