// exec_faults_test.cpp — the exec adapter against programs that misbehave
// (tests/adapter/faulty/): each fault becomes the documented CallStatus with
// a useful detail, the suite itself goes on, and reset() brings it back.
#include <errno.h>
#include <signal.h>

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "adapter_test_util.h"

namespace vgc::test {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// True when `pid` is gone: no process, not even an unreaped zombie.
bool reaped(pid_t pid) { return kill(pid, 0) == -1 && errno == ESRCH; }

std::unique_ptr<ExecImplementation> open_exec(const std::string& spec, const OpenOptions& o) {
  std::string error;
  std::unique_ptr<Implementation> impl = open_implementation(spec, o, &error);
  EXPECT_NE(impl, nullptr) << error;
  if (!impl) return nullptr;
  auto* exec = dynamic_cast<ExecImplementation*>(impl.get());
  EXPECT_NE(exec, nullptr);
  if (!exec) return nullptr;
  impl.release();
  return std::unique_ptr<ExecImplementation>(exec);
}

const Command kCommand = cmd::LayerDestroy{7};

TEST(ExecFaults, CrashOnThirdCommandIsACrashAndResetRestartsIt) {
  auto impl = open_exec(faulty_spec("crash_on_third.sh"), test_options(5.0));
  ASSERT_TRUE(impl);
  EXPECT_EQ(impl->identity(), "crash-on-third");
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  const pid_t pid = impl->pid();
  EXPECT_TRUE(impl->apply(kCommand).applied);
  EXPECT_TRUE(impl->apply(kCommand).applied);
  const Answer crash = impl->apply(kCommand);
  EXPECT_EQ(crash.status, CallStatus::Crash);
  EXPECT_NE(crash.detail.find("exited with status 3"), std::string::npos) << crash.detail;
  EXPECT_NE(crash.detail.find("crash_on_third: giving up on command 3"), std::string::npos) << crash.detail;
  EXPECT_TRUE(reaped(pid));
  // Every later call fails the same way without talking to it.
  const auto t0 = Clock::now();
  const Answer again = impl->apply(kCommand);
  EXPECT_EQ(again.status, CallStatus::Crash);
  EXPECT_NE(again.detail.find("giving up"), std::string::npos) << again.detail;
  EXPECT_NE(again.detail.find("not sent"), std::string::npos) << again.detail;
  EXPECT_EQ(impl->snapshot().status, CallStatus::Crash);
  EXPECT_EQ(impl->derived().status, CallStatus::Crash);
  EXPECT_LT(seconds_since(t0), 0.1);
  // reset() starts a new process, which works again.
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  EXPECT_NE(impl->pid(), pid);
  EXPECT_TRUE(impl->apply(kCommand).applied);
  const Document s = impl->snapshot();
  EXPECT_EQ(s.status, CallStatus::Ok);
  EXPECT_EQ(s.text, "vgc-snapshot 1\nend\n");
}

TEST(ExecFaults, HangIsATimeoutWithinTheLimitAndTheSuiteGoesOn) {
  auto impl = open_exec(faulty_spec("hang_on_command.sh"), test_options(0.5));
  ASSERT_TRUE(impl);
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  const pid_t pid = impl->pid();
  auto t0 = Clock::now();
  const Answer a = impl->apply(kCommand);
  const double took = seconds_since(t0);
  EXPECT_EQ(a.status, CallStatus::Timeout);
  EXPECT_GE(took, 0.45);
  EXPECT_LT(took, 2.0);
  EXPECT_NE(a.detail.find("within 0.5 s"), std::string::npos) << a.detail;
  EXPECT_NE(a.detail.find("hang_on_command: sleeping on"), std::string::npos) << a.detail;
  EXPECT_TRUE(reaped(pid));
  t0 = Clock::now();
  EXPECT_EQ(impl->apply(kCommand).status, CallStatus::Timeout);
  EXPECT_LT(seconds_since(t0), 0.1);
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  EXPECT_NE(impl->pid(), pid);
  EXPECT_EQ(impl->apply(kCommand).status, CallStatus::Timeout);
}

TEST(ExecFaults, GarbageAnswersAreProtocolErrorsQuotingTheLine) {
  {
    auto impl = open_exec(faulty_spec("garbage_answer.sh", "words"), test_options(5.0));
    ASSERT_TRUE(impl);
    ASSERT_EQ(impl->reset().status, CallStatus::Ok);
    const Answer a = impl->apply(kCommand);
    EXPECT_EQ(a.status, CallStatus::ProtocolError);
    EXPECT_NE(a.detail.find("\"sure, why not\""), std::string::npos) << a.detail;
    EXPECT_NE(a.detail.find("layer_destroy 7"), std::string::npos) << a.detail;
    EXPECT_EQ(impl->apply(kCommand).status, CallStatus::ProtocolError);  // sticky
    ASSERT_EQ(impl->reset().status, CallStatus::Ok);                     // until reset
    EXPECT_EQ(impl->snapshot().status, CallStatus::Ok);
  }
  {
    auto impl = open_exec(faulty_spec("garbage_answer.sh", "reason2"), test_options(5.0));
    ASSERT_TRUE(impl);
    ASSERT_EQ(impl->reset().status, CallStatus::Ok);
    const Answer a = impl->apply(kCommand);
    EXPECT_EQ(a.status, CallStatus::ProtocolError);
    EXPECT_NE(a.detail.find("\"rejected NO SUCH_LAYER\""), std::string::npos) << a.detail;
  }
  {
    auto impl = open_exec(faulty_spec("garbage_answer.sh", "document"), test_options(5.0));
    ASSERT_TRUE(impl);
    ASSERT_EQ(impl->reset().status, CallStatus::Ok);
    EXPECT_TRUE(impl->apply(kCommand).applied);
    const auto t0 = Clock::now();
    const Document d = impl->snapshot();
    EXPECT_EQ(d.status, CallStatus::ProtocolError);
    EXPECT_NE(d.detail.find("\"here you go\""), std::string::npos) << d.detail;
    EXPECT_LT(seconds_since(t0), 1.0);  // found at once, not by timing out
  }
  {
    auto impl = open_exec(faulty_spec("garbage_answer.sh", "twice"), test_options(5.0));
    ASSERT_TRUE(impl);
    ASSERT_EQ(impl->reset().status, CallStatus::Ok);
    EXPECT_TRUE(impl->apply(kCommand).applied);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // its second "ok" has arrived
    const Answer a = impl->apply(kCommand);
    EXPECT_EQ(a.status, CallStatus::ProtocolError);
    EXPECT_NE(a.detail.find("wrote \"ok\" before being sent"), std::string::npos) << a.detail;
  }
}

TEST(ExecFaults, AProgramThatNeverAnswersHelloDoesNotOpen) {
  std::string error;
  const auto t0 = Clock::now();
  OpenOptions o = test_options(30);
  o.start_timeout_seconds = 0.5;  // the start's own limit (--start-timeout), not the per-call one
  auto impl = open_implementation(faulty_spec("silent_hello.sh"), o, &error);
  EXPECT_EQ(impl, nullptr);
  EXPECT_LT(seconds_since(t0), 2.0);
  EXPECT_NE(error.find("timeout"), std::string::npos) << error;
  EXPECT_NE(error.find("within 0.5 s (--start-timeout)"), std::string::npos) << error;
  EXPECT_NE(error.find("?hello"), std::string::npos) << error;
  EXPECT_NE(error.find("silent_hello: ignoring ?hello"), std::string::npos) << error;
}

TEST(ExecFaults, AWrongHelloDoesNotOpen) {
  std::string error;
  EXPECT_EQ(open_implementation("exec:read l; echo hello; cat >/dev/null", test_options(5.0), &error), nullptr);
  EXPECT_NE(error.find("protocol-error"), std::string::npos) << error;
  EXPECT_NE(error.find("\"hello\""), std::string::npos) << error;
  EXPECT_EQ(open_implementation("exec:read l; echo vgc-exec 2 future; cat >/dev/null", test_options(5.0), &error), nullptr);
  EXPECT_NE(error.find("version \"2\""), std::string::npos) << error;
}

TEST(ExecFaults, AMissingProgramDoesNotOpenAndSaysWhy) {
  std::string error;
  EXPECT_EQ(open_implementation("exec:/nonexistent/vgc-host --serve", test_options(5.0), &error), nullptr);
  EXPECT_NE(error.find("crash"), std::string::npos) << error;
  EXPECT_NE(error.find("exited with status 127"), std::string::npos) << error;
  EXPECT_NE(error.find("/nonexistent/vgc-host"), std::string::npos) << error;
}

TEST(ExecFaults, StderrFloodAndCrlfLineEndsAreFine) {
  auto impl = open_exec(faulty_spec("polite_noise.py"), test_options(10.0));
  ASSERT_TRUE(impl);
  EXPECT_EQ(impl->identity(), "polite-noise");
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(impl->apply(kCommand).applied);
  const Document s = impl->snapshot();
  EXPECT_EQ(s.status, CallStatus::Ok) << s.detail;
  EXPECT_EQ(s.text, "vgc-snapshot 1\nend\n");
  const std::string tail = impl->stderr_tail();
  EXPECT_FALSE(tail.empty());
  EXPECT_LE(tail.size(), 20u * 302u);  // bounded: 20 lines of at most 300 bytes
}

TEST(ExecFaults, WritingToAClosedInputIsACrashNotSigpipe) {
  // "exec" so that no wrapper shell keeps a copy of the program's stdin open:
  // then the suite's write really meets a pipe without reader (EPIPE).
  auto impl = open_exec("exec:exec " + faulty_spec("closes_input.sh").substr(5), test_options(5.0));
  ASSERT_TRUE(impl);
  ASSERT_EQ(impl->reset().status, CallStatus::Ok);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // it has closed its stdin by now
  const Answer a = impl->apply(kCommand);
  EXPECT_EQ(a.status, CallStatus::Crash);
  EXPECT_NE(a.detail.find("input was closed"), std::string::npos) << a.detail;
}

TEST(ExecFaults, AnOverlongAnswerIsAProtocolErrorAndBoundsMemory) {
  OpenOptions o = test_options(5.0);
  o.max_answer_bytes = 1 << 20;
  auto impl = open_exec("exec:read l; echo vgc-exec 1 big; read l; head -c 3000000 /dev/zero | tr '\\0' x; cat >/dev/null", o);
  ASSERT_TRUE(impl);
  const auto t0 = Clock::now();
  const Answer a = impl->reset();
  EXPECT_EQ(a.status, CallStatus::ProtocolError);
  EXPECT_NE(a.detail.find("longer than 1048576 bytes"), std::string::npos) << a.detail;
  EXPECT_LT(seconds_since(t0), 4.0);
}

TEST(ExecFaults, TheDestructorEndsAndReapsTheProgram) {
  auto impl = open_exec(faulty_spec("hang_on_command.sh"), test_options(5.0));
  ASSERT_TRUE(impl);
  const pid_t pid = impl->pid();
  ASSERT_GT(pid, 0);
  EXPECT_FALSE(reaped(pid));
  impl.reset();
  EXPECT_TRUE(reaped(pid));
}

TEST(OpenImplementation, MalformedSpecsNameTheThreeForms) {
  for (const std::string spec : {"", "refrence", "exec:", "exec:   ", "plugin:", "dll:/x.so"}) {
    std::string error;
    EXPECT_EQ(open_implementation(spec, test_options(), &error), nullptr) << spec;
    EXPECT_NE(error.find("reference"), std::string::npos) << error;
    EXPECT_NE(error.find("exec:CMD"), std::string::npos) << error;
    EXPECT_NE(error.find("plugin:PATH"), std::string::npos) << error;
  }
}

}  // namespace
}  // namespace vgc::test
