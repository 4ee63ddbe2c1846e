// launched_host.cpp — see launched_host.h.
#include "launched_host.h"

#include <fcntl.h>
#include <netdb.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <thread>
#include <utility>

#include "forwarding_implementation.h"

namespace vgc {
namespace {

using Clock = std::chrono::steady_clock;

std::string wait_status_text(int status) {
  if (WIFEXITED(status)) return "exit " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "signal " + std::to_string(WTERMSIG(status));
  return "status " + std::to_string(status);
}

// The host vgc started, as an Implementation: every call goes to the
// session logged in after the last start; restart() starts the host anew.
class LaunchedHostImplementation final : public ForwardingImplementation {
 public:
  LaunchedHostImplementation(std::unique_ptr<LaunchedHost> host, OpenOptions options,
                             std::unique_ptr<Implementation> first)
      : ForwardingImplementation(first.get(), host->command(), "no session"),
        host_(std::move(host)),
        options_(std::move(options)),
        sut_(std::move(first)) {}
  ~LaunchedHostImplementation() override {
    sut_.reset();  // logs out while the host still runs
    host_.reset();
  }
  std::uint64_t instance() const override { return host_->starts(); }
  Answer restart() override {
    forward_to(nullptr);
    sut_.reset();
    std::string why;
    if (!host_->start(options_, &sut_, &why)) {
      set_why(why);
      return unanswered();
    }
    forward_to(sut_.get());
    return {};
  }

 private:
  std::unique_ptr<LaunchedHost> host_;
  OpenOptions options_;
  std::unique_ptr<Implementation> sut_;
};

}  // namespace

bool udp_port_free(const std::string& host, std::uint16_t port) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_DGRAM;
  addrinfo* list = nullptr;
  if (getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &list) != 0) return true;
  bool free = true;
  for (addrinfo* a = list; a && free; a = a->ai_next) {
    const int fd = socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    if (bind(fd, a->ai_addr, a->ai_addrlen) != 0 && errno == EADDRINUSE) free = false;
    close(fd);
  }
  freeaddrinfo(list);
  return free;
}

LaunchedHost::LaunchedHost(Route route, std::string command, std::string log, double start_timeout_s)
    : route_(std::move(route)), command_(std::move(command)), log_(std::move(log)), start_timeout_s_(start_timeout_s) {}

LaunchedHost::~LaunchedHost() { stop(); }

void LaunchedHost::stop() {
  if (proc_.pid > 0 || proc_.control_fd >= 0) stop_reaped(&proc_);
}

bool LaunchedHost::start(const OpenOptions& options, std::unique_ptr<Implementation>* session, std::string* why) {
  stop();
  ++starts_;
  const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>(std::max(1.0, start_timeout_s_)));
  // The port first: a host of an earlier start (or of the previous libFuzzer
  // round, whose reaper is still ending it) may hold it for a moment.
  const auto port_until = Clock::now() + std::chrono::seconds(10);
  while (!udp_port_free(route_.host, route_.port)) {
    if (Clock::now() >= port_until) {
      *why = "UDP port " + std::to_string(route_.port) + " of " + route_.host +
             " is in use by another program: with --host-cmd vgc starts the host itself, on the address of --impl " +
             route_.spec + " (stop the host running there, or give another port)";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  const int in = open("/dev/null", O_RDONLY | O_CLOEXEC);
  const int out = log_.empty() ? open("/dev/null", O_WRONLY | O_CLOEXEC)
                               : open(log_.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (in < 0 || out < 0) {
    if (in >= 0) close(in);
    if (out >= 0) close(out);
    *why = "cannot open " + (log_.empty() ? std::string("/dev/null") : log_) + " for the host's output";
    return false;
  }
  std::string sh = "/bin/sh", dash_c = "-c", text = command_;
  char* argv[] = {sh.data(), dash_c.data(), text.data(), nullptr};
  std::string error;
  const bool started = spawn_reaped("/bin/sh", argv, in, out, out, &proc_, &error);
  close(in);
  close(out);
  if (!started) {
    *why = "cannot run the host command: " + error;
    return false;
  }
  // Logins until one is accepted: the first bounded by a second, so that a
  // host that listens late is found soon after; each next one twice as long
  // (a loaded machine's host may take longer than a second to answer a
  // whole start: two logins, a node, the bone form's probe).
  OpenOptions attempt = options;
  std::string last = "no login tried";
  double limit = 1;
  for (;;) {
    int status = 0;
    const pid_t w = waitpid(proc_.pid, &status, WNOHANG);
    if (w == proc_.pid) {
      proc_.pid = -1;
      stop_reaped(&proc_);
      *why = "the host command ended (" + wait_status_text(status) + ") before the host accepted a login: " +
             command_ + " (--host-cmd runs the host in the foreground: a command that starts it in the background "
             "and returns ends it too" + (log_.empty() ? std::string(")") : "; its output is in " + log_ + ")");
      return false;
    }
    const double left = std::chrono::duration<double>(until - Clock::now()).count();
    if (left <= 0) {
      stop();
      *why = "the host started by --host-cmd did not accept a login within " +
             std::to_string(static_cast<int>(start_timeout_s_)) + " s (--start-timeout): " + last;
      return false;
    }
    attempt.start_timeout_seconds = std::min(limit, left);
    limit *= 2;
    std::unique_ptr<Implementation> s = open_route(route_, attempt, &last);
    if (s) {
      if (session) *session = std::move(s);
      return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

std::unique_ptr<Implementation> open_launched_host(const Route& route, const OpenOptions& options,
                                                   const std::string& command, const std::string& log,
                                                   std::string* error) {
  auto host = std::make_unique<LaunchedHost>(route, command, log, options.start_timeout_seconds);
  std::unique_ptr<Implementation> first;
  if (!host->start(options, &first, error)) return nullptr;
  return std::make_unique<LaunchedHostImplementation>(std::move(host), options, std::move(first));
}

}  // namespace vgc
