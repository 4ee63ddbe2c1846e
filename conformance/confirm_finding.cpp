// confirm_finding.cpp — see confirm_finding.h.
#include "confirm_finding.h"

#include <fmt/core.h>

#include <algorithm>

#include "bounded_text.h"
#include "cancel.h"
#include "check_step.h"
#include "replay_program.h"  // a finding is confirmed by replaying it on a fresh instance
#include "command_text.h"
#include "program_checker.h"

namespace vgc {
namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kHistoryPrefix = "depends on the implementation's history";
constexpr const char* kUnconfirmed = "not confirmed on a fresh instance";

// Restarts the implementation and replays commands on it, within a budget
// of attempts and time.
class Reproducer {
 public:
  Reproducer(Implementation& sut, const Finding& sought, Clock::time_point deadline, int max_attempts)
      : sut_(sut), sought_(sought), deadline_(deadline), max_attempts_(max_attempts) {}

  bool spent() const { return attempts_ >= max_attempts_ || Clock::now() >= deadline_ || cancel_signal(); }
  int attempts() const { return attempts_; }
  // How many attempts had a fresh instance to replay on, and why the last
  // start failed (a host that stopped answering, a program that no longer
  // starts): with none started, nothing was confirmed or refuted.
  int started() const { return started_; }
  const std::string& start_failure() const { return start_failure_; }

  // Whether `commands` from a fresh instance fail with the status sought;
  // when they do, *commands is cut after the command that failed.
  // `request`: the capability check to repeat after them (a capability
  // finding's program).
  bool fails(std::vector<Command>* commands, const std::optional<CapabilityRequest>& request = std::nullopt) {
    if (spent()) return false;
    ++attempts_;
    if (!started_fresh()) return false;  // it cannot even start: nothing to learn here
    const ReplayResult r = replay_program(Program{*commands, request}, sut_);
    if (!r.failure || !same_kind(*r.failure)) return false;
    if (r.failed_at >= 0 && static_cast<std::size_t>(r.failed_at) + 1 < commands->size())
      commands->resize(static_cast<std::size_t>(r.failed_at) + 1);
    last_ = *r.failure;
    return true;
  }
  const Finding& last_failure() const { return last_; }

  // The same kind of failure as the one sought: a crash, a timeout, or a
  // protocol error, on whatever command; or, for a wrong answer (a wrong
  // verdict, reason or document), a wrong answer in whatever clause.
  bool same_kind(const Finding& f) const { return finding_kind(f) == finding_kind(sought_); }

  // Same clause and status as `f`, from its own program on a fresh instance.
  bool reproduces(const PropertyFinding& f) {
    ++attempts_;
    if (!started_fresh()) return false;
    const ReplayResult r = replay_program(f.program, sut_);
    const auto same = [&f](const Finding& x) { return x.status == f.finding.status && x.clause == f.finding.clause; };
    return (r.failure && same(*r.failure)) || std::any_of(r.also_failed.begin(), r.also_failed.end(), same);
  }

 private:
  bool started_fresh() {
    const Answer a = sut_.restart();
    if (a.status != CallStatus::Ok) {
      start_failure_ = fmt::format("{}: {}", call_status_name(a.status), bounded_text(a.detail));
      return false;
    }
    ++started_;
    return true;
  }

  Implementation& sut_;
  Finding sought_;
  Clock::time_point deadline_;
  int max_attempts_;
  int attempts_ = 0;
  int started_ = 0;
  std::string start_failure_;
  Finding last_;
};

std::vector<Command> flatten(const std::vector<std::vector<Command>>& cases) {
  std::vector<Command> out;
  for (const auto& c : cases) out.insert(out.end(), c.begin(), c.end());
  return out;
}

// Drops whole cases (first to last) while what is left still fails.
std::vector<std::vector<Command>> reduce_cases(std::vector<std::vector<Command>> cases, Reproducer* rep) {
  for (std::size_t i = 0; i < cases.size() && cases.size() > 1 && !rep->spent();) {
    auto fewer = cases;
    fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(i));
    std::vector<Command> flat = flatten(fewer);
    if (!flat.empty() && rep->fails(&flat)) cases = std::move(fewer);
    else ++i;
  }
  return cases;
}

// Drops runs of commands, halving their length (ddmin's complements), while
// what is left still fails.
std::vector<Command> reduce_commands(std::vector<Command> commands, Reproducer* rep) {
  for (std::size_t chunk = std::max<std::size_t>(1, commands.size() / 2); chunk >= 1 && !rep->spent(); chunk /= 2) {
    for (std::size_t at = 0; at < commands.size() && commands.size() > 1 && !rep->spent();) {
      std::vector<Command> fewer = commands;
      fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(at),
                  fewer.begin() + static_cast<std::ptrdiff_t>(std::min(commands.size(), at + chunk)));
      if (!fewer.empty() && rep->fails(&fewer)) commands = std::move(fewer);
      else at += chunk;
    }
    if (chunk == 1) break;
  }
  return commands;
}

}  // namespace

void HistoryRecorder::follow_instance() {
  if (sut_.instance() == instance_) return;
  instance_ = sut_.instance();
  history_.clear();
}

Answer HistoryRecorder::reset() {
  Answer a = sut_.reset();
  follow_instance();
  history_.emplace_back();
  return a;
}

Answer HistoryRecorder::restart() {
  Answer a = sut_.restart();
  follow_instance();
  history_.clear();
  history_.emplace_back();
  return a;
}

Answer HistoryRecorder::apply(const Command& c) {
  follow_instance();
  if (history_.empty()) history_.emplace_back();
  history_.back().push_back(c);
  return sut_.apply(c);
}

bool is_call_failure(const Finding& f) {
  if (f.status == FindingStatus::Crash || f.status == FindingStatus::Timeout) return true;
  return f.status == FindingStatus::Fail && f.protocol_error;
}

bool fails_fresh(Implementation& sut, const Finding& f, const Program& program) {
  Reproducer rep(sut, f, Clock::now() + std::chrono::hours(1), 1);
  std::vector<Command> commands = program.commands;
  return rep.fails(&commands, program.request);
}

bool reproduces_fresh(Implementation& sut, const Finding& f, const Program& program) {
  Reproducer rep(sut, f, Clock::now() + std::chrono::hours(1), 1);
  PropertyFinding pf;
  pf.finding = f;
  pf.program = program;
  return rep.reproduces(pf);
}

bool note_reproduces_fresh(Implementation& sut, const Finding& note, const Program& program) {
  if (sut.restart().status != CallStatus::Ok) return false;
  const ReplayResult r = replay_program(program, sut);
  for (const Finding& n : r.notes)
    if (n.clause == note.clause) return true;
  return r.failure && r.failure->clause == note.clause;
}

bool kind_tells_differences_apart(const Finding& f) { return finding_kind_of(f) == FindingKind::HiddenState; }

FindingKind finding_kind_of(const Finding& f) {
  if (f.history_kind) return *f.history_kind;  // the kind the history brought about
  if (f.status == FindingStatus::Crash) return FindingKind::Crash;
  if (f.status == FindingStatus::Timeout) return FindingKind::Timeout;
  if (is_call_failure(f)) return FindingKind::ProtocolError;
  if (f.late_view) return FindingKind::HiddenState;
  return FindingKind::WrongAnswer;
}

std::string finding_kind(const Finding& f) { return finding_kind_name(finding_kind_of(f)); }

int finding_severity(const Finding& f) { return static_cast<int>(finding_kind_of(f)); }

bool depends_on_history(const Finding& f) { return f.history_kind.has_value(); }

bool confirm_call_failure(Implementation& sut, PropertyFinding* pf, const std::vector<std::vector<Command>>& history,
                          Clock::time_point deadline, int max_attempts) {
  Reproducer rep(sut, pf->finding, deadline, max_attempts);
  if (rep.reproduces(*pf)) return true;
  if (rep.started() == 0) {
    // No fresh instance to replay on: the finding stands where it was
    // seen, and says it was not confirmed (nor shown to need a history).
    pf->finding.message += fmt::format(" [{}: no fresh instance could be started to replay it on ({})]",
                                       kUnconfirmed, rep.start_failure());
    return true;
  }

  const std::string blamed = pf->finding.clause;
  const std::size_t shrunk = pf->program.commands.size();
  std::vector<Command> whole = flatten(history);
  const std::size_t since_start = whole.size();
  std::string how;
  std::vector<Command> reproducer = whole;
  const std::optional<CapabilityRequest> request = pf->program.request;
  bool reproduced = rep.fails(&reproducer, request);
  if (reproduced) {
    std::vector<std::vector<Command>> cases = reduce_cases(history, &rep);
    reproducer = flatten(cases);
    rep.fails(&reproducer, request);  // cuts it after the failing command
    reproducer = reduce_commands(reproducer, &rep);
    how = fmt::format("the {} commands since the instance started, reduced (by cases, then commands; {} restarts{}) "
                      "to these {}, fail a fresh instance the same way",
                      since_start, rep.attempts(), rep.spent() ? ", stopped at the limit" : "", reproducer.size());
  } else {
    how = fmt::format("even the whole history since the instance started ({} commands) did not fail a fresh instance "
                      "again: the failure could not be reproduced (flaky?); the program below is that history",
                      since_start);
  }
  // A protocol error is ACCEPT-1's whatever the history; a crash, a
  // time-out or a wrong answer that only a history brings about is the
  // implementation not standing up to that history: STABLE-1.
  const FindingKind kind = finding_kind_of(pf->finding);
  Finding f;
  f.status = pf->finding.status;
  f.clause = kind == FindingKind::ProtocolError ? "ACCEPT-1" : "STABLE-1";
  f.history_kind = kind;
  f.message = fmt::format(
      "{}: {} after {} commands since the instance started, while applying a "
      "command of {} (not blamed on it: the case it ended, {} commands from a fresh node, does not fail a fresh "
      "instance); {}. As "
      "seen: {}",
      kHistoryPrefix, finding_kind_name(kind), since_start, blamed, shrunk, how, pf->finding.message);
  pf->finding = f;
  pf->program = Program{reproducer, request};
  pf->program.history_kind = kind;
  return false;
}

std::optional<Finding> blame_as_history(const Program& program, const Finding& seen, std::size_t failed_at) {
  if (!program.history_kind || finding_kind_of(seen) != *program.history_kind) return std::nullopt;
  Finding f;
  f.status = seen.status;
  f.clause = *program.history_kind == FindingKind::ProtocolError ? "ACCEPT-1" : "STABLE-1";
  f.history_kind = program.history_kind;
  f.message = fmt::format(
      "{}: {} after {} commands from a fresh instance, on a command of {} (not blamed on it: this file "
      "reproduces a finding certify confirmed as depending on the history). As seen: {}",
      kHistoryPrefix, finding_kind_name(*program.history_kind), failed_at + 1, seen.clause, seen.message);
  return f;
}

}  // namespace vgc
