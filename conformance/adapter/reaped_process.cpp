// reaped_process.cpp — see reaped_process.h.
#include "reaped_process.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

extern char** environ;

namespace vgc {
namespace {

// Everything below runs in the forked reaper or program, before any exec:
// async-signal-safe system calls only (no allocation, no stdio, no locks).

void sleep_ms(long ms) {
  timespec t{ms / 1000, (ms % 1000) * 1000000L};
  while (nanosleep(&t, &t) < 0 && errno == EINTR) {
  }
}

// "/proc/<pid>/stat" into buf.
void stat_path(const char* pid, char* buf, std::size_t size) {
  static const char head[] = "/proc/", tail[] = "/stat";
  std::size_t n = 0;
  for (const char* p = head; *p && n + 1 < size; ++p) buf[n++] = *p;
  for (const char* p = pid; *p && n + 1 < size; ++p) buf[n++] = *p;
  for (const char* p = tail; *p && n + 1 < size; ++p) buf[n++] = *p;
  buf[n] = '\0';
}

// The parent pid field of /proc/<pid>/stat ("pid (comm) S ppid ..."; comm
// may hold spaces and parentheses: the last ')' ends it), or -1.
pid_t parent_of(const char* pid) {
  char path[64], buf[512];
  stat_path(pid, path, sizeof path);
  const int fd = open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return -1;
  const ssize_t n = read(fd, buf, sizeof buf - 1);
  close(fd);
  if (n <= 0) return -1;
  buf[n] = '\0';
  const char* close_paren = nullptr;
  for (const char* p = buf; *p; ++p)
    if (*p == ')') close_paren = p;
  if (!close_paren || close_paren[1] != ' ' || !close_paren[2] || close_paren[3] != ' ') return -1;
  pid_t ppid = 0;
  for (const char* p = close_paren + 4; *p >= '0' && *p <= '9'; ++p) ppid = ppid * 10 + (*p - '0');
  return ppid;
}

// SIGKILL to every child of this process (orphans reparented to it) and to
// its process group, found by scanning /proc (getdents64: no allocation).
void kill_children() {
  const pid_t self = getpid();
  const int dir = open("/proc", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return;
  alignas(8) char buf[8192];
  for (;;) {
    const long n = syscall(SYS_getdents64, dir, buf, sizeof buf);
    if (n <= 0) break;
    for (long off = 0; off < n;) {
      // struct linux_dirent64 { u64 d_ino; s64 d_off; u16 d_reclen; u8 d_type; char d_name[]; }
      unsigned short reclen;
      memcpy(&reclen, buf + off + 16, sizeof reclen);
      const char* name = buf + off + 19;
      off += reclen;
      if (name[0] < '1' || name[0] > '9') continue;
      pid_t pid = 0;
      bool digits = true;
      for (const char* p = name; *p; ++p) {
        if (*p < '0' || *p > '9') digits = false;
        else pid = pid * 10 + (*p - '0');
      }
      if (!digits || pid == self || parent_of(name) != self) continue;
      // Its group too, when it leads one (a setsid'd process does); a
      // living process's pid is no other group's id.
      kill(-pid, SIGKILL);
      kill(pid, SIGKILL);
    }
  }
  close(dir);
}

// The program's side of the fork: its own process group, its descriptors,
// default signals, then exec.
[[noreturn]] void exec_program(const char* path, char* const argv[], char* const* envp, int in_fd, int out_fd,
                               int err_fd) {
  setpgid(0, 0);
  dup2(in_fd, 0);  // dup2 clears O_CLOEXEC on 0, 1 and 2
  dup2(out_fd, 1);
  dup2(err_fd, 2);
  syscall(SYS_close_range, 3u, ~0u, 0u);
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  for (int sig : {SIGPIPE, SIGINT, SIGQUIT, SIGTERM, SIGCHLD, SIGHUP, SIGTSTP, SIGTTIN, SIGTTOU})
    sigaction(sig, &dfl, nullptr);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  execve(path, argv, envp ? envp : environ);
  static const char msg[] = "vgc: cannot start a child process (execve failed)\n";
  (void)!write(2, msg, sizeof msg - 1);
  _exit(127);
}

// Ends the reaper the way the program ended.
[[noreturn]] void exit_like(int status) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    rlimit none{0, 0};
    setrlimit(RLIMIT_CORE, &none);  // the program's crash, not a core of the reaper
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigaction(sig, &dfl, nullptr);
    sigset_t only;
    sigemptyset(&only);
    sigaddset(&only, sig);
    sigprocmask(SIG_UNBLOCK, &only, nullptr);
    kill(getpid(), sig);
    _exit(128 + sig);
  }
  _exit(WIFEXITED(status) ? WEXITSTATUS(status) : 125);
}

void write_all(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
}

// keep_descendants, once the program has ended (its status sent): what it
// started lives on, its orphans reaped, until the control pipe's end of
// file (vgc stopped it or ended) or until no child is left.
void keep_descendants(int control_fd) {
  for (;;) {
    pollfd pfd{control_fd, POLLIN, 0};
    if (poll(&pfd, 1, 100) > 0) return;
    pid_t w;
    while ((w = waitpid(-1, nullptr, WNOHANG)) > 0) {
    }
    if (w < 0 && errno == ECHILD) return;
  }
}

// The reaper: a subreaper holding the control pipe's read end, the
// program's parent. Tells vgc the program's pid (report_fd), waits for the
// program's end or the pipe's, then kills everything left (5 s at most) and
// ends as the program did. With `keep`, the program's end sends its status
// on report_fd and what it started is kept first (keep_descendants).
[[noreturn]] void reap_main(int control_fd, int report_fd, bool keep, const char* path, char* const argv[],
                            char* const* envp, int in_fd, int out_fd, int err_fd) {
  setpgid(0, 0);  // out of vgc's group: the terminal's Ctrl-C and a CI's group kill reach vgc, not the reaper
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGTSTP, SIGTTIN, SIGTTOU}) sigaction(sig, &ignore, nullptr);
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigaction(SIGCHLD, &dfl, nullptr);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) != 0) {
    static const char msg[] = "vgc: PR_SET_CHILD_SUBREAPER failed: what the implementation starts may outlive vgc\n";
    (void)!write(err_fd, msg, sizeof msg - 1);
  }
  const pid_t program = fork();
  if (program == 0) exec_program(path, argv, envp, in_fd, out_fd, err_fd);
  if (program > 0) setpgid(program, program);  // also here: no race with the program's own call
  write_all(report_fd, &program, sizeof program);
  // Hold nothing of vgc's but the control pipe and, with `keep`, the report
  // pipe (not a CI log's pipe, not the program's pipes: their end of file
  // is how vgc sees the program end). Both first above 9, so that moving
  // one to 3 or 4 cannot close the other.
  const int control_high = fcntl(control_fd, F_DUPFD, 10);
  const int report_high = keep ? fcntl(report_fd, F_DUPFD, 10) : -1;
  dup2(control_high, 3);
  control_fd = 3;
  if (keep) {
    dup2(report_high, 4);
    report_fd = 4;
  }
  const int null_fd = open("/dev/null", O_RDWR);
  for (int fd = 0; fd < 3; ++fd)
    if (null_fd >= 0 && null_fd != fd) dup2(null_fd, fd);
  syscall(SYS_close_range, keep ? 5u : 4u, ~0u, 0u);
  int status = 0;
  bool ended = program < 0, stop = false;
  if (program < 0) status = 127 << 8;
  while (!ended) {
    pollfd pfd{control_fd, POLLIN, 0};
    const int r = poll(&pfd, 1, 20);
    siginfo_t info{};  // not reaped yet: while it is unreaped its group id is not reused
    if (waitid(P_PID, static_cast<id_t>(program), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == program)
      ended = true;
    if (r > 0) {  // end of file (or a byte): stop
      stop = true;
      break;
    }
  }
  if (keep && !stop) {
    if (program > 0) {
      while (waitpid(program, &status, 0) < 0 && errno == EINTR) {
      }
    }
    write_all(report_fd, &status, sizeof status);
    keep_descendants(control_fd);
  } else if (program > 0) {
    kill(-program, SIGKILL);  // the program's group
    kill(program, SIGKILL);
    while (waitpid(program, &status, 0) < 0 && errno == EINTR) {
    }
  }
  // Then every orphan, as they arrive, until no child is left.
  for (int round = 0; round < 250; ++round) {
    pid_t w;
    while ((w = waitpid(-1, nullptr, WNOHANG)) > 0) {
    }
    if (w < 0 && errno == ECHILD) break;
    kill_children();
    sleep_ms(20);
  }
  exit_like(status);
}

}  // namespace

bool spawn_reaped(const char* path, char* const argv[], int in_fd, int out_fd, int err_fd, ReapedProcess* out,
                  std::string* error, const ReapedStart& how) {
  int control[2], report[2];
  if (pipe2(control, O_CLOEXEC) != 0) {
    *error = std::string("cannot create the reaper's pipe: ") + strerror(errno);
    return false;
  }
  if (pipe2(report, O_CLOEXEC) != 0) {
    *error = std::string("cannot create the reaper's pipe: ") + strerror(errno);
    close(control[0]);
    close(control[1]);
    return false;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    *error = std::string("cannot start a child process's reaper: ") + strerror(errno);
    for (int fd : {control[0], control[1], report[0], report[1]}) close(fd);
    return false;
  }
  if (pid == 0) {
    close(control[1]);
    close(report[0]);
    reap_main(control[0], report[1], how.keep_descendants, path, argv, how.envp, in_fd, out_fd, err_fd);
  }
  close(control[0]);
  close(report[1]);
  // The program's pid comes at once (the reaper's first act after forking
  // it); end of file instead means the reaper died.
  pid_t program = -1;
  std::size_t got = 0;
  while (got < sizeof program) {
    const ssize_t n = read(report[0], reinterpret_cast<char*>(&program) + got, sizeof program - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  if (got < sizeof program) program = -1;
  out->pid = pid;
  out->control_fd = control[1];
  out->program = program;
  if (how.keep_descendants) {
    out->status_fd = report[0];
  } else {
    close(report[0]);
    out->status_fd = -1;
  }
  return true;
}

bool wait_program_status(const ReapedProcess& p, int bound_ms, int* status) {
  if (p.status_fd < 0) return false;
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(bound_ms);
  int value = 0;
  std::size_t got = 0;
  while (got < sizeof value) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now());
    if (left.count() < 0) return false;
    pollfd pfd{p.status_fd, POLLIN, 0};
    const int r = poll(&pfd, 1, static_cast<int>(std::min<long long>(left.count() + 1, 1000)));
    if (r < 0 && errno != EINTR) return false;
    if (r <= 0) continue;
    const ssize_t n = read(p.status_fd, reinterpret_cast<char*>(&value) + got, sizeof value - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    got += static_cast<std::size_t>(n);
  }
  *status = value;
  return true;
}

void keep_until_exit(ReapedProcess* p) {
  static std::mutex mutex;
  static auto* kept_reapers = new std::vector<ReapedProcess>;  // never destroyed: their pipes close with vgc
  std::vector<ReapedProcess>& kept = *kept_reapers;
  const std::lock_guard<std::mutex> lock(mutex);
  for (auto it = kept.begin(); it != kept.end();) {
    if (waitpid(it->pid, nullptr, WNOHANG) == it->pid) {  // nothing it started is left
      close(it->control_fd);
      if (it->status_fd >= 0) close(it->status_fd);
      it = kept.erase(it);
    } else {
      ++it;
    }
  }
  kept.push_back(*p);
  *p = ReapedProcess{};
}

int stop_reaped(ReapedProcess* p, int bound_ms) {
  int status = 0;
  if (p->control_fd >= 0) close(p->control_fd);
  p->control_fd = -1;
  if (p->status_fd >= 0) close(p->status_fd);
  p->status_fd = -1;
  p->program = -1;
  if (p->pid > 0) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(bound_ms);
    for (;;) {
      const pid_t w = waitpid(p->pid, &status, WNOHANG);
      if (w == p->pid || (w < 0 && errno != EINTR)) break;
      if (std::chrono::steady_clock::now() >= until) {
        kill(p->pid, SIGKILL);  // a stuck reaper: what it had not killed yet is left
        while (waitpid(p->pid, &status, 0) < 0 && errno == EINTR) {
        }
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }
  p->pid = -1;
  return status;
}

}  // namespace vgc
