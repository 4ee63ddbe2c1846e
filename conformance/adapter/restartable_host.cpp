// restartable_host.cpp — see restartable_host.h.
#include "restartable_host.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>
#include <utility>

#include "forwarding_implementation.h"
#include "reaped_process.h"

namespace vgc {
namespace {

using Clock = std::chrono::steady_clock;

// A host with a restart command: restart() runs it and logs in to the host
// it started; every other call goes to the session open now.
class RestartableHost final : public ForwardingImplementation {
 public:
  RestartableHost(Route route, OpenOptions options, std::string command, std::unique_ptr<Implementation> first)
      : ForwardingImplementation(first.get(), route.spec, "no session"),
        route_(std::move(route)),
        options_(std::move(options)),
        command_(std::move(command)),
        sut_(std::move(first)) {}
  std::uint64_t instance() const override { return starts_; }
  Answer restart() override {
    ++starts_;
    forward_to(nullptr);
    sut_.reset();
    std::string why;
    if (!run_restart_command(command_, 60, &why)) {
      set_why(why);
      return unanswered();
    }
    const auto until = Clock::now() + std::chrono::seconds(15);
    for (;;) {
      std::string error;
      sut_ = open_route(route_, options_, &error);
      if (sut_) {
        forward_to(sut_.get());
        return {};
      }
      set_why("the host did not accept a login after the restart command: " + error);
      if (Clock::now() >= until) return unanswered();
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
  }

 private:
  Route route_;
  OpenOptions options_;
  std::string command_;
  std::unique_ptr<Implementation> sut_;
  std::uint64_t starts_ = 0;
};

}  // namespace

std::unique_ptr<Implementation> open_restartable(const Route& route, const OpenOptions& options,
                                                 const std::string& restart_command, std::string* error) {
  std::unique_ptr<Implementation> sut = open_route(route, options, error);
  if (!sut || restart_command.empty() || route.traits().restartable) return sut;
  return std::make_unique<RestartableHost>(route, options, restart_command, std::move(sut));
}

bool run_restart_command(const std::string& command, double limit_s, std::string* why) {
  if (command.empty()) {
    *why = "no restart command (--restart CMD)";
    return false;
  }
  // Under a reaper that keeps what the command starts (the host) until vgc
  // ends (reaped_process.h, keep_descendants): the host outlives the
  // command, not vgc. No terminal and no pipe of ours: a host left running
  // must not hold vgc's output open.
  const int null = open("/dev/null", O_RDWR | O_CLOEXEC);
  if (null < 0) {
    *why = "cannot open /dev/null to run the restart command";
    return false;
  }
  std::string sh = "/bin/sh", dash_c = "-c", text = command;
  char* argv[] = {sh.data(), dash_c.data(), text.data(), nullptr};
  ReapedProcess proc;
  ReapedStart how;
  how.keep_descendants = true;
  std::string error;
  const bool started = spawn_reaped("/bin/sh", argv, null, null, null, &proc, &error, how);
  close(null);
  if (!started) {
    *why = "cannot run the restart command: " + error;
    return false;
  }
  int status = 0;
  if (!wait_program_status(proc, static_cast<int>(limit_s * 1000), &status)) {
    stop_reaped(&proc);
    *why = "the restart command did not finish within " + std::to_string(static_cast<int>(limit_s)) + " s";
    return false;
  }
  keep_until_exit(&proc);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
  *why = "the restart command failed (" +
         (WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status))
                            : "signal " + std::to_string(WTERMSIG(status))) +
         "): " + command;
  return false;
}

}  // namespace vgc
