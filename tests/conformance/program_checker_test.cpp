// program_checker_test.cpp — conformance/program_checker: checking with
// digests finds every divergence check_step finds, at the same command and
// with the same finding (issue 21 item 1), and an implementation whose
// ?digest does not stand for its documents cannot pass.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <string>
#include <vector>

#include "arbitrary_command.h"
#include "command_text.h"
#include "derived_document.h"
#include "faulty_implementation.h"
#include "program_checker.h"
#include "reference_wrapper.h"
#include "runner.h"
#include "scale_mesh.h"
#include "snapshot.h"

namespace vgc {
namespace {

// A program drawn for the reference's states, as a fuzzer or a property would.
std::vector<Command> draw_program(std::uint64_t seed, int length) {
  rc::Random random(seed);
  Node model;
  std::vector<Command> out;
  for (int i = 0; i < length; ++i) {
    const Command c = gen::gen_command_for(model)(random.split(), 40).value();
    model.apply(c);
    out.push_back(c);
  }
  return out;
}

struct Outcome {
  int index = -1;  // the first failing command, -1 for none
  std::string clause, message, notes;
};

Outcome run(Implementation& sut, const std::vector<Command>& program, bool use_digest) {
  Outcome o;
  sut.reset();
  ProgramChecker checker(sut, /*follow_choices=*/true, use_digest);
  EXPECT_EQ(checker.used_digest(), use_digest && sut.offers_digest());
  for (std::size_t i = 0; i < program.size(); ++i) {
    const StepResult r = checker.step(program[i]);
    for (const auto& n : r.notes) o.notes += n.clause + ": " + n.message + "\n";
    if (r.failure) {
      o.index = static_cast<int>(i);
      o.clause = r.failure->clause;
      o.message = r.failure->message;
      return o;
    }
  }
  if (auto l = checker.finish(program)) o.clause = "finish: " + l->step.failure->clause;
  return o;
}

TEST(ProgramChecker, EveryFaultIsFoundAtTheSameCommandWithAndWithoutDigests) {
  int found = 0, programs = 0;
  const auto& catalog = faults::fault_catalog();
  for (int fault = 1; fault < static_cast<int>(catalog.size()); ++fault) {
    if (catalog[static_cast<std::size_t>(fault)].expected_status != "fail") continue;  // crashes and hangs
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const auto program = draw_program(seed * 7919 + static_cast<std::uint64_t>(fault), 40);
      faults::FaultyImplementation with(fault), without(fault);
      const Outcome a = run(with, program, true), b = run(without, program, false);
      ++programs;
      if (a.index >= 0) ++found;
      EXPECT_EQ(a.index, b.index) << catalog[static_cast<std::size_t>(fault)].name << " seed " << seed;
      EXPECT_EQ(a.clause, b.clause) << catalog[static_cast<std::size_t>(fault)].name << " seed " << seed;
      EXPECT_EQ(a.message, b.message) << catalog[static_cast<std::size_t>(fault)].name << " seed " << seed;
      EXPECT_EQ(a.notes, b.notes) << catalog[static_cast<std::size_t>(fault)].name << " seed " << seed;
    }
  }
  // Not vacuous: the drawn programs do find faults.
  EXPECT_GT(found, programs / 8) << found << " of " << programs;
}

// Offers ?digest, and answers the digest of a fresh node's documents
// whatever it holds, while printing its true documents.
class LyingDigest final : public test::ReferenceWrapper {
 public:
  std::string name() const override { return "lying-digest"; }
  bool offers_digest() override { return true; }
  DigestAnswer digest() override {
    if (++calls_ <= honest_calls_) return inner_.digest();
    return {CallStatus::Ok, NodeDigest().digests(), ""};
  }
  int honest_calls_ = 1 << 30;

 private:
  int calls_ = 0;
};

TEST(ProgramChecker, DigestsThatDifferWhileTheDocumentsAgreeAreNoFinding) {
  Program p;
  p.commands = draw_program(3, 30);
  LyingDigest honest;
  EXPECT_FALSE(replay_program(p, honest).failure);
  // From the 6th digest on it lies: each step looks different, is judged on
  // the documents (which agree), and the rest is checked step by step.
  LyingDigest lying;
  lying.honest_calls_ = 5;
  const ReplayResult r = replay_program(p, lying);
  EXPECT_FALSE(r.failure) << r.failure->message;
}

// Prints the documents right but offers a digest that matches the
// reference's documents while the snapshot shows something else: the
// whole comparison at the end finds it, and localizes it.
class HiddenSnapshot final : public test::ReferenceWrapper {
 public:
  std::string name() const override { return "hidden-snapshot"; }
  bool offers_digest() override { return true; }
  DigestAnswer digest() override { return inner_.digest(); }
  Document snapshot() override {
    Document d = inner_.snapshot();
    if (inner_.node().vertices().size() > 2) d.text.insert(d.text.rfind("end\n"), "vertex 4000000000 0 0 0\n");
    return d;
  }
};

TEST(ProgramChecker, DocumentsThatDifferUnderAgreeingDigestsFailAtTheEndAndAreLocalized) {
  Program p;
  for (int i = 0; i < 6; ++i) {
    Command c = cmd::VertexSetXyzReal64{0, static_cast<std::uint32_t>(i), double(i), 0, 0};
    p.commands.push_back(c);
  }
  HiddenSnapshot sut;
  const ReplayResult r = replay_program(p, sut);
  ASSERT_TRUE(r.failure);
  EXPECT_EQ(r.failed_at, 2) << r.failure->message;  // the third vertex: localized step by step
  EXPECT_NE(r.failure->message.find("snapshot"), std::string::npos) << r.failure->message;
}

// The faulty node behind a route that offers no ?digest (as a plugin).
class NoDigest final : public Implementation {
 public:
  explicit NoDigest(int fault) : inner_(fault) {}
  std::string name() const override { return "no-digest"; }
  Answer reset() override { return inner_.reset(); }
  Answer apply(const Command& c) override { return inner_.apply(c); }
  Document snapshot() override {
    ++documents;
    return inner_.snapshot();
  }
  Document derived() override { return inner_.derived(); }
  int documents = 0;

 private:
  faults::FaultyImplementation inner_;
};

// Sparse reading (a property at scale on a route without ?digest) finds a
// node that drops ids past its storage bound at the same command, with the
// same finding, as checking every command (here with digests, which the
// test above shows equal to reading the documents after every command),
// reading the documents far less often.
TEST(ProgramChecker, SparseReadingFindsTheSameCommandAsCheckingEveryStep) {
  const int fault = faults::find_fault("ids-past-storage-bound");
  ASSERT_GT(fault, 0);
  for (int shape = 0; shape < kScaleShapes; ++shape) {
    ScaleCase sc;
    sc.shape = static_cast<ScaleShape>(shape);
    sc.elements = kScaleMinElements;
    sc.seed = static_cast<std::uint64_t>(shape) + 1;
    const auto program = scale_case_commands(sc);
    faults::FaultyImplementation every(fault);
    const Outcome a = run(every, program, true);
    NoDigest sparse(fault);
    sparse.reset();
    ProgramChecker checker(sparse, /*follow_choices=*/true);
    checker.allow_sparse_reading();
    Outcome b;
    for (std::size_t i = 0; i < program.size() && b.index < 0; ++i) {
      const StepResult r = checker.step(program[i]);
      if (r.failure) {
        b.index = checker.failed_at() >= 0 ? checker.failed_at() : static_cast<int>(i);
        b.clause = r.failure->clause;
        b.message = r.failure->message;
      }
    }
    if (b.index < 0)
      if (auto l = checker.finish(program)) b.index = l->index, b.clause = l->step.failure->clause;
    ASSERT_GE(a.index, 100) << describe(sc);
    EXPECT_EQ(a.index, b.index) << describe(sc);
    EXPECT_EQ(a.clause, b.clause) << describe(sc);
    EXPECT_EQ(a.message, b.message) << describe(sc);
    EXPECT_LT(sparse.documents * 20, a.index) << describe(sc) << ": " << sparse.documents << " readings";
  }
}

// Without a fault, sparse reading agrees to the end, and finish() reads the
// documents once more.
TEST(ProgramChecker, SparseReadingOfTheReferenceAgrees) {
  ScaleCase sc;
  sc.shape = ScaleShape::Torus;
  sc.elements = kScaleMinElements;
  sc.spread_ids = true;
  const auto program = scale_case_commands(sc);
  NoDigest sut(0);
  sut.reset();
  ProgramChecker checker(sut, true);
  checker.allow_sparse_reading();
  for (const auto& c : program) ASSERT_FALSE(checker.step(c).failure) << print_command(c);
  EXPECT_FALSE(checker.finish(program));
  EXPECT_LT(sut.documents, 40);
}

}  // namespace
}  // namespace vgc
