// exec_implementation.cpp — see exec_implementation.h and docs/adapters.md.
#include "exec_implementation.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <utility>
#include <cmath>
#include <mutex>
#include <thread>

#include "bounded_text.h"
#include "cancel.h"
#include "capability_documents.h"
#include "command_text.h"
#include "declared_profile.h"
#include "number_text.h"
#include "route.h"


namespace vgc {
namespace {

constexpr std::size_t kStderrLines = 20;
constexpr std::size_t kStderrLineBytes = 300;
constexpr std::size_t kQuoteBytes = 200;
// How long pump() polls without blocking before it blocks (see there).
constexpr std::chrono::microseconds kSpinBeforeBlocking{200};

// The suite must survive writing to a program that has gone: ignore SIGPIPE
// (write() then fails with EPIPE). Done once, and only when nobody chose a
// handler of their own. Children get the default back (reaped_process.cpp).
void ignore_sigpipe_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction old {};
    if (sigaction(SIGPIPE, nullptr, &old) == 0 && old.sa_handler == SIG_DFL) {
      struct sigaction sa {};
      sa.sa_handler = SIG_IGN;
      sigemptyset(&sa.sa_mask);
      sigaction(SIGPIPE, &sa, nullptr);
    }
  });
}

// A line for a report: quoted with escapes, cut at kQuoteBytes.
std::string quote_line(const std::string& s) {
  if (s.size() <= kQuoteBytes) return format_quoted(s);
  return format_quoted(s.substr(0, kQuoteBytes)) + "... (" + std::to_string(s.size()) + " bytes)";
}

std::string signal_text(int sig) {
  const char* abbrev = sigabbrev_np(sig);
  if (abbrev) return std::string("SIG") + abbrev;
  return "signal " + std::to_string(sig);
}

std::string describe_status(int status) {
  if (WIFEXITED(status)) {
    const int code = WEXITSTATUS(status);
    std::string s = "exited with status " + std::to_string(code);
    if (code > 128 && code < 128 + 65)
      s += " (a shell's way of reporting " + signal_text(code - 128) + ")";
    return s;
  }
  if (WIFSIGNALED(status)) return "was killed by " + signal_text(WTERMSIG(status));
  return "ended with wait status " + std::to_string(status);
}

bool set_nonblocking(int fd) {
  const int flags = fcntl(fd, F_GETFL);
  return flags >= 0 && fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0;
}

std::string seconds_text(double s) {
  char buf[32];
  snprintf(buf, sizeof buf, "%g s", s);
  return buf;
}

}  // namespace

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char ch : s) {
    if (ch == '\'') out += "'\\''";
    else out += ch;
  }
  return out + "'";
}

ExecImplementation::ExecImplementation(std::string command, const OpenOptions& options,
                                       std::string display_name)
    : command_(std::move(command)), options_(options), display_name_(std::move(display_name)) {
  if (display_name_.empty()) display_name_ = route_spec(RouteKind::Exec, command_);
  failed_ = CallStatus::Crash;
  failed_detail_ = "not started";
}

ExecImplementation::~ExecImplementation() {
  if (pid_ > 0) {
    if (failed_ == CallStatus::Ok && in_fd_ >= 0) {
      const char quit[] = "?quit\n";
      // Best effort; the pipe is non-blocking and SIGPIPE is ignored.
      [[maybe_unused]] ssize_t n = write(in_fd_, quit, sizeof quit - 1);
    }
    kill_and_reap(std::chrono::milliseconds(200));
  }
  close_fds();
}

ExecImplementation::Clock::time_point ExecImplementation::deadline(double seconds) const {
  const double s = std::max(0.0, seconds);
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

ExecImplementation::Clock::time_point ExecImplementation::deadline() const {
  return deadline(options_.timeout_seconds);
}

void ExecImplementation::close_fds() {
  for (int* fd : {&in_fd_, &out_fd_, &err_fd_}) {
    if (*fd >= 0) close(*fd);
    *fd = -1;
  }
}

bool ExecImplementation::spawn(std::string* error) {
  ignore_sigpipe_once();
  int in[2] = {-1, -1}, out[2] = {-1, -1}, err[2] = {-1, -1};
  auto close_all = [&] {
    for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]})
      if (fd >= 0) close(fd);
  };
  if (pipe2(in, O_CLOEXEC) != 0 || pipe2(out, O_CLOEXEC) != 0 || pipe2(err, O_CLOEXEC) != 0) {
    *error = std::string("cannot create pipes: ") + strerror(errno);
    close_all();
    return false;
  }
  std::string sh = "/bin/sh", dash_c = "-c";
  char* argv[] = {sh.data(), dash_c.data(), command_.data(), nullptr};
  ReapedProcess proc;
  std::string why;
  const bool started = spawn_reaped("/bin/sh", argv, in[0], out[1], err[1], &proc, &why);
  close(in[0]);
  close(out[1]);
  close(err[1]);
  in[0] = out[1] = err[1] = -1;
  if (!started) {
    *error = why;
    close_all();
    return false;
  }
  const pid_t pid = proc.pid;
  control_fd_ = proc.control_fd;
  pid_ = pid;
  ++starts_;
  in_fd_ = in[1];
  out_fd_ = out[0];
  err_fd_ = err[0];
  set_nonblocking(in_fd_);
  set_nonblocking(out_fd_);
  set_nonblocking(err_fd_);
  out_buf_.clear();
  out_pos_ = 0;
  err_partial_.clear();
  err_lines_.clear();
  return true;
}

void ExecImplementation::take_stderr_bytes(const char* p, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    if (p[i] == '\n') {
      if (!err_partial_.empty() && err_partial_.back() == '\r') err_partial_.pop_back();
      err_lines_.push_back(std::move(err_partial_));
      err_partial_.clear();
      if (err_lines_.size() > kStderrLines) err_lines_.pop_front();
    } else if (err_partial_.size() < kStderrLineBytes) {
      err_partial_ += p[i];
    }
  }
}

void ExecImplementation::drain_stderr() {
  char buf[65536];
  while (err_fd_ >= 0) {
    const ssize_t n = read(err_fd_, buf, sizeof buf);
    if (n > 0) {
      take_stderr_bytes(buf, static_cast<std::size_t>(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else if (n < 0 && errno == EAGAIN) {
      return;
    } else {  // EOF or error: stop listening
      close(err_fd_);
      err_fd_ = -1;
    }
  }
}

std::string ExecImplementation::stderr_tail() const {
  std::string s;
  for (const std::string& l : err_lines_) s += l + "\n";
  if (!err_partial_.empty()) s += err_partial_ + "\n";
  return s;
}

bool ExecImplementation::pump(bool want_write, Clock::time_point dl, bool* can_write) {
  if (can_write) *can_write = false;
  for (;;) {
    // A cancelled run (cancel.h) waits for no answer: the wait ends as a
    // timeout, which the runner discards.
    if (cancel_signal()) return false;
    pollfd fds[4];
    int n = 0;
    int out_i = -1, err_i = -1, in_i = -1;
    if (cancel_fd() >= 0) fds[n++] = {cancel_fd(), POLLIN, 0};
    // Stop reading stdout once it holds more than any acceptable answer.
    if (out_fd_ >= 0 && buffered() <= answer_limit()) {
      out_i = n;
      fds[n++] = {out_fd_, POLLIN, 0};
    }
    if (err_fd_ >= 0) {
      err_i = n;
      fds[n++] = {err_fd_, POLLIN, 0};
    }
    if (want_write && in_fd_ >= 0) {
      in_i = n;
      fds[n++] = {in_fd_, POLLOUT, 0};
    }
    const auto now = Clock::now();
    if (now >= dl) return false;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(dl - now).count() + 1;
    // Most answers come within microseconds. Polling without blocking for a
    // short while first keeps this CPU awake for them: on a virtual machine
    // with idle CPUs each blocking wait's wake-up cost about 50 us, most of
    // a command's round trip (certify through `vgc serve`: 14.5 s idle,
    // 2.3 s with any other load; docs/performance.md).
    int rc = 0;
    for (const auto spin_end = now + kSpinBeforeBlocking; rc == 0 && Clock::now() < spin_end;)
      rc = poll(fds, static_cast<nfds_t>(n), 0);
    if (rc == 0) rc = poll(fds, static_cast<nfds_t>(n), static_cast<int>(std::min<long long>(left, 60000)));
    if (rc < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    if (rc == 0) continue;  // re-check the deadline
    if (err_i >= 0 && fds[err_i].revents) drain_stderr();
    bool progress = false;
    if (in_i >= 0 && fds[in_i].revents) {
      if (can_write) *can_write = true;
      progress = true;
    }
    if (out_i >= 0 && fds[out_i].revents) {
      char buf[65536];
      const ssize_t r = read(out_fd_, buf, sizeof buf);
      if (r > 0) {
        out_buf_.append(buf, static_cast<std::size_t>(r));
      } else if (r == 0 || (errno != EINTR && errno != EAGAIN)) {
        close(out_fd_);  // EOF: read_line sees out_fd_ < 0
        out_fd_ = -1;
      }
      progress = true;
    }
    if (progress) return true;
  }
}

ExecImplementation::Io ExecImplementation::write_all(const std::string& data, Clock::time_point dl) {
  std::size_t done = 0;
  while (done < data.size()) {
    if (in_fd_ < 0) return Io::WriteFailed;
    const ssize_t n = write(in_fd_, data.data() + done, data.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) {
      bool can_write = false;
      while (!can_write) {
        if (!pump(true, dl, &can_write)) return cancel_signal() ? Io::Cancelled : Io::Timeout;
      }
      continue;
    }
    return Io::WriteFailed;  // EPIPE: the program closed its stdin or died
  }
  return Io::Ok;
}

ExecImplementation::Io ExecImplementation::read_line(std::string* line, Clock::time_point dl) {
  std::size_t scanned = 0;
  for (;;) {
    const std::size_t nl = out_buf_.find('\n', out_pos_ + scanned);
    if (nl != std::string::npos) {
      if (nl - out_pos_ > answer_limit()) return Io::TooLong;
      line->assign(out_buf_, out_pos_, nl - out_pos_);
      out_pos_ = nl + 1;
      // Taken lines are dropped in bulk: erasing each line from the front
      // moved the rest of a 64 KiB read per line (a 10^6-line answer).
      if (out_pos_ == out_buf_.size()) {
        out_buf_.clear();
        out_pos_ = 0;
      } else if (out_pos_ > (std::size_t{1} << 20) && out_pos_ > out_buf_.size() / 2) {
        out_buf_.erase(0, out_pos_);
        out_pos_ = 0;
      }
      if (!line->empty() && line->back() == '\r') line->pop_back();
      return Io::Ok;
    }
    scanned = buffered();
    if (buffered() > answer_limit()) return Io::TooLong;
    if (out_fd_ < 0) return Io::Eof;
    if (!pump(false, dl, nullptr)) return cancel_signal() ? Io::Cancelled : Io::Timeout;
  }
}

ExecImplementation::Io ExecImplementation::exchange(const std::string& line, std::string* answer,
                                                    Clock::time_point dl) {
  // Output nobody asked for (a second answer line, a banner) would be
  // taken for the answer to this request: refuse what has already arrived.
  if (buffered() == 0 && out_fd_ >= 0) {
    char buf[4096];
    const ssize_t r = read(out_fd_, buf, sizeof buf);
    if (r > 0) out_buf_.append(buf, static_cast<std::size_t>(r));
  }
  if (buffered() != 0) return Io::Unrequested;
  const Io w = write_all(line + "\n", dl);
  if (w != Io::Ok) return w;  // WriteFailed: it closed its stdin or died
  return read_line(answer, dl);
}

std::string ExecImplementation::kill_and_reap(std::chrono::milliseconds grace) {
  if (pid_ <= 0) {
    close_fds();
    return "had already been stopped";
  }
  if (in_fd_ >= 0) {  // end of input: a well-behaved program exits now
    close(in_fd_);
    in_fd_ = -1;
  }
  // Wait up to `grace` for it to end by itself, without reaping yet: while
  // it is unreaped its pid cannot be reused, so killing its group is safe.
  const auto until = Clock::now() + grace;
  bool ended = false;
  for (;;) {
    siginfo_t info{};
    if (waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid_) {
      ended = true;
      break;
    }
    if (Clock::now() >= until) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  // The reaper kills its group and everything it started, then ends as it did.
  ReapedProcess proc{pid_, control_fd_};
  const int status = stop_reaped(&proc);
  pid_ = -1;
  control_fd_ = -1;
  drain_stderr();
  close_fds();
  if (ended) return describe_status(status);
  return "did not end by itself and was killed";
}

void ExecImplementation::fail(CallStatus status, std::string detail) {
  const std::chrono::milliseconds grace(status == CallStatus::Crash ? 500 : 0);
  const std::string ended = kill_and_reap(grace);
  if (status == CallStatus::Crash) detail += ": the program " + ended;
  const std::string tail = stderr_tail();
  if (!tail.empty()) {
    detail += "\nlast lines of its stderr:";
    std::size_t start = 0;
    while (start < tail.size()) {
      const std::size_t nl = tail.find('\n', start);
      detail += "\n  " + tail.substr(start, nl - start);
      start = nl + 1;
    }
  }
  failed_ = status;
  failed_detail_ = std::move(detail);
}

void ExecImplementation::fail_io(Io io, const std::string& what) {
  switch (io) {
    case Io::Ok: return;
    case Io::Timeout:
      // The limit that ran out, by the option that sets it (OpenOptions).
      fail(CallStatus::Timeout,
           "no complete answer to " + what + " within " +
               (starting_ ? seconds_text(options_.start_timeout_seconds) + " (--start-timeout)"
                : request_timeout_ > 0
                    ? seconds_text(request_timeout_) + " (--timeout, scaled with the size of the answer expected)"
                    : seconds_text(options_.timeout_seconds) + " (--timeout)"));
      return;
    case Io::Cancelled:  // a Timeout to the runner, which drops what a cancel cut short
      fail(CallStatus::Timeout, "not answered: the run was cancelled by " + std::string(cancel_signal_name()) +
                                    " while vgc waited for the answer to " + what);
      return;
    case Io::TooLong:
      fail(CallStatus::ProtocolError, "the answer to " + what + " is longer than " + std::to_string(answer_limit()) +
                                          " bytes (vgc's limit on one answer or document)");
      return;
    case Io::Eof:
      fail(CallStatus::Crash, "end of its output while answering " + what);
      return;
    case Io::WriteFailed:
      fail(CallStatus::Crash, "its input was closed when sending " + what);
      return;
    case Io::Unrequested: {
      const std::string first = out_buf_.substr(out_pos_, out_buf_.find('\n', out_pos_) - out_pos_);
      fail(CallStatus::ProtocolError, "it wrote " + quote_line(first) + " before being sent " + what +
                                          " (more than one answer line to an earlier request?)");
      return;
    }
  }
}

Answer ExecImplementation::failed_answer() const {
  Answer a;
  a.status = failed_;
  a.detail = "not sent: an earlier call failed and reset() has not restarted it; that failure: " + failed_detail_;
  return a;
}

Answer ExecImplementation::start() {
  if (pid_ > 0) kill_and_reap(std::chrono::milliseconds(0));
  hello_name_.clear();
  std::string error;
  if (!spawn(&error)) {
    failed_ = CallStatus::Crash;
    failed_detail_ = error;
    return failed_answer();
  }
  failed_ = CallStatus::Ok;
  std::string line;
  starting_ = true;  // the ?hello answer is the start: --start-timeout
  const Io io = exchange("?hello", &line, deadline(options_.start_timeout_seconds));
  if (io != Io::Ok) {
    fail_io(io, "?hello");
    starting_ = false;
    Answer a;
    a.status = failed_;
    a.detail = failed_detail_;
    return a;
  }
  starting_ = false;
  const std::string prefix = "vgc-exec ";
  if (line.rfind(prefix, 0) == 0) {
    const std::string rest = line.substr(prefix.size());
    const std::size_t sp = rest.find(' ');
    const std::string version = rest.substr(0, sp);
    if (version == "1") {
      hello_name_ = sp == std::string::npos ? std::string() : bounded_text(std::string_view(rest).substr(sp + 1));
      Answer hello;
      hello.applied = true;
      return hello;
    }
    fail(CallStatus::ProtocolError, "it speaks exec protocol version " + quote_line(version) +
                                        "; the suite speaks version 1 (answer to ?hello: " + quote_line(line) + ")");
  } else {
    fail(CallStatus::ProtocolError,
         "answered ?hello with " + quote_line(line) + "; expected \"vgc-exec 1 <name>\"");
  }
  Answer a;
  a.status = failed_;
  a.detail = failed_detail_;
  return a;
}

Answer ExecImplementation::restart() {
  if (pid_ > 0) kill_and_reap(std::chrono::milliseconds(0));
  failed_ = CallStatus::Crash;
  failed_detail_ = "restarted";
  return reset();  // starts it (a failed or stopped program is started by reset)
}

Answer ExecImplementation::reset() {
  if (failed_ != CallStatus::Ok || pid_ <= 0) {
    Answer a = start();
    if (a.status != CallStatus::Ok) return a;
  }
  std::string line;
  const Io io = exchange("?reset", &line, deadline());
  Answer a;
  if (io != Io::Ok) {
    fail_io(io, "?reset");
  } else if (line != "ok") {
    fail(CallStatus::ProtocolError, "answered ?reset with " + quote_line(line) + "; expected \"ok\"");
  } else {
    a.applied = true;
    return a;
  }
  a.status = failed_;
  a.detail = failed_detail_;
  return a;
}

Answer ExecImplementation::request_line(const std::string& request, std::string* answer) {
  if (failed_ != CallStatus::Ok) return failed_answer();
  Answer a;
  const Io io = exchange(request, answer, deadline());
  if (io == Io::Ok) return a;
  fail_io(io, quote_line(request));
  a.status = failed_;
  a.detail = failed_detail_;
  return a;
}

bool ExecImplementation::offers_digest() {
  if (digest_claimed_ < 0) {
    // Asked when a check starts, on a fresh node. A program that cannot
    // answer ?capabilities claims nothing; it is started again so that this
    // question, which certify asks again before its capability cases (and
    // reports there), does not become a failure of the next command.
    const Document d = request("?capabilities");
    if (d.status != CallStatus::Ok) {
      digest_claimed_ = 0;
      start();
      return false;
    }
    const std::string first = d.text.substr(0, d.text.find('\n'));
    digest_claimed_ = (" " + first + " ").find(" digest ") != std::string::npos && first.rfind("capabilities", 0) == 0;
  }
  return digest_claimed_ == 1;
}

DigestAnswer ExecImplementation::digest() {
  DigestAnswer d;
  std::string line;
  const Answer a = request_line("?digest", &line);
  if (a.status != CallStatus::Ok) return {a.status, {}, a.detail};
  if (!parse_digest_line(line, &d.digests)) {
    fail(CallStatus::ProtocolError,
         "answered ?digest with " + quote_line(line) + "; expected \"digest <16 hex digits> <16 hex digits>\"");
    return {failed_, {}, failed_detail_};
  }
  return d;
}

Answer ExecImplementation::apply(const Command& c) {
  if (failed_ != CallStatus::Ok) return failed_answer();
  if (profile_.c_string_names && has_name_with_nul(c)) {  // declared_profile.h: as on the Verse wire
    Answer a;
    a.not_sent = true;
    a.verdict_reported = false;
    a.detail = "it declares that its names are C strings (profile:c-string-names), and a name holds a NUL byte";
    return a;
  }
  if (profile_.no_bone_rotation && has_bone_rotation(c)) {
    Answer a;
    a.not_sent = true;
    a.verdict_reported = false;
    a.detail = "it declares that its bone_create carries no rotation (profile:no-bone-rotation), and this one has "
               "another rotation than the identity 0 0 0 1";
    return a;
  }
  const std::string text = print_command(c);
  std::string line;
  Answer a = request_line(text, &line);
  if (a.status != CallStatus::Ok) return a;
  static const std::string kRejected = "rejected ";
  if (line == "ok") {
    a.applied = true;
    return a;
  }
  if (line == "done") {  // processed, verdict not reported (docs/adapters.md)
    a.verdict_reported = false;
    return a;
  }
  if (line.rfind(kRejected, 0) == 0) {
    const std::string_view reason = std::string_view(line).substr(kRejected.size());
    const bool token = !reason.empty() && std::none_of(reason.begin(), reason.end(), [](char ch) {
      return static_cast<unsigned char>(ch) <= ' ' || ch == 0x7f;
    });
    if (token) {
      // No reason name is near kShownBytes long: a cut one still differs
      // from the reference's, and every copy of it stays small.
      a.reason = bounded_text(reason);
      return a;
    }
  } else if (line == "error" || line.rfind("error ", 0) == 0) {
    a.malformed = true;
    a.detail = line.size() > 6 ? bounded_text(std::string_view(line).substr(6)) : std::string();
    return a;
  }
  fail(CallStatus::ProtocolError, "answered " + quote_line(line) + " to " + quote_line(text) +
                                      "; expected \"ok\", \"rejected <REASON>\", \"done\" or \"error <message>\"");
  a.status = failed_;
  a.detail = failed_detail_;
  return a;
}

Document ExecImplementation::request_document(const char* request, const char* header, bool error_allowed) {
  Document d;
  if (failed_ != CallStatus::Ok) {
    const Answer a = failed_answer();
    d.status = a.status;
    d.detail = a.detail;
    return d;
  }
  // Limits for this answer: the options' own, or scaled to the answer
  // expected (expect_answer_bytes), 4 MiB per --timeout.
  const std::size_t expected = std::exchange(next_request_bytes_, 0);
  answer_limit_ = std::max(options_.max_answer_bytes, 4 * expected);
  request_timeout_ = options_.timeout_seconds * (1.0 + static_cast<double>(expected) / (4 << 20));
  const auto dl = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                                     std::max(0.0, request_timeout_)));
  std::string line;
  Io io = exchange(request, &line, dl);
  const std::string head = std::string(header) + " ";
  if (io == Io::Ok && error_allowed && (line == "error" || line.rfind("error ", 0) == 0)) {
    d.text = line + "\n";
    return d;
  }
  if (io == Io::Ok && line != header && line.rfind(head, 0) != 0) {
    fail(CallStatus::ProtocolError, std::string("answered ") + request + " with " + quote_line(line) +
                                        "; a document must start with \"" + header + " 1\"");
  } else {
    while (io == Io::Ok) {
      // A line of a document is short (the longest the reference prints is
      // well under a KiB): a longer one is kept cut (bounded_text.h); it
      // still differs from the reference's line, as the whole one did.
      d.text += line.size() > kShownBytes ? bounded_text(line) : line;
      d.text += '\n';
      if (line == "end") {
        answer_limit_ = 0, request_timeout_ = 0;
        return d;
      }
      if (d.text.size() > answer_limit()) {
        io = Io::TooLong;
        break;
      }
      io = read_line(&line, dl);
    }
    fail_io(io, request);
  }
  if (io == Io::Timeout) d.limit = "--timeout";
  if (io == Io::TooLong) d.limit = "the answer size limit";
  answer_limit_ = 0, request_timeout_ = 0;
  d.status = failed_;
  d.detail = failed_detail_;
  d.text.clear();
  return d;
}

Document ExecImplementation::snapshot() { return request_document("?snapshot", "vgc-snapshot"); }
Document ExecImplementation::derived() { return request_document("?derived", "vgc-derived"); }

Document ExecImplementation::request(const std::string& line) {
  const char* header = capability_document_header(line);
  if (!header) return {CallStatus::ProtocolError, {}, "not supported"};
  Document d = request_document(line.c_str(), header, true);
  // Its answer to ?capabilities declares its profile too (declared_profile.h);
  // a failed or refused question leaves the last one declared.
  if (line == "?capabilities" && d.status == CallStatus::Ok && d.text.rfind("capabilities", 0) == 0)
    profile_ = declared_profile(d.text);
  return d;
}

}  // namespace vgc
