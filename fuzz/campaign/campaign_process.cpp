// campaign_process.cpp — see campaign_process.h.
#include "campaign_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

#include "process_cpu.h"
#include "reaped_command.h"
#include "reaped_process.h"

extern char** environ;

namespace vgc::fuzz {


// The environment of a child: this process's, with env_add (NAME=value)
// replacing or adding variables. Built before fork(), so that the child
// only calls execve (a soak forks from several threads at once, and
// putenv after fork is not safe there).
std::vector<std::string> child_environment(const std::vector<std::string>& env_add) {
  std::vector<std::string> env;
  for (char** e = environ; e && *e; ++e) {
    const std::string entry(*e);
    const std::string name = entry.substr(0, entry.find('=') + 1);
    const bool replaced = std::any_of(env_add.begin(), env_add.end(),
                                      [&](const std::string& kv) { return kv.rfind(name, 0) == 0; });
    if (!replaced) env.push_back(entry);
  }
  env.insert(env.end(), env_add.begin(), env_add.end());
  return env;
}

// Runs argv (in a process group of its own, under the reaper:
// reaped_process.h) with env additions,
// stdout+stderr into `on_line` line by line, until it exits or `deadline`
// passes; then SIGTERM to the whole group, SIGKILL 2 s later. With
// cpu_limit_s > 0 the group is also stopped so once it has used that many
// CPU seconds (process_cpu.h, read at most once a second); its CPU time is
// then the larger of that reading and the kernel's rusage, which misses a
// job killed before its parent waited for it.
ChildRun run_streaming(const std::vector<std::string>& argv, const std::vector<std::string>& env_add,
                        std::chrono::steady_clock::time_point deadline,
                        const std::function<void(const std::string&)>& on_line,
                        const std::function<bool()>& stop_now, double cpu_limit_s) {
  ChildRun result;
  const std::vector<std::string> env = child_environment(env_add);
  std::vector<char*> args, envp;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  for (const std::string& kv : env) envp.push_back(const_cast<char*>(kv.c_str()));
  envp.push_back(nullptr);
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return result;
  ReapedProcess proc;
  ReapedStart how;
  how.envp = envp.data();
  std::string error;
  const bool started = spawn_reaped(args[0], args.data(), 0, fds[1], fds[1], &proc, &error, how);
  close(fds[1]);
  if (!started || proc.program < 0) {
    close(fds[0]);
    if (started) stop_reaped(&proc);
    return result;
  }
  // The group is the program's (signals go to -pid); its end and CPU time
  // come from the reaper (reaper_pid), whose wait status is the program's.
  const pid_t pid = proc.program, reaper_pid = proc.pid;
  std::string pending;
  char buf[4096];
  bool open = true;
  // waitpid that keeps the child's CPU time (its rusage counts the
  // descendants it waited for: libFuzzer's fork-mode jobs).
  auto reap = [&](int* status, int options) {
    rusage ru{};
    const pid_t w = wait4(reaper_pid, status, options, &ru);
    if (w == reaper_pid)
      result.cpu_s = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
                     static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) / 1e6;
    return w;
  };
  auto kill_group = [&](bool late) {
    result.killed = late;
    kill(-pid, SIGTERM);
    const auto hard = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (std::chrono::steady_clock::now() < hard) {
      if (reap(nullptr, WNOHANG) == reaper_pid) return true;  // the reaper killed any job of the group still alive
      usleep(50 * 1000);
    }
    kill(-pid, SIGKILL);
    return false;
  };
  bool reaped = false, stopped = false;
  double cpu_read = 0;
  auto next_cpu_read = std::chrono::steady_clock::now();
  auto budget_spent = [&] {
    if (cpu_limit_s <= 0 || std::chrono::steady_clock::now() < next_cpu_read) return false;
    next_cpu_read = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    cpu_read = std::max(cpu_read, process_group_cpu_seconds(pid));
    return cpu_read >= cpu_limit_s;
  };
  while (open) {
    const auto now = std::chrono::steady_clock::now();
    const bool late = now >= deadline;
    const bool spent = !late && budget_spent();
    if (late || spent || (stop_now && stop_now())) {
      reaped = kill_group(late);
      if (!late) reaped = reaped || reap(nullptr, 0) == reaper_pid;
      stopped = !late;
      result.cpu_spent = spent;
      break;
    }
    const int ms = static_cast<int>(
        std::min<long long>(1000, std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count() + 1));
    pollfd pfd{fds[0], POLLIN, 0};
    const int r = poll(&pfd, 1, ms);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) continue;
    const ssize_t n = read(fds[0], buf, sizeof buf);
    if (n <= 0) {
      open = false;
      break;
    }
    pending.append(buf, static_cast<std::size_t>(n));
    for (std::size_t nl; (nl = pending.find('\n')) != std::string::npos;) {
      std::string line = pending.substr(0, nl);
      pending.erase(0, nl + 1);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      on_line(line);
    }
  }
  if (!pending.empty()) on_line(pending);
  close(fds[0]);
  int status = 0;
  if (!reaped) {
    // The pipe closed: the fuzzer is ending; give it until the deadline.
    for (;;) {
      const pid_t w = reap(&status, WNOHANG);
      if (w == reaper_pid) break;
      if (std::chrono::steady_clock::now() >= deadline) {
        if (!kill_group(true)) reap(&status, 0);
        break;
      }
      usleep(50 * 1000);
    }
  }
  close(proc.control_fd);  // the reaper has ended (or is killing what is left)
  result.cpu_s = std::max(result.cpu_s, cpu_read);
  if (result.cpu_spent) {
    result.exit = 0;  // stopped at its budget: the end asked for, as -max_total_time's
    return result;
  }
  if (reaped || result.killed || stopped) {
    result.exit = 128 + SIGTERM;
    return result;
  }
  result.exit = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

std::string run_capture(const std::string& command) {
  std::string out;
  run_reaped_shell(command, &out);
  return out;
}

}  // namespace vgc::fuzz
