// process_group_guard.cpp — see process_group_guard.h.
#include "process_group_guard.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace vgc {
namespace {

// In the forked watcher only async-signal-safe calls (this process may have
// threads): leave vgc's process group and its signals, hold nothing of
// vgc's but the pipe's read end (it must not keep a CI log's pipe open),
// wait for end of file, kill the group.
[[noreturn]] void watch_in_child(int read_fd, pid_t pgid) {
  setpgid(0, 0);
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGTSTP, SIGTTIN, SIGTTOU})
    sigaction(sig, &ignore, nullptr);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  const int null_fd = open("/dev/null", O_RDWR);
  for (int fd = 0; fd < 3; ++fd)
    if (null_fd >= 0 && null_fd != fd) dup2(null_fd, fd);
  if (read_fd != 3) {
    dup2(read_fd, 3);
    read_fd = 3;
  }
  syscall(SYS_close_range, 4u, ~0u, 0u);
  char c;
  while (read(read_fd, &c, 1) < 0 && errno == EINTR) {
  }
  // End of file: the process that started the group has ended; or a byte:
  // it asked (it never writes one). Either way the group goes.
  kill(-pgid, SIGKILL);
  _exit(0);
}

}  // namespace

bool ProcessGroupGuard::watch(pid_t pgid, std::string* error) {
  release();
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    *error = std::string("cannot create a pipe for the process watcher: ") + std::strerror(errno);
    return false;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    *error = std::string("cannot start the process watcher: ") + std::strerror(errno);
    close(fds[0]);
    close(fds[1]);
    return false;
  }
  if (pid == 0) watch_in_child(fds[0], pgid);
  close(fds[0]);
  watcher_ = pid;
  alive_fd_ = fds[1];
  return true;
}

void ProcessGroupGuard::release() {
  if (watcher_ > 0) {
    kill(watcher_, SIGKILL);  // before it could see end of file: the group is left alone
    while (waitpid(watcher_, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  if (alive_fd_ >= 0) close(alive_fd_);
  watcher_ = -1;
  alive_fd_ = -1;
}

}  // namespace vgc
