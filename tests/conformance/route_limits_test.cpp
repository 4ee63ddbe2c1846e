// route_limits_test.cpp — a route that cannot show everything
// (Implementation::limits, RouteLimits): what it cannot show is reported
// `not-applicable` naming the route and why, never `pass` and never a
// silent `unchecked`, and a run where everything it can show passes is
// conformant and complete.
//
// The test double is what the Verse wire route looks like to the runner
// (docs/adapters.md "The Verse wire route"): the reference behind `done`
// answers (a host acknowledges nothing), no derived document (the wire
// carries no effective creases and no bone poses), no observable
// subscription column, and no capability requests.
//
// Spec: docs/certify.md "Clause statuses"; the clauses named below.
#include <gtest/gtest.h>

#include <string>

#include "check_step.h"
#include "document_diff.h"
#include "reference_wrapper.h"
#include "../reference/test_util.h"  // test::C
#include "report.h"
#include "runner.h"
#include "verdict.h"
#include "default_run.h"

namespace vgc {
namespace {

using test::C;

class WireLike : public test::ReferenceWrapper {
 public:
  explicit WireLike(bool drop_vertex_crease_layers = false) : drop_(drop_vertex_crease_layers) {}
  std::string name() const override { return "wire-like"; }
  Answer apply(const Command& c) override {
    Answer a;
    a.verdict_reported = false;
    // A fault only the derived document would show is invisible here; one
    // the snapshot shows is not (tested below).
    if (drop_) {
      if (const auto* x = std::get_if<cmd::CreaseSetVertex>(&c); x && !x->layer.empty()) return a;
    }
    const Answer inner = inner_.apply(c);
    a.status = inner.status;
    a.detail = inner.detail;
    return a;
  }
  Document snapshot() override {
    Document d = inner_.snapshot();
    d.text = without_subscriptions(d.text);  // this route cannot see them
    return d;
  }
  Document derived() override {
    ++derived_calls;
    return {CallStatus::ProtocolError, {}, "the test route carries no derived document"};
  }
  RouteLimits limits() const override {
    RouteLimits l;
    l.route = "the test route";
    l.derived = false;
    l.why_no_derived = "the test route carries no derived document";
    l.subscriptions = false;
    l.at_scale = false;  // as the wire: a command per packet exchange
    l.clauses["REASON-1"] = "the test route reports no verdicts";
    l.clauses["LAYER-SUBSCRIBE-1"] = "the test route shows no subscription";
    for (const char* id : {"MESH-CLASSIFY-1", "SUBD-CATMARK-1", "NORMALS-SPLIT-1", "LOOP-TRIANGLE-1",
                           "EDIT-HIERARCHY-1"})
      l.clauses[id] = "the test route carries no capability requests";
    return l;
  }
  int derived_calls = 0;

 private:
  bool drop_;
};

RunOptions options() { return unhurried_run(5, 60, 40); }

const ClauseOutcome* clause_in(const RunResult& run, std::string_view id) {
  for (const auto& co : run.clauses)
    if (co.clause->id == id) return &co;
  return nullptr;
}

TEST(RouteLimits, WithoutSubscriptionsMasksOnlyTheLastWordOfLayerLines) {
  const std::string in =
      "vgc-snapshot 1\nlayer 0 \"vertex\" VERTEX_XYZ - - REAL64\nlayer 2 \"a b\" VERTEX_REAL - 0 -\n"
      "crease_vertex \"\" 0\nend\n";
  EXPECT_EQ(without_subscriptions(in),
            "vgc-snapshot 1\nlayer 0 \"vertex\" VERTEX_XYZ - - -\nlayer 2 \"a b\" VERTEX_REAL - 0 -\n"
            "crease_vertex \"\" 0\nend\n");
}

TEST(RouteLimits, ASubscribeIsNotASnapshotDifferenceOnARouteThatCannotSeeIt) {
  WireLike sut;
  ASSERT_EQ(sut.reset().status, CallStatus::Ok);
  Node model, after;
  const StepResult r = check_step(model, C("layer_subscribe 0 REAL64"), sut, &after);
  EXPECT_FALSE(r.failure) << r.failure->clause << ": " << r.failure->message;
  EXPECT_FALSE(r.derived_judged);
  EXPECT_EQ(sut.derived_calls, 0);
}

TEST(RouteLimits, WhatTheRouteCannotShowIsNotApplicableWithWhyAndTheRunIsConformant) {
  WireLike sut;
  const RunResult run = run_certification(sut, options());
  EXPECT_EQ(sut.derived_calls, 0) << "derived() was called on a route that has none";
  EXPECT_EQ(run.route, "the test route");
  int not_applicable = 0;
  for (const ClauseOutcome& co : run.clauses) {
    EXPECT_TRUE(co.status == ClauseStatus::Pass || co.status == ClauseStatus::NotApplicable)
        << co.clause->id << " " << co.status << ": " << co.note << (co.finding ? co.finding->message : "");
    if (co.status == ClauseStatus::NotApplicable) {
      ++not_applicable;
      EXPECT_NE(co.note.find("not judgeable over the test route: "), std::string::npos) << co.clause->id << co.note;
    }
  }
  // The route's own list, each with its why.
  for (const char* id : {"REASON-1", "LAYER-SUBSCRIBE-1", "SUBD-CATMARK-1", "EDIT-HIERARCHY-1"}) {
    const ClauseOutcome* co = clause_in(run, id);
    ASSERT_NE(co, nullptr) << id;
    EXPECT_EQ(co->status, ClauseStatus::NotApplicable) << id;
  }
  // A clause only the derived document decides: bone world poses
  // (BONE-DOWNSTREAM-1).
  const ClauseOutcome* downstream = clause_in(run, "BONE-DOWNSTREAM-1");
  ASSERT_NE(downstream, nullptr);
  EXPECT_EQ(downstream->status, ClauseStatus::NotApplicable) << downstream->note;
  EXPECT_NE(downstream->note.find("only the derived document"), std::string::npos) << downstream->note;
  EXPECT_EQ(downstream->exercised, 0);
  // A clause judged on the snapshot too (which crease layers are accepted)
  // passes on that, and says its derived part (the effective creases read
  // from the layer) was not judged.
  for (const char* id : {"CREASE-VERTEX-LAYER-1", "CREASE-EDGE-LAYER-1"}) {
    const ClauseOutcome* co = clause_in(run, id);
    ASSERT_NE(co, nullptr) << id;
    EXPECT_EQ(co->status, ClauseStatus::Pass) << id << ": " << co->note;
    EXPECT_NE(co->note.find("its derived part ("), std::string::npos) << id << ": " << co->note;
  }
  // The seven the route names, and the two only the derived document
  // decides: BONE-DOWNSTREAM-1 and BONE-PARENT-1 (a root's pose). Before
  // the rule-traced attribution, BONE-PARENT-1 counted as exercised by a
  // bone_create with a missing parent being accepted, which judges no pose.
  const ClauseOutcome* parent = clause_in(run, "BONE-PARENT-1");
  ASSERT_NE(parent, nullptr);
  EXPECT_EQ(parent->status, ClauseStatus::NotApplicable) << parent->note;
  EXPECT_EQ(not_applicable, 9);
  EXPECT_TRUE(judge(run, nullptr).new_failures.empty());
  EXPECT_TRUE(run.complete);
  EXPECT_EQ(judge(run, nullptr).name, "conformant");
  // Each not-judgeable clause appears with its why in the summary.
  ReportContext ctx;
  ctx.implementation_spec = "wire-like";
  ctx.command_line = "vgc certify --impl wire-like";
  ctx.run_dir = "/nonexistent";
  const std::string summary = render_summary(run, judge(run, nullptr), ctx);
  EXPECT_NE(summary.find("| BONE-DOWNSTREAM-1 | MUST | not-applicable (not judgeable over the test route: "),
            std::string::npos)
      << summary;
  EXPECT_NE(summary.find("Not judgeable over the test route (not-applicable; the clause table says why for each): "),
            std::string::npos)
      << summary;
}

// A fault the snapshot shows is still caught on such a route: the vertex
// crease layer setting is dropped, and the snapshot's crease_vertex line
// does not change.
TEST(RouteLimits, AFaultTheSnapshotShowsIsStillCaught) {
  WireLike sut(/*drop_vertex_crease_layers=*/true);
  RunOptions o = options();
  o.clause_glob = "CREASE-*";
  const RunResult run = run_certification(sut, o);
  bool caught = false;
  for (const ClauseOutcome& co : run.clauses)
    if (co.finding && co.status == ClauseStatus::Fail) caught = true;
  EXPECT_TRUE(caught) << "the dropped crease_set_vertex was not found";
  EXPECT_FALSE(judge(run, nullptr).new_failures.empty());
}

}  // namespace
}  // namespace vgc
