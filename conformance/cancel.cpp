// cancel.cpp — see cancel.h.
#include "cancel.h"

#include <fcntl.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>

#include <atomic>

namespace vgc {
namespace {

std::atomic<int> g_signal{0};
std::atomic<long> g_sender{0};
std::atomic<long long> g_when_ns{0};  // CLOCK_MONOTONIC of the first request

long long monotonic_ns() noexcept {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);  // async-signal-safe
  return static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}
std::atomic<int> g_read_fd{-1};
std::atomic<int> g_write_fd{-1};

}  // namespace

void prepare_cancel() {
  if (g_read_fd.load() >= 0) return;
  int fds[2];
  if (pipe2(fds, O_CLOEXEC | O_NONBLOCK) != 0) return;  // the runner's own checks still stop the run
  g_write_fd.store(fds[1]);
  g_read_fd.store(fds[0]);
}

void request_cancel(int signal_number, long sender) noexcept {
  int expected = 0;
  if (g_signal.compare_exchange_strong(expected, signal_number)) {
    g_sender.store(sender);
    g_when_ns.store(monotonic_ns());
  }
  const int fd = g_write_fd.load();
  if (fd >= 0) {
    const char byte = 1;
    [[maybe_unused]] const ssize_t n = write(fd, &byte, 1);  // never read back: stays readable
  }
}

bool repeated_cancel(int signal_number, long sender) noexcept {
  return g_signal.load() == signal_number && g_sender.load() == sender &&
         monotonic_ns() - g_when_ns.load() < 1000000000LL;
}

int cancel_signal() noexcept { return g_signal.load(std::memory_order_relaxed); }

const char* cancel_signal_name() noexcept {
  switch (cancel_signal()) {
    case 0: return "";
    case SIGTERM: return "SIGTERM";
    case SIGINT: return "SIGINT";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}

int cancelled_exit_code(std::string_view name) noexcept {
  if (name == "SIGTERM") return 128 + SIGTERM;
  if (name == "SIGINT") return 128 + SIGINT;
  if (name == "SIGHUP") return 128 + SIGHUP;
  return 2;
}

int cancel_fd() noexcept { return g_read_fd.load(std::memory_order_relaxed); }

}  // namespace vgc
