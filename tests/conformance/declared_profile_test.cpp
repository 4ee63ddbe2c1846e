// declared_profile_test.cpp — a profile an exec program declares in its
// ?capabilities answer (declared_profile.h): its words read (bounded, an
// unknown word named and ignored, never an error), mapped onto the route
// limits the Verse wire has, and followed by certify, replay and the fuzz
// fast path, so that the clauses the program declares it cannot show are
// `not-applicable` with its declaration as the why, as on the wire.
//
// Spec: docs/adapters.md section 1 ("A declared profile"); the derived-only
// clauses BONE-PARENT-1 and BONE-DOWNSTREAM-1 (bone world poses);
// LAYER-SUBSCRIBE-1, REASON-1, BONE-VALUE-1 and the capability clauses
// (route_limit_clauses.h); issue 27, Deliver item 4.
#include <gtest/gtest.h>

#include <string>

#include "clause_status.h"
#include "command_text.h"
#include "declared_profile.h"
#include "exec_implementation.h"
#include "fast_check.h"
#include "report.h"
#include "../reference/test_util.h"  // test::C
#include "route_limit_clauses.h"
#include "runner.h"
#include "verdict.h"
#include "default_run.h"

namespace vgc {
namespace {

using test::C;

TEST(DeclaredProfile, EachKnownWordIsTheRouteLimitItNamesWithTheDeclarationAsWhy) {
  const DeclaredProfile p = declared_profile(
      "capabilities manifold profile:no-derived profile:subscriptions-unseen profile:no-verdicts "
      "profile:no-bone-rotation profile:no-requests profile:c-string-names\nend\n");
  EXPECT_EQ(p.words.size(), 6u);
  EXPECT_TRUE(p.unknown.empty());
  EXPECT_TRUE(p.c_string_names);
  EXPECT_FALSE(p.limits.derived);
  EXPECT_FALSE(p.limits.subscriptions);
  EXPECT_TRUE(p.limits.at_scale) << "a declared profile is no reason to skip the properties at scale";
  EXPECT_NE(p.limits.route.find("profile:no-derived"), std::string::npos) << p.limits.route;
  for (const char* id : {"LAYER-SUBSCRIBE-1", "REASON-1", "BONE-VALUE-1", "SUBD-CATMARK-1", "BONE-DOWNSTREAM-1"}) {
    const std::string why = route_limit_of(id, p.limits);
    EXPECT_NE(why.find("in its ?capabilities answer"), std::string::npos) << id << ": " << why;
    EXPECT_NE(why.find("not judgeable over the exec route with the profile"), std::string::npos) << id << ": " << why;
  }
  EXPECT_NE(route_limit_of("BONE-DOWNSTREAM-1", p.limits).find("profile:no-derived"), std::string::npos);
  EXPECT_NE(route_limit_of("BONE-VALUE-1", p.limits).find("profile:no-bone-rotation"), std::string::npos);
  EXPECT_EQ(route_limit_of("BONE-CREATE-1", p.limits), "");
}

TEST(DeclaredProfile, NoWordsNoLimitsAndOnlyTheFirstLineOfACapabilitiesAnswerCounts) {
  for (const char* answer : {"capabilities manifold\nend\n", "capabilities\nend\n", "error unknown request\n",
                             "capabilities\nprofile:no-derived\nend\n", "profile:no-derived\n",
                             "capabilitiesx profile:no-derived\nend\n", "capabilities profile:\nend\n"}) {
    const DeclaredProfile p = declared_profile(answer);
    EXPECT_TRUE(p.words.empty()) << answer;
    EXPECT_TRUE(p.limits.route.empty()) << answer;
    EXPECT_TRUE(p.limits.derived) << answer;
  }
}

TEST(DeclaredProfile, AnUnknownWordIsNamedInTheRouteAndLimitsNothing) {
  const DeclaredProfile p = declared_profile("capabilities profile:teleport profile:no-derived\nend\n");
  ASSERT_EQ(p.unknown, std::vector<std::string>{"teleport"});
  EXPECT_FALSE(p.limits.derived);
  EXPECT_NE(p.limits.route.find("not known to this vgc, so limiting nothing: profile:teleport"), std::string::npos)
      << p.limits.route;
  const DeclaredProfile only = declared_profile("capabilities profile:teleport\nend\n");
  EXPECT_TRUE(only.limits.derived);
  EXPECT_TRUE(only.limits.cannot.empty());
  EXPECT_NE(only.limits.route.find("profile:teleport"), std::string::npos) << only.limits.route;
  for (const Clause& c : clause_catalog()) EXPECT_EQ(route_limit_of(c.id, only.limits), "") << c.id;
}

TEST(DeclaredProfile, WordsAreBoundedAndEscaped) {
  std::string answer = "capabilities";
  for (int i = 0; i < 100; ++i) answer += " profile:" + std::string(1000, 'x');
  answer += " profile:a\x01z\nend\n";
  const DeclaredProfile p = declared_profile(answer);
  EXPECT_EQ(p.words.size(), kMaxProfileWords);
  for (const std::string& w : p.words) EXPECT_LE(w.size(), kMaxProfileWordBytes);
  EXPECT_LT(p.limits.route.size(), 2000u);
  const DeclaredProfile odd = declared_profile("capabilities profile:a\x01z\nend\n");
  ASSERT_EQ(odd.unknown.size(), 1u);
  EXPECT_EQ(odd.unknown[0].find('\x01'), std::string::npos) << "an unprintable byte is escaped";
}

TEST(DeclaredProfile, NamesWithANulInside) {
  EXPECT_TRUE(has_name_with_nul(C("layer_create 2 \"a\\x00b\" VERTEX_REAL 0 0")));
  EXPECT_FALSE(has_name_with_nul(C("layer_create 2 \"ab\" VERTEX_REAL 0 0")));
  EXPECT_TRUE(has_name_with_nul(C("crease_set_vertex \"\\x00\" 7")));
  EXPECT_TRUE(has_name_with_nul(C("bone_create 0 \"w\" \"\" 65535 0 0 0 \"\" 0 0 0 1 \"r\\x00\"")));
  EXPECT_FALSE(has_name_with_nul(C("vertex_set_xyz_real64 0 0 1 2 3")));
}

TEST(DeclaredProfile, BoneRotationsOtherThanTheIdentity) {
  EXPECT_FALSE(has_bone_rotation(C("bone_create 0 \"w\" \"\" 65535 0 0 0 \"\" 0 0 0 1 \"\"")));
  EXPECT_TRUE(has_bone_rotation(C("bone_create 0 \"w\" \"\" 65535 0 0 0 \"\" 0 0 1 0 \"\"")));
  EXPECT_TRUE(has_bone_rotation(C("bone_create 0 \"w\" \"\" 65535 0 0 0 \"\" -0 0 0 1 \"\"")));
  EXPECT_TRUE(has_bone_rotation(C("bone_create 0 \"w\" \"\" 65535 0 0 0 \"\" nan 0 0 1 \"\"")));
  EXPECT_FALSE(has_bone_rotation(C("bone_create 0 \"\" \"\" 65535 0 0 0 \"\" 0 0 1 0 \"\"")))
      << "bone_create with an empty weight is bone_destroy: it carries no rotation";
  EXPECT_FALSE(has_bone_rotation(C("vertex_set_xyz_real64 0 0 1 2 3")));
}

// ---- through the exec route: tests/conformance/declared_profile_node.py ----

std::string node_program(const std::string& words) {
  return "exec:python3 " + shell_quote(std::string(VGC_SOURCE_DIR) + "/tests/conformance/declared_profile_node.py") +
         " " + shell_quote(VGC_BINARY) + (words.empty() ? "" : " " + words);
}

std::unique_ptr<Implementation> open_node(const std::string& words) {
  OpenOptions o;
  o.timeout_seconds = 60;  // a hang guard; the machine may be loaded
  std::string error;
  auto impl = open_implementation(node_program(words), o, &error);
  EXPECT_TRUE(impl) << error;
  return impl;
}

RunOptions bone_options() { return unhurried_run(1, 30, 40, "BONE-*"); }

const ClauseOutcome* clause_in(const RunResult& run, std::string_view id) {
  for (const auto& co : run.clauses)
    if (co.clause->id == id) return &co;
  return nullptr;
}

TEST(DeclaredProfileExec, WithoutTheDeclarationAStoreThatDerivesNothingFailsTheDerivedOnlyClauses) {
  auto impl = open_node("");
  ASSERT_TRUE(impl);
  const RunResult run = run_certification(*impl, bone_options());
  EXPECT_EQ(run.route, "");
  // A root's pose is the first derived line it lacks (BONE-PARENT-1); the
  // case stops there, so BONE-DOWNSTREAM-1 is left unjudged, not excused.
  const ClauseOutcome* parent = clause_in(run, "BONE-PARENT-1");
  ASSERT_NE(parent, nullptr);
  EXPECT_EQ(parent->status, ClauseStatus::Fail) << parent->note;
  const ClauseOutcome* downstream = clause_in(run, "BONE-DOWNSTREAM-1");
  ASSERT_NE(downstream, nullptr);
  EXPECT_NE(downstream->status, ClauseStatus::NotApplicable) << downstream->note;
}

TEST(DeclaredProfileExec, DeclaringNoDerivedMakesThemNotApplicableWithTheDeclarationAsWhy) {
  auto impl = open_node("profile:no-derived");
  ASSERT_TRUE(impl);
  const RunResult run = run_certification(*impl, bone_options());
  EXPECT_NE(run.route.find("profile:no-derived"), std::string::npos) << run.route;
  for (const char* id : {"BONE-DOWNSTREAM-1", "BONE-PARENT-1"}) {
    const ClauseOutcome* co = clause_in(run, id);
    ASSERT_NE(co, nullptr) << id;
    EXPECT_EQ(co->status, ClauseStatus::NotApplicable) << id << ": " << co->note
                                                       << (co->finding ? co->finding->message : "");
    EXPECT_NE(co->note.find("profile:no-derived in its ?capabilities answer"), std::string::npos) << co->note;
  }
  // The program exits if ?derived is asked: nothing else failed either.
  for (const ClauseOutcome& co : run.clauses)
    EXPECT_TRUE(co.status == ClauseStatus::Pass || co.status == ClauseStatus::NotApplicable)
        << co.clause->id << " " << co.status << ": " << co.note << (co.finding ? co.finding->message : "");
}

TEST(DeclaredProfileExec, AnUnknownWordIsNamedInTheReportAndIgnored) {
  auto impl = open_node("profile:teleport");
  ASSERT_TRUE(impl);
  const RunResult run = run_certification(*impl, bone_options());
  EXPECT_NE(run.route.find("not known to this vgc, so limiting nothing: profile:teleport"), std::string::npos)
      << run.route;
  const ClauseOutcome* parent = clause_in(run, "BONE-PARENT-1");
  ASSERT_NE(parent, nullptr);
  EXPECT_EQ(parent->status, ClauseStatus::Fail) << "the unknown word limits nothing: " << parent->note;
  for (const ClauseOutcome& co : run.clauses) EXPECT_NE(co.status, ClauseStatus::NotApplicable) << co.clause->id;
  // The report's header names it too, though it hides no clause.
  const std::string summary = render_summary(run, judge(run, nullptr), ReportContext{});
  EXPECT_NE(summary.find("Route: the exec route with the profile the implementation declares (profile:teleport); "
                         "not known to this vgc, so limiting nothing: profile:teleport."),
            std::string::npos)
      << summary.substr(0, 1500);
}

Program posed_bone() {
  return Program{{C("layer_create 2 \"w\" VERTEX_UINT32 0 0"),
                  C("bone_create 65535 \"w\" \"\" 65535 1 2 3 \"\" 0 0 0 1 \"\"")},
                 std::nullopt};
}

TEST(DeclaredProfileExec, ReplayAsksForTheProfileFirstAndJudgesAsCertifyDid) {
  {
    auto impl = open_node("");
    ASSERT_TRUE(impl);
    const ReplayResult r = replay_program(posed_bone(), *impl);
    ASSERT_TRUE(r.failure);
    EXPECT_EQ(r.failure->clause, "BONE-PARENT-1") << r.failure->message;
  }
  auto impl = open_node("profile:no-derived");
  ASSERT_TRUE(impl);
  const ReplayResult r = replay_program(posed_bone(), *impl);
  EXPECT_FALSE(r.failure) << r.failure->clause << ": " << r.failure->message;
  // The fuzz fast path follows the same limits (the fuzzer asks once when it opens the program).
  const FastCheckResult fast = check_program_fast(posed_bone().commands, *impl);
  EXPECT_FALSE(fast.exact_ran);
  EXPECT_FALSE(fast.replay.failure);
}

TEST(DeclaredProfileExec, CStringNamesAreNotSentANameWithANul) {
  auto impl = open_node("profile:c-string-names");
  ASSERT_TRUE(impl);
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  const Command nul = C("layer_create 2 \"a\\x00b\" VERTEX_REAL 0 0");
  EXPECT_FALSE(impl->apply(nul).not_sent) << "before ?capabilities nothing is declared";
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  ASSERT_EQ(impl->request("?capabilities").status, CallStatus::Ok);
  const Answer a = impl->apply(nul);
  EXPECT_TRUE(a.not_sent);
  EXPECT_NE(a.detail.find("profile:c-string-names"), std::string::npos) << a.detail;
  EXPECT_EQ(impl->snapshot().text.find("layer 2"), std::string::npos) << "the program never saw it";
  EXPECT_TRUE(impl->apply(C("layer_create 2 \"ab\" VERTEX_REAL 0 0")).applied);
}

TEST(DeclaredProfileExec, NoBoneRotationIsNotSentARotationItCannotCarry) {
  auto impl = open_node("profile:no-bone-rotation");
  ASSERT_TRUE(impl);
  ASSERT_EQ(impl->request("?capabilities").status, CallStatus::Ok);
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  ASSERT_TRUE(impl->apply(C("layer_create 2 \"w\" VERTEX_UINT32 0 0")).applied);
  const Answer turned = impl->apply(C("bone_create 0 \"w\" \"\" 65535 0 0 0 \"\" nan 0 0 1 \"\""));
  EXPECT_TRUE(turned.not_sent);
  EXPECT_NE(turned.detail.find("profile:no-bone-rotation"), std::string::npos) << turned.detail;
  EXPECT_EQ(impl->snapshot().text.find("\nbone "), std::string::npos) << "the program never saw it";
  EXPECT_TRUE(impl->apply(C("bone_create 0 \"w\" \"\" 65535 0 0 0 \"\" 0 0 0 1 \"\"")).applied);
}

}  // namespace
}  // namespace vgc
