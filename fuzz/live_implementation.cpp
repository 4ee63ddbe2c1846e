// live_implementation.cpp — see live_implementation.h.
#include "live_implementation.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>

namespace vgc::fuzz {
namespace {

using Clock = std::chrono::steady_clock;

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : fallback;
}

OpenOptions open_options(const LiveOptions& o) {
  OpenOptions options;
  options.timeout_seconds = o.timeout_s;
  if (!o.verse_bone_form.empty()) options.verse_bone_form = o.verse_bone_form;
  return options;
}

// A Verse host with a restart command: restart() runs it and logs in to
// the host it started; every other call goes to the session open now.
class RestartableHost final : public Implementation {
 public:
  RestartableHost(LiveOptions o, std::unique_ptr<Implementation> first) : o_(std::move(o)), sut_(std::move(first)) {}
  std::string name() const override { return o_.spec; }
  std::string identity() const override { return sut_ ? sut_->identity() : o_.spec; }
  RouteLimits limits() const override { return sut_ ? sut_->limits() : RouteLimits{}; }
  std::uint64_t instance() const override { return starts_; }
  Answer reset() override { return sut_ ? sut_->reset() : gone(); }
  Answer apply(const Command& c) override { return sut_ ? sut_->apply(c) : gone(); }
  Document snapshot() override { return sut_ ? sut_->snapshot() : Document{CallStatus::Crash, {}, why_}; }
  Document derived() override { return sut_ ? sut_->derived() : Document{CallStatus::Crash, {}, why_}; }
  Document request(const std::string& line) override {
    return sut_ ? sut_->request(line) : Document{CallStatus::Crash, {}, why_};
  }
  Answer restart() override {
    ++starts_;
    sut_.reset();
    if (!run_restart_command(o_.restart, 60, &why_)) return gone();
    const auto until = Clock::now() + std::chrono::seconds(15);
    for (;;) {
      std::string error;
      sut_ = open_implementation(o_.spec, open_options(o_), &error);
      if (sut_) return {};
      why_ = "the host did not accept a login after the restart command: " + error;
      if (Clock::now() >= until) return gone();
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
  }

 private:
  Answer gone() const {
    Answer a;
    a.status = CallStatus::Crash;
    a.detail = why_;
    return a;
  }
  LiveOptions o_;
  std::unique_ptr<Implementation> sut_;
  std::uint64_t starts_ = 0;
  std::string why_ = "no session";
};

}  // namespace

LiveOptions live_options_from_environment() {
  LiveOptions o;
  o.spec = env_or("VGC_FUZZ_IMPL", "");
  const std::string t = env_or("VGC_FUZZ_TIMEOUT", "");
  if (!t.empty()) {
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (end != t.c_str() && *end == '\0' && v > 0) o.timeout_s = v;
  }
  o.verse_bone_form = env_or("VGC_FUZZ_VERSE_BONE_FORM", "");
  o.restart = env_or("VGC_FUZZ_RESTART", "");
  // The baseline's clause ids: the first word of every line that is not a
  // comment (conformance/report/baseline.h; the campaign parsed it whole).
  if (const std::string path = env_or("VGC_FUZZ_BASELINE", ""); !path.empty()) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
      const auto start = line.find_first_not_of(" \t");
      if (start == std::string::npos || line[start] == '#') continue;
      o.tolerated.insert(line.substr(start, line.find_first_of(" \t", start) - start));
    }
  }
  return o;
}

bool can_confirm_on_fresh_instance(const LiveOptions& o) {
  return o.spec.rfind("exec:", 0) == 0 || !o.restart.empty();
}

std::unique_ptr<Implementation> open_live_implementation(const LiveOptions& o, std::string* error) {
  if (o.spec.rfind("exec:", 0) != 0 && o.spec.rfind("verse:", 0) != 0) {
    *error = "'" + o.spec + "': a live implementation is exec:CMD or verse:[NAME@]HOST[:PORT]";
    return nullptr;
  }
  std::unique_ptr<Implementation> sut = open_implementation(o.spec, open_options(o), error);
  if (!sut || o.spec.rfind("verse:", 0) != 0 || o.restart.empty()) return sut;
  return std::make_unique<RestartableHost>(o, std::move(sut));
}

bool run_restart_command(const std::string& command, double limit_s, std::string* why) {
  if (command.empty()) {
    *why = "no restart command (--restart CMD)";
    return false;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    *why = "cannot fork to run the restart command";
    return false;
  }
  if (pid == 0) {
    // A session of its own (the host it starts outlives it, outside the
    // fuzzer's process group), no terminal and no pipe of ours: a host left
    // running must not hold the campaign's output open.
    setsid();
    const int null = open("/dev/null", O_RDWR);
    if (null >= 0) {
      dup2(null, 0);
      dup2(null, 1);
      dup2(null, 2);
    }
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limit_s));
  int status = 0;
  for (;;) {
    const pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (Clock::now() >= until) {
      kill(-pid, SIGKILL);
      waitpid(pid, &status, 0);
      *why = "the restart command did not finish within " + std::to_string(static_cast<int>(limit_s)) + " s";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
  *why = "the restart command failed (" +
         (WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status))
                            : "signal " + std::to_string(WTERMSIG(status))) +
         "): " + command;
  return false;
}

}  // namespace vgc::fuzz
