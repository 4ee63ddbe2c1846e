// verse_route_test.cpp — `--impl verse:HOST[:PORT]` against `vgc serve
// --verse`: the reference node served as a Verse host on loopback, certified
// over the wire (conformance/adapter/verse_implementation.h).
//
// Spec: docs/adapters.md section 7 (the Verse wire route: what it judges,
// what it cannot); docs/certify.md "Clause statuses" (not-applicable).
//
// Each test starts its own host on a free port (`vgc serve --verse
// 127.0.0.1:0` prints the port it bound) and kills it at the end; every
// wait is bounded.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "adapter_test_util.h"
#include "command_gen.h"
#include "document_diff.h"
#include "snapshot.h"
#include "wire_commands.h"
#include "implementation.h"
#include "untold.h"
#include "report.h"
#include "restartable_host.h"
#include "route.h"
#include "runner.h"
#include "verdict.h"
#include "verse_implementation.h"
#include "default_run.h"

namespace vgc {
namespace {

// `vgc serve --verse 127.0.0.1:0 [extra]` as a child process, with `env`
// added to its environment.
class ServedHost {
 public:
  ServedHost(const std::vector<std::string>& extra, const std::vector<std::string>& env) {
    int out[2];
    if (pipe(out) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      dup2(out[1], STDOUT_FILENO);
      close(out[0]);
      close(out[1]);
      for (const auto& e : env) putenv(const_cast<char*>(e.c_str()));
      std::vector<std::string> args = {VGC_BINARY, "serve", "--verse", "127.0.0.1:0"};
      args.insert(args.end(), extra.begin(), extra.end());
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(VGC_BINARY, argv.data());
      _exit(127);
    }
    close(out[1]);
    out_ = out[0];
    // "vgc-verse listening ADDR:PORT", within 30 s.
    std::string line;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (line.find('\n') == std::string::npos && std::chrono::steady_clock::now() < deadline) {
      pollfd p{out_, POLLIN, 0};
      if (poll(&p, 1, 200) <= 0) continue;
      char buf[256];
      const ssize_t n = read(out_, buf, sizeof buf);
      if (n <= 0) break;
      line.append(buf, static_cast<std::size_t>(n));
    }
    line_ = line.substr(0, line.find('\n'));
    const auto colon = line_.rfind(':');
    if (line_.rfind("vgc-verse listening ", 0) == 0 && colon != std::string::npos)
      port_ = static_cast<std::uint16_t>(std::atoi(line_.c_str() + colon + 1));
  }
  ~ServedHost() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (out_ >= 0) close(out_);
  }
  std::uint16_t port() const { return port_; }
  const std::string& line() const { return line_; }
  std::string spec() const { return "verse:127.0.0.1:" + std::to_string(port_); }
  void signal(int sig) { kill(pid_, sig); }

 private:
  pid_t pid_ = -1;
  int out_ = -1;
  std::uint16_t port_ = 0;
  std::string line_;
};

// A login (the start's limit, --start-timeout) is given 10 s at least: a
// host that went silent costs one such wait (then vgc stops asking).
std::unique_ptr<Implementation> open_verse(const ServedHost& host, double timeout_seconds = 5.0) {
  std::string error;
  OpenOptions o = test::test_options(timeout_seconds);
  o.start_timeout_seconds = std::max(10.0, timeout_seconds);
  auto sut = open_implementation(host.spec(), o, &error);
  EXPECT_NE(sut, nullptr) << error;
  return sut;
}

RunOptions options(int cases) { return unhurried_run(1, cases, 50); }

// The wire cannot tell a command from its alias (docs/spec_facts.md
// section 4): what the host receives for `c` decodes as wire_canonical(c).
// So no property may expect different outcomes for the two forms over this
// route: on every state the properties reach, the reference gives both the
// same verdict and the same state.
RC_GTEST_PROP(VerseRoute, ACommandAndItsWireFormHaveTheSameOutcome, ()) {
  Node model;
  const auto focus = *rc::gen::element(Focus::Layers, Focus::Polygons, Focus::Creases, Focus::Bones, Focus::Values,
                                       Focus::Ids, Focus::Anything);
  const auto n = *rc::gen::inRange(1, 40);
  for (int i = 0; i < n; ++i) {
    const Command c = *gen_command(model, focus);
    const Command wire = verse::wire_canonical(c);
    Node as_sent = model, as_received = model;
    const Reason a = as_sent.apply(c), b = as_received.apply(wire);
    RC_ASSERT((a == Reason::Ok) == (b == Reason::Ok));
    RC_ASSERT(print_snapshot(as_sent) == print_snapshot(as_received));
    model = std::move(as_sent);
  }
}

TEST(VerseRoute, AddressesParseAndBadOnesSayWhatToDo) {
  std::string name, host, error;
  std::uint16_t port = 0;
  ASSERT_TRUE(parse_verse_address("localhost", &name, &host, &port, &error)) << error;
  EXPECT_EQ(host, "localhost");
  EXPECT_EQ(port, 4950);
  EXPECT_EQ(name, "vgc");
  ASSERT_TRUE(parse_verse_address("alice@10.0.0.7:4951", &name, &host, &port, &error)) << error;
  EXPECT_EQ(name, "alice");
  EXPECT_EQ(host, "10.0.0.7");
  EXPECT_EQ(port, 4951);
  EXPECT_FALSE(parse_verse_address("", &name, &host, &port, &error));
  EXPECT_NE(error.find("verse:HOST[:PORT]"), std::string::npos) << error;
  EXPECT_FALSE(parse_verse_address("localhost:99999", &name, &host, &port, &error));
  EXPECT_NE(error.find("not a port"), std::string::npos) << error;
  EXPECT_FALSE(parse_verse_address("localhost:", &name, &host, &port, &error));
}

TEST(VerseRoute, NoHostListeningIsAClearErrorWithinTheTimeout) {
  // A port of a socket we hold and never read: nothing answers there.
  ServedHost host({}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  host.signal(SIGSTOP);
  std::string error;
  const auto start = std::chrono::steady_clock::now();
  OpenOptions o = test::test_options(30);
  o.start_timeout_seconds = 0.5;  // a login is a start: its own limit
  auto sut = open_implementation(host.spec(), o, &error);
  EXPECT_EQ(sut, nullptr);
  EXPECT_NE(error.find("cannot certify this host (timeout)"), std::string::npos) << error;
  EXPECT_NE(error.find("(--start-timeout)"), std::string::npos) << error;
  EXPECT_NE(error.find("Is a Verse host listening there"), std::string::npos) << error;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));  // bounded, not a hang
  host.signal(SIGCONT);
}

TEST(VerseRoute, TheServedReferenceIsConformantOverTheWire) {
  ServedHost host({}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  auto sut = open_verse(host);
  ASSERT_NE(sut, nullptr);
  const RunResult run = run_certification(*sut, options(60));
  int not_applicable = 0;
  for (const ClauseOutcome& co : run.clauses) {
    EXPECT_TRUE(co.status == ClauseStatus::Pass || co.status == ClauseStatus::NotApplicable)
        << co.clause->id << " " << co.status << ": " << co.note << (co.finding ? " " + co.finding->message : "");
    if (co.status == ClauseStatus::NotApplicable) {
      ++not_applicable;
      EXPECT_EQ(co.note.rfind("not judgeable over the Verse wire: ", 0), 0u) << co.clause->id << ": " << co.note;
    }
  }
  EXPECT_GT(not_applicable, 0);
  EXPECT_EQ(run.route, "the Verse wire");
  EXPECT_GT(run.unreported_verdicts, 0);  // every answer is `done`
  EXPECT_TRUE(judge(run, nullptr).new_failures.empty());
  EXPECT_TRUE(run.complete);
  EXPECT_EQ(judge(run, nullptr).name, "conformant");
}

// A host that plays r6 (vgc serve --verse --like-r6): ids reused after a
// destroy, bone_create in r6's form. The default --verse-bone-form auto
// finds the form, says so, and the run finishes with nothing left
// unchecked for a time-out or the budget.
TEST(VerseRoute, AHostLikeR6IsCertifiedToTheEndInItsBoneForm) {
  ServedHost host({"--like-r6"}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  auto sut = open_verse(host);
  ASSERT_NE(sut, nullptr);
  EXPECT_NE(sut->identity().find("bone_create in the r6 form"), std::string::npos) << sut->identity();
  const RunResult run = run_certification(*sut, options(30));
  for (const ClauseOutcome& co : run.clauses) {
    EXPECT_NE(co.status, ClauseStatus::Unchecked) << co.clause->id << ": " << co.note;
    EXPECT_NE(co.status, ClauseStatus::Timeout) << co.clause->id << ": " << (co.finding ? co.finding->message : co.note);
    EXPECT_NE(co.status, ClauseStatus::Crash) << co.clause->id << ": " << (co.finding ? co.finding->message : co.note);
    if (co.clause->id == "BONE-CREATE-1" || co.clause->id == "BONE-DESTROY-1" || co.clause->id == "BONE-NAME-1") {
      EXPECT_EQ(co.status, ClauseStatus::Pass) << co.clause->id << ": " << (co.finding ? co.finding->message : co.note);
    }
  }
}

// A certification resets the node before every case (thousands of times
// per run), and on a loaded machine every round trip through the host costs
// milliseconds (docs/verse_wire.md "Where the time of a wire run goes"): a
// reset takes a node made ahead, in a batch, instead of making one and
// waiting three times for the host. Each reset still gives a fresh node.
TEST(VerseRoute, AResetCostsLessThanOneRoundTripOnAverage) {
  ServedHost host({"--like-r6"}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  auto sut = open_verse(host);
  ASSERT_NE(sut, nullptr);
  auto* verse = dynamic_cast<VerseImplementation*>(sut.get());
  ASSERT_NE(verse, nullptr);
  const std::string fresh = print_snapshot(Node{});
  const Command layer = cmd::LayerCreate{2, "w", static_cast<std::uint8_t>(LayerType::VertexUint32), 0, 0};
  const Command vertex = cmd::VertexSetXyzReal64{0, 3, 1, 2, 3};
  const std::uint64_t before = verse->round_trips();
  constexpr int kResets = 64;
  for (int i = 0; i < kResets; ++i) {
    ASSERT_EQ(sut->reset().status, CallStatus::Ok) << "reset " << i;
    const Document d = sut->snapshot();
    ASSERT_EQ(d.status, CallStatus::Ok);
    EXPECT_EQ(without_subscriptions(d.text), without_subscriptions(fresh)) << "reset " << i << " is not a fresh node";
    ASSERT_EQ(sut->apply(i % 2 ? layer : vertex).status, CallStatus::Ok);  // each node is used before the next reset
  }
  const std::uint64_t per_reset_and_command = verse->round_trips() - before;
  // One round trip per command (its barrier; the layer_create two: the
  // observer subscribes to the new layer), less than one per reset.
  EXPECT_LT(per_reset_and_command, static_cast<std::uint64_t>(kResets + kResets / 2 + kResets))
      << per_reset_and_command << " round trips for " << kResets << " resets and commands";
}

TEST(VerseRoute, ASeededFaultInTheServedNodeIsNamedWithItsClause) {
  ServedHost host({"--impl", std::string("plugin:") + VGC_FAULT_PLUGIN}, {"VGC_FAULT=polygon-delete-ignored"});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  auto sut = open_verse(host);
  ASSERT_NE(sut, nullptr);
  RunOptions o = options(40);
  o.clause_glob = "POLY-*";
  const RunResult run = run_certification(*sut, o);
  bool named = false;
  for (const ClauseOutcome& co : run.clauses)
    if (co.clause->id == "POLY-DELETE-1") {
      named = co.status == ClauseStatus::Fail && co.finding;
      EXPECT_TRUE(named) << co.status << ": " << co.note;
      if (co.finding) {
        EXPECT_NE(co.finding->message.find("observed done, and the state is unchanged"), std::string::npos)
            << co.finding->message;
      }
    }
  EXPECT_TRUE(named);
  EXPECT_FALSE(judge(run, nullptr).new_failures.empty());
}

// Issue 27 item 2: a host's broadcasts are its verdicts. A host that, as
// r6 does, sends its subscribers the delete of a vertex that is not live
// (`--r6-deviation announce-missing-deletes`) applied the delete, although
// the state the watching session built does not change: VERTEX-DELETE-1
// fails on the verdict. (main's route judged the unchanged state as the
// delete dropped and passed it.)
TEST(VerseRoute, ABroadcastOfARefusedCommandIsItsVerdict) {
  ServedHost host({"--r6-deviation", "announce-missing-deletes"}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  auto sut = open_verse(host);
  ASSERT_NE(sut, nullptr);
  RunOptions o = options(40);
  o.clause_glob = "VERTEX-*";
  const RunResult run = run_certification(*sut, o);
  bool named = false;
  for (const ClauseOutcome& co : run.clauses) {
    if (co.clause->id != "VERTEX-DELETE-1") {
      EXPECT_TRUE(co.status == ClauseStatus::Pass || co.status == ClauseStatus::NotApplicable)
          << co.clause->id << " " << co.status << ": " << (co.finding ? co.finding->message : co.note);
      continue;
    }
    ASSERT_TRUE(co.finding) << co.status << ": " << co.note;
    named = co.status == ClauseStatus::Fail;
    EXPECT_NE(co.finding->message.find("the host sent its subscribers `vertex_delete"), std::string::npos)
        << co.finding->message;
  }
  EXPECT_TRUE(named);
}

// Issue 29 item 7: a finding on the wire carries what the host sent back
// after the counterexample's last command, as the route's mirror applied
// it (Finding::host_sent), so that a person reading it at 2 a.m. sees what
// the host said and not only what vgc concluded from it. A host that
// announces a delete it did not apply shows that delete; a host that
// ignores a polygon delete shows that it sent nothing.
TEST(VerseRoute, AFindingCarriesWhatTheHostSentBackAfterItsLastCommand) {
  {
    ServedHost host({"--r6-deviation", "announce-missing-deletes"}, {});
    ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
    auto sut = open_verse(host);
    ASSERT_NE(sut, nullptr);
    RunOptions o = options(40);
    o.clause_glob = "VERTEX-DELETE-*";
    const RunResult run = run_certification(*sut, o);
    bool seen = false;
    for (const ClauseOutcome& co : run.clauses) {
      if (co.clause->id != "VERTEX-DELETE-1" || !co.finding) continue;
      seen = true;
      // What the host announced for the last command (the deviation sends
      // a vertex_delete, whatever the command) is what it sent back first.
      EXPECT_TRUE(co.finding->host_sent_seen);
      ASSERT_EQ(co.finding->host_sent_count, co.finding->host_sent.size());
      ASSERT_FALSE(co.finding->host_sent.empty()) << co.finding->message;
      EXPECT_EQ(co.finding->host_sent.front().rfind("vertex_delete ", 0), 0u) << co.finding->host_sent.front();
      EXPECT_NE(co.finding->message.find("the host sent its subscribers `" + co.finding->host_sent.front() + "`"),
                std::string::npos)
          << co.finding->message;
    }
    EXPECT_TRUE(seen);
  }
  {
    ServedHost host({"--impl", std::string("plugin:") + VGC_FAULT_PLUGIN}, {"VGC_FAULT=polygon-delete-ignored"});
    ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
    auto sut = open_verse(host);
    ASSERT_NE(sut, nullptr);
    RunOptions o = options(40);
    o.clause_glob = "POLY-DELETE-*";
    const RunResult run = run_certification(*sut, o);
    bool seen = false;
    for (const ClauseOutcome& co : run.clauses) {
      if (co.clause->id != "POLY-DELETE-1" || !co.finding) continue;
      seen = true;
      EXPECT_TRUE(co.finding->host_sent_seen) << co.finding->message;
      EXPECT_EQ(co.finding->host_sent_count, 0u) << co.finding->host_sent.front();
      EXPECT_TRUE(co.finding->host_sent.empty());
    }
    EXPECT_TRUE(seen);
  }
}

// Issue 27 item 3: a late subscriber. A host that tells a session
// subscribing later another default for a VERTEX_XYZ layer than it told
// those who watched the layer's creation (`--r6-deviation xyz-no-default`,
// r6 keeps no default for such a layer) is seen only by a session that
// subscribes after the case: LAYER-CREATE-1 fails, as hidden state, blamed
// by provenance on the layer's creation, and the counterexample replays
// so. The served reference with no deviation stays conformant
// (TheServedReferenceIsConformantOverTheWire).
TEST(VerseRoute, ALateSubscriberSeesWhatTheWatchersWereNotTold) {
  ServedHost host({"--r6-deviation", "xyz-no-default"}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  auto sut = open_verse(host);
  ASSERT_NE(sut, nullptr);
  RunOptions o = options(60);
  o.clause_glob = "LAYER-*";
  const RunResult run = run_certification(*sut, o);
  std::optional<Program> program;
  for (const ClauseOutcome& co : run.clauses) {
    if (co.clause->id == "LAYER-CREATE-1") {
      ASSERT_TRUE(co.finding) << co.status << ": " << co.note;
      EXPECT_EQ(co.status, ClauseStatus::Fail);
      EXPECT_EQ(co.finding->message.rfind("late subscriber: ", 0), 0u) << co.finding->message;
      EXPECT_NE(co.finding->message.find("VERTEX_XYZ - 0 -"), std::string::npos) << co.finding->message;
      program = co.program;
    } else if (co.clause->id != "LAYER-RECREATE-1") {  // a re-typed XYZ layer: the same deviation, IMPL.-DEFINED
      EXPECT_TRUE(co.status == ClauseStatus::Pass || co.status == ClauseStatus::NotApplicable)
          << co.clause->id << " " << co.status << ": " << (co.finding ? co.finding->message : co.note);
    }
  }
  ASSERT_TRUE(program);
  const ReplayResult r = replay_program(*program, *sut);
  ASSERT_TRUE(r.failure);
  EXPECT_EQ(r.failure->clause, "LAYER-CREATE-1") << r.failure->message;
  EXPECT_EQ(r.failure->message.rfind("late subscriber: ", 0), 0u) << r.failure->message;
}

// Issue 27 item 3, r6's fifth behaviour: a session that subscribes to a
// layer at REAL32 and then at REAL64 is kept on both lists and gets every
// value twice (`--r6-deviation both-formats`). The late subscriber watches
// layer 0 of every node so subscribed; a REAL32 value it is sent during
// the case is LAYER-SUBSCRIBE-1's (on the wire otherwise not judgeable).
TEST(VerseRoute, ASubscriptionInTwoFormatsIsFound) {
  ServedHost host({"--r6-deviation", "both-formats"}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  auto sut = open_verse(host);
  ASSERT_NE(sut, nullptr);
  RunOptions o = options(20);
  o.clause_glob = "VERTEX-*,LAYER-SUBSCRIBE-1";
  const RunResult run = run_certification(*sut, o);
  bool named = false;
  for (const ClauseOutcome& co : run.clauses) {
    if (co.clause->id != "LAYER-SUBSCRIBE-1") {
      EXPECT_TRUE(co.status == ClauseStatus::Pass || co.status == ClauseStatus::NotApplicable)
          << co.clause->id << " " << co.status << ": " << (co.finding ? co.finding->message : co.note);
      continue;
    }
    ASSERT_TRUE(co.finding) << co.status << ": " << co.note;
    named = co.status == ClauseStatus::Fail;
    EXPECT_NE(co.finding->message.find("a REAL32 value after its REAL64 subscription"), std::string::npos)
        << co.finding->message;
  }
  EXPECT_TRUE(named);
}

// The host stops answering after the first property (SIGSTOP): the rest of
// the run is timeouts, bounded by --timeout, and the report is written.
// A certification of LAYER-* and POLY-* (10 cases) against `host`, which
// is stopped (SIGSTOP) after the first property and let go at the end.
RunResult run_silenced_after_one_property(ServedHost& host, double timeout_seconds) {
  auto sut = open_verse(host, timeout_seconds);
  EXPECT_NE(sut, nullptr);
  if (!sut) return {};
  RunOptions o = options(10);
  o.clause_glob = "LAYER-*,POLY-*";
  bool silenced = false;
  o.property_done = [&](const PropertyOutcome&, const RunProgress&) {
    if (!silenced) host.signal(SIGSTOP), silenced = true;
  };
  const RunResult run = run_certification(*sut, o);
  host.signal(SIGCONT);
  EXPECT_TRUE(silenced);
  return run;
}

TEST(VerseRoute, AHostThatGoesSilentGivesTimeoutsAndAFinishedReport) {
  ServedHost host({}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  const RunResult run = run_silenced_after_one_property(host, 1.0);
  bool timeout = false;
  for (const ClauseOutcome& co : run.clauses) timeout = timeout || co.status == ClauseStatus::Timeout;
  EXPECT_TRUE(timeout) << "no clause timed out";
  EXPECT_FALSE(judge(run, nullptr).new_failures.empty());
  const std::string root = ::testing::TempDir() + "vgc-verse-silent";
  std::filesystem::remove_all(root);
  ReportContext ctx;
  ctx.implementation_spec = host.spec();
  ctx.command_line = "vgc certify --impl " + host.spec();
  ctx.started = "2026-11-23T00:00:00Z";
  ctx.run_dir = default_run_dir(root, run, ctx);
  std::string error;
  ASSERT_TRUE(write_report(root, run, judge(run, nullptr), ctx, &error)) << error;
  EXPECT_TRUE(std::filesystem::exists(ctx.run_dir + "/report.json"));
  std::filesystem::remove_all(root);
}

// Issue 31: a host that stops answering (SIGSTOP) is a time-out, at the
// default --timeout too, and never a crash of the session nor a finding
// that "depends on the implementation's history": no fresh instance of it
// can be started, so nothing can be confirmed or refuted, and the finding
// says that it is unconfirmed. (A time-out between two commands, at a
// reset, is STABLE-1's: "an implementation answers every call".) (The route used to take the driver's 1 s
// without acknowledgements for a dropped session, a crash, and the
// confirmation's failed login for "does not reproduce".)
TEST(VerseRoute, AHostThatGoesSilentIsATimeoutNotACrashNorHistory) {
  ServedHost host({}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  const RunResult run = run_silenced_after_one_property(host, 5.0);
  int timeouts = 0;
  for (const ClauseOutcome& co : run.clauses) {
    const std::string what = std::string(co.clause->id) + " " + clause_status_name(co.status) + ": " +
                             (co.finding ? co.finding->message : co.note);
    EXPECT_NE(co.status, ClauseStatus::Crash) << what;
    if (co.finding) {
      EXPECT_EQ(co.finding->message.find("depends on the implementation's history"), std::string::npos) << what;
    }
    if (co.status != ClauseStatus::Timeout) continue;
    ++timeouts;
    ASSERT_TRUE(co.finding) << what;
    EXPECT_NE(co.finding->message.find("not confirmed on a fresh instance"), std::string::npos) << what;
  }
  EXPECT_GT(timeouts, 0) << "no clause timed out";
  EXPECT_FALSE(judge(run, nullptr).new_failures.empty());
}

// ... and a host that is only slow (stopped for 1.5 s, as a starved
// process on a loaded machine acknowledges late) is neither a crash nor a
// time-out: the driver's packets stay unacknowledged past the route's 1 s,
// the observer's round trip then comes back, and so do the driver's
// acknowledgements. (The route used to end the driver's session at 1 s:
// a STABLE-1 crash against a served reference at load 15.)
TEST(VerseRoute, AHostThatIsOnlySlowIsNeitherACrashNorATimeout) {
  ServedHost host({}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  auto sut = open_verse(host, 5.0);
  ASSERT_NE(sut, nullptr);
  RunOptions o = options(10);
  o.clause_glob = "LAYER-*,POLY-*";
  std::thread resume;
  o.property_done = [&](const PropertyOutcome&, const RunProgress&) {
    if (resume.joinable()) return;
    host.signal(SIGSTOP);
    resume = std::thread([&host] {
      std::this_thread::sleep_for(std::chrono::milliseconds(1500));
      host.signal(SIGCONT);
    });
  };
  const RunResult run = run_certification(*sut, o);
  if (resume.joinable()) resume.join();
  ASSERT_TRUE(resume.get_id() == std::thread::id());
  for (const ClauseOutcome& co : run.clauses)
    EXPECT_TRUE(co.status == ClauseStatus::Pass || co.status == ClauseStatus::NotApplicable)
        << co.clause->id << " " << clause_status_name(co.status) << ": "
        << (co.finding ? co.finding->message : co.note);
}

// `vgc certify` through the CLI against a faulty served node, then the
// replay line its report prints, run as printed: it names the clause.
TEST(VerseRoute, TheReplayLinePrintedForAWireFindingWorksAsPrinted) {
  ServedHost host({"--impl", std::string("plugin:") + VGC_FAULT_PLUGIN}, {"VGC_FAULT=polygon-delete-ignored"});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  const std::string dir = ::testing::TempDir() + "vgc-verse-replay";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string certify = "cd " + shell_quote(dir) + " && " + shell_quote(VGC_BINARY) +
                              " certify --quiet --cases 30 --clauses 'POLY-*' --impl " + host.spec() +
                              " > certify.out 2>&1";
  const int rc = std::system(certify.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 1) << test::read_text(dir + "/certify.out");
  const auto report = nlohmann::json::parse(test::read_text(dir + "/reports/latest/report.json"), nullptr, false);
  ASSERT_FALSE(report.is_discarded());
  std::string replay;
  for (const auto& c : report["clauses"])
    if (c["id"] == "POLY-DELETE-1" && c.contains("replay")) replay = c["replay"];
  ASSERT_FALSE(replay.empty()) << report.dump(1);
  EXPECT_NE(replay.find(host.spec()), std::string::npos) << replay;
  // As printed ("./vgc replay ..."), from a directory where ./vgc is the
  // vgc binary (in a checkout it is the wrapper script that runs it).
  std::filesystem::create_symlink(VGC_BINARY, dir + "/vgc");
  const std::string line = replay;
  const int replayed = std::system(("cd " + shell_quote(dir) + " && " + line + " > replay.out 2>&1").c_str());
  ASSERT_TRUE(WIFEXITED(replayed));
  EXPECT_EQ(WEXITSTATUS(replayed), 1) << line << "\n" << test::read_text(dir + "/replay.out");
  EXPECT_NE(test::read_text(dir + "/replay.out").find("POLY-DELETE-1"), std::string::npos)
      << test::read_text(dir + "/replay.out");
  std::filesystem::remove_all(dir);
}

// A host vgc did not start has a fresh instance only through the user's
// restart command (restartable_host.h, `certify --restart` as `fuzz
// --restart`): restart() runs it, logs in again and counts the instance;
// a command that fails leaves every call a crash that says why, sending
// nothing. (Seen failing with restart() left without the new login: the
// snapshot after it was a crash "no session".)
TEST(VerseRoute, ARestartCommandGivesAFreshInstance) {
  ServedHost host({}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  const std::string dir = ::testing::TempDir() + "vgc-verse-restart";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::string error;
  const std::optional<Route> route = parse_route(host.spec(), &error);
  ASSERT_TRUE(route) << error;
  OpenOptions o = test::test_options(5.0);
  o.start_timeout_seconds = 10;
  auto sut = open_restartable(*route, o, "touch " + shell_quote(dir + "/restarted"), &error);
  ASSERT_NE(sut, nullptr) << error;
  EXPECT_EQ(sut->name(), host.spec());
  EXPECT_EQ(sut->instance(), 0u);
  ASSERT_EQ(sut->reset().status, CallStatus::Ok);
  ASSERT_EQ(sut->apply(cmd::LayerCreate{2, "kept", static_cast<std::uint8_t>(LayerType::VertexUint32), 0, 0}).status,
            CallStatus::Ok);
  EXPECT_NE(sut->snapshot().text.find("\"kept\""), std::string::npos);

  const Answer restarted = sut->restart();
  EXPECT_EQ(restarted.status, CallStatus::Ok) << restarted.detail;
  EXPECT_TRUE(std::filesystem::exists(dir + "/restarted")) << "the restart command did not run";
  EXPECT_EQ(sut->instance(), 1u);
  const Document fresh = sut->snapshot();
  ASSERT_EQ(fresh.status, CallStatus::Ok) << fresh.detail;
  EXPECT_EQ(fresh.text.find("\"kept\""), std::string::npos) << "not a fresh node:\n" << fresh.text;
  EXPECT_FALSE(sut->limits().route.empty()) << "the route's limits are forwarded";

  auto failing = open_restartable(*route, o, "exit 3", &error);
  ASSERT_NE(failing, nullptr) << error;
  const Answer a = failing->restart();
  EXPECT_EQ(a.status, CallStatus::Crash);
  EXPECT_NE(a.detail.find("the restart command failed (exit 3)"), std::string::npos) << a.detail;
  const Document after = failing->snapshot();
  EXPECT_EQ(after.status, CallStatus::Crash);
  EXPECT_EQ(after.detail, a.detail);
  EXPECT_EQ(failing->name(), host.spec());
  std::filesystem::remove_all(dir);
}

// Issue 31: on the wire every command cost a round trip of its own (its
// barrier). Told what comes next (Implementation::expect_commands, as the
// runner tells each case), the route sends the slot writes that follow
// before one barrier, ended by one other command (here a layer_create),
// and still answers each command with the state after it alone: the
// snapshot after every command is the reference's after that prefix. Sent
// untold, the same program takes a round trip per command. (Before the
// batches, told or not, 26 commands cost 27 round trips.)
TEST(VerseRoute, CommandsToldAheadShareOneRoundTrip) {
  ServedHost host({}, {});
  ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
  auto sut = open_verse(host);
  ASSERT_NE(sut, nullptr);
  auto* verse = dynamic_cast<VerseImplementation*>(sut.get());
  ASSERT_NE(verse, nullptr);
  std::vector<Command> program;
  for (std::uint32_t v = 0; v < 12; ++v)
    program.push_back(cmd::VertexSetXyzReal64{0, v, 1.0 * v, -0.5 * v, 0.25});
  program.push_back(cmd::PolygonSetCornerUint32{1, 0, {0, 1, 2, kNone32}});
  program.push_back(cmd::PolygonSetCornerUint32{1, 1, {2, 3, 4, 5}});
  program.push_back(cmd::LayerCreate{2, "weight", static_cast<std::uint8_t>(LayerType::VertexReal), 0, 0.5});
  for (std::uint32_t v = 0; v < 10; ++v) program.push_back(cmd::VertexSetReal64{2, v, 0.125 * v});
  program.push_back(cmd::VertexSetReal64{2, 0, 7});  // a slot written twice: another round trip
  const auto run = [&](bool told) {
    EXPECT_EQ(sut->reset().status, CallStatus::Ok);
    Node model;
    const std::uint64_t before = verse->round_trips();
    for (std::size_t i = 0; i < program.size(); ++i) {
      if (told) sut->expect_commands(std::vector<Command>(program.begin() + static_cast<std::ptrdiff_t>(i), program.end()));
      const Answer a = sut->apply(program[i]);
      sut->expect_commands({});
      EXPECT_EQ(a.status, CallStatus::Ok) << i << ": " << a.detail;
      EXPECT_EQ(model.apply(program[i]), Reason::Ok) << i;
      const Document d = sut->snapshot();
      EXPECT_EQ(without_subscriptions(d.text), without_subscriptions(print_snapshot(model)))
          << (told ? "told" : "untold") << ", after command " << i << ": " << print_command(program[i]);
    }
    return verse->round_trips() - before;
  };
  const std::uint64_t alone = run(false);
  const std::uint64_t batched = run(true);
  EXPECT_GE(alone, program.size()) << "one barrier per command when nothing is told";
  EXPECT_LE(batched * 4, program.size()) << batched << " round trips for " << program.size() << " commands told ahead";
  EXPECT_GT(verse->batches(), 0u);
  EXPECT_EQ(verse->batch_fallbacks(), 0u);
}

using test::Untold;  // each command on its own round trip (untold.h)

// Issue 31: a deviation inside a batch is blamed on the command that made
// it, as when every command has its own barrier. The served node has a
// seeded fault: a polygon with a repeated corner is stored as a triangle
// (POLY-DISTINCT-1), or a corner naming no vertex creates it at the origin
// (POLY-VERTEX-REF-1; its vertex message is at a slot of a later command of
// the batch, or at one no command writes). The faulty command sits in the
// middle of slot writes that share its round trip; replay_program (what
// certify's confirmation and `vgc replay` run) judges the program told
// ahead and untold: the same command, the same clause.
TEST(VerseRoute, ADeviationInsideABatchIsBlamedOnItsCommand) {
  struct Fault {
    const char* name;
    const char* clause;
    Command faulty;
  };
  const std::vector<Fault> faults = {
      {"duplicate-corners-accepted", "POLY-DISTINCT-1", cmd::PolygonSetCornerUint32{1, 0, {0, 1, 1, 2}}},
      {"missing-corner-vertices-created", "POLY-VERTEX-REF-1", cmd::PolygonSetCornerUint32{1, 0, {0, 1, 5, kNone32}}},
      {"missing-corner-vertices-created", "POLY-VERTEX-REF-1", cmd::PolygonSetCornerUint32{1, 0, {0, 1, 9, kNone32}}},
  };
  for (const Fault& f : faults) {
    SCOPED_TRACE(std::string(f.name) + ": " + print_command(f.faulty));
    ServedHost host({"--impl", std::string("plugin:") + VGC_FAULT_PLUGIN}, {std::string("VGC_FAULT=") + f.name});
    ASSERT_NE(host.port(), 0) << "no port in \"" << host.line() << "\"";
    auto sut = open_verse(host);
    ASSERT_NE(sut, nullptr);
    auto* verse = dynamic_cast<VerseImplementation*>(sut.get());
    ASSERT_NE(verse, nullptr);
    Program program;
    for (std::uint32_t v = 0; v < 4; ++v) program.commands.push_back(cmd::VertexSetXyzReal64{0, v, 1.0 * v, 2, 3});
    const std::size_t at = program.commands.size();
    program.commands.push_back(f.faulty);
    for (std::uint32_t v = 4; v < 8; ++v) program.commands.push_back(cmd::VertexSetXyzReal64{0, v, 1.0 * v, 2, 3});
    Untold untold(*sut);
    const ReplayResult alone = replay_program(program, untold);
    const std::uint64_t batches_before = verse->batches();
    const ReplayResult told = replay_program(program, *sut);
    ASSERT_TRUE(alone.failure);
    ASSERT_TRUE(told.failure);
    EXPECT_EQ(alone.failure->clause, f.clause) << alone.failure->message;
    EXPECT_EQ(told.failure->clause, alone.failure->clause) << told.failure->message;
    EXPECT_EQ(told.failed_at, static_cast<int>(at));
    EXPECT_EQ(alone.failed_at, static_cast<int>(at));
    EXPECT_EQ(told.failure->message, alone.failure->message);
    EXPECT_GT(verse->batches() + verse->batch_fallbacks(), batches_before) << "the told replay sent no batch";
  }
}

}  // namespace
}  // namespace vgc
