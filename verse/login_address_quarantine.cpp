// login_address_quarantine.cpp — see login_address_quarantine.h
// (docs/verse_wire.md section 2, "A login's address").
#include "login_address_quarantine.h"

#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <deque>
#include <mutex>

namespace vgc::verse {
namespace {

using Clock = std::chrono::steady_clock;

struct Held {
  int fd;
  Clock::time_point until;
};

struct Quarantine {
  std::mutex mutex;
  std::deque<Held> held;  // oldest first

  void release_expired(Clock::time_point now) {
    while (!held.empty() && (held.front().until <= now || held.size() > kMaxQuarantined)) {
      ::close(held.front().fd);
      held.pop_front();
    }
  }
};

Quarantine& quarantine() {
  static Quarantine* q = new Quarantine;  // never destroyed: the sockets close with the process
  return *q;
}

}  // namespace

void quarantine_login_socket(int fd) {
  if (fd < 0) return;
  const int smallest = 1;  // the kernel rounds it up to its minimum
  (void)::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &smallest, sizeof smallest);
  Quarantine& q = quarantine();
  const Clock::time_point now = Clock::now();
  std::lock_guard<std::mutex> lock(q.mutex);
  q.held.push_back({fd, now + std::chrono::duration_cast<Clock::duration>(
                                  std::chrono::duration<double>(kQuarantineSeconds))});
  q.release_expired(now);
}

std::size_t quarantined_login_sockets() {
  Quarantine& q = quarantine();
  std::lock_guard<std::mutex> lock(q.mutex);
  q.release_expired(Clock::now());
  return q.held.size();
}

}  // namespace vgc::verse
