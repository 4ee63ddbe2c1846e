// exec_implementation.h — an implementation that is a separate program
// speaking the exec protocol (docs/adapters.md "exec:CMD") on its stdin and
// stdout: one text command per line in, one answer line out.
//
// Spec: the command language of docs/commands.md (command_text.h) and the
// documents of snapshot.h and derived_document.h; the protocol itself is
// docs/adapters.md.
//
// Rationale: the implementation under test may crash, hang, or print
// anything, and none of that may stop or crash the suite. So the program
// runs in its own process group, every read and write is non-blocking and
// bounded by a deadline (poll), stderr is drained all the time (the last
// lines are kept for the report), answers are bounded in size, SIGPIPE is
// ignored, and the child is always reaped. It runs under a reaper of its
// own (reaped_process.h) that kills the program's group and everything it
// started, setsid'd and double-forked processes included, when the program
// ends or vgc does, even by SIGKILL. A failed call (Crash, Timeout,
// ProtocolError) kills the program; every later call returns the same
// failure without talking to it, until reset() starts it again.
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
#include <string>
#include <sys/types.h>

#include "declared_profile.h"
#include "implementation.h"
#include "reaped_process.h"

namespace vgc {

class ExecImplementation final : public Implementation {
 public:
  // `command` is run with /bin/sh -c. `display_name` is what name() says
  // (route_spec of the exec route to `command` when empty). Does not start the program: call start().
  ExecImplementation(std::string command, const OpenOptions& options, std::string display_name = {});
  ~ExecImplementation() override;  // sends ?quit, then kills what is left and reaps it
  ExecImplementation(const ExecImplementation&) = delete;
  ExecImplementation& operator=(const ExecImplementation&) = delete;

  // Starts the program and performs the ?hello handshake within
  // OpenOptions::start_timeout_seconds. On failure returns the Answer describing it (status != Ok) and
  // leaves the implementation in that failed state; reset() retries.
  Answer start();

  std::string name() const override { return display_name_; }
  std::string identity() const override { return hello_name_.empty() ? display_name_ : hello_name_; }
  Answer reset() override;
  // Kills the program (whatever state it is in) and starts it again.
  Answer restart() override;
  std::uint64_t instance() const override { return starts_; }
  Answer apply(const Command& c) override;
  Document snapshot() override;
  Document derived() override;
  // ?capabilities, ?classify, ?subdivide N, ?normals ... (the requests
  // capability_document_header knows): read as a document like
  // ?snapshot; an "error ..." answer is returned as it is (status Ok).
  // A ?capabilities answer's profile words are kept (declared_profile.h).
  Document request(const std::string& line) override;
  // What the program declared it does not show, in its last ?capabilities
  // answer (declared_profile.h): no limits until it was asked, so a caller
  // that follows them asks ?capabilities first (certify, replay, fuzz).
  RouteLimits limits() const override { return profile_.limits; }
  // The next request's document is expected to be about `bytes` long (a
  // derived answer on a large mesh): its size limit becomes at least 4x
  // that, and its time limit grows by --timeout per 4 MiB expected
  // (request_limits), so that a correct implementation is never cut off
  // by a limit sized for generated cases.
  void expect_answer_bytes(std::size_t bytes) override { next_request_bytes_ = bytes; }
  // Asks ?capabilities once (per ExecImplementation, not per instance: the
  // same program) whether the program claims the word `digest`; call it on
  // a fresh node (a program that fails the question is started again).
  bool offers_digest() override;
  // ?digest: one line "digest <hex16> <hex16>"; anything else is a ProtocolError.
  DigestAnswer digest() override;

  // Sends one raw line (without the newline) and reads one answer line.
  // For tests and for requests outside the Command set. Failure rules as apply().
  Answer request_line(const std::string& line, std::string* answer);

  // The running program's process id (also its process group id), or -1.
  pid_t pid() const { return pid_; }
  // The last lines the program wrote to stderr, oldest first.
  std::string stderr_tail() const;

 private:
  using Clock = std::chrono::steady_clock;
  enum class Io { Ok, Eof, Timeout, Cancelled, TooLong, WriteFailed, Unrequested };

  bool spawn(std::string* error);
  // Sends `line` + "\n" and reads one line, with one deadline for both.
  Io exchange(const std::string& line, std::string* answer, Clock::time_point deadline);
  Io write_all(const std::string& data, Clock::time_point deadline);
  Io read_line(std::string* line, Clock::time_point deadline);
  // Waits for readable stdout/stderr (and writable stdin when `want_write`),
  // draining stderr. Returns false at the deadline.
  bool pump(bool want_write, Clock::time_point deadline, bool* can_write);
  void drain_stderr();
  void take_stderr_bytes(const char* p, std::size_t n);
  // Records a failure: kills and reaps the program, builds the detail.
  void fail(CallStatus status, std::string detail);
  // The failure answer for an Io result other than Ok.
  void fail_io(Io io, const std::string& what);
  std::string kill_and_reap(std::chrono::milliseconds grace);
  void close_fds();
  Answer failed_answer() const;
  Document request_document(const char* request, const char* header, bool error_allowed = false);
  Clock::time_point deadline() const;  // of a call: --timeout from now
  Clock::time_point deadline(double seconds) const;

  std::string command_;
  OpenOptions options_;
  std::string display_name_;
  std::string hello_name_;
  pid_t pid_ = -1;            // the program's reaper (its wait status is the program's)
  int control_fd_ = -1;       // closing it makes the reaper stop the program (reaped_process.h)
  std::uint64_t starts_ = 0;  // programs started so far
  int in_fd_ = -1;   // the program's stdin
  int out_fd_ = -1;  // its stdout
  int err_fd_ = -1;  // its stderr
  std::string out_buf_;
  std::size_t out_pos_ = 0;  // out_buf_ before it is read (a line is taken by moving it, not by erasing)
  // The answer limits of the next request (expect_answer_bytes) and of the
  // one being read; 0: the options' own.
  std::size_t next_request_bytes_ = 0;
  std::size_t answer_limit_ = 0;
  double request_timeout_ = 0;
  std::size_t answer_limit() const { return answer_limit_ ? answer_limit_ : options_.max_answer_bytes; }
  std::size_t buffered() const { return out_buf_.size() - out_pos_; }
  std::string err_partial_;
  std::deque<std::string> err_lines_;
  DeclaredProfile profile_;  // from its last ?capabilities answer
  int digest_claimed_ = -1;  // offers_digest(): -1 not asked yet, 0 no, 1 yes
  bool starting_ = false;  // waiting for the ?hello answer: the limit is --start-timeout
  CallStatus failed_ = CallStatus::Ok;  // sticky failure until reset()
  std::string failed_detail_;
};

// Quotes `s` for /bin/sh: 'it'\''s'.
std::string shell_quote(const std::string& s);

}  // namespace vgc
