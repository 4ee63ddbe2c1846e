// run_budget.cpp — see run_budget.h.
#include "run_budget.h"

#include <dirent.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
#include <vector>

namespace vgc {
namespace {

double seconds_of(const rusage& u) {
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

struct ProcStat {
  long ppid = 0;
  double cpu = 0;  // utime + stime + cutime + cstime, seconds
};

// /proc/PID/stat's fields after the command's closing parenthesis (the
// command may hold spaces and parentheses): state ppid ... utime(14)
// stime(15) cutime(16) cstime(17), counted from 1 over the whole line.
bool read_stat(const std::string& pid, ProcStat* out) {
  std::ifstream f("/proc/" + pid + "/stat");
  std::string line;
  if (!std::getline(f, line)) return false;
  const auto close = line.rfind(')');
  if (close == std::string::npos) return false;
  std::istringstream rest(line.substr(close + 1));
  std::vector<std::string> fields;
  for (std::string w; rest >> w && fields.size() < 16;) fields.push_back(w);
  if (fields.size() < 16) return false;  // fields[0] is state (field 3)
  auto num = [](const std::string& s) {
    long long v = 0;
    std::from_chars(s.data(), s.data() + s.size(), v);
    return v;
  };
  static const double tick = static_cast<double>(sysconf(_SC_CLK_TCK));
  out->ppid = static_cast<long>(num(fields[1]));
  out->cpu = static_cast<double>(num(fields[11]) + num(fields[12]) + num(fields[13]) + num(fields[14])) / tick;
  return true;
}

// Seconds the task waited in a run queue for a CPU (/proc/.../schedstat:
// "on-CPU ns, run-queue ns, timeslices"); 0 where the kernel keeps none.
double schedstat_wait_seconds(const std::string& path) {
  std::ifstream f(path);
  std::string on_cpu, waiting;
  if (!(f >> on_cpu >> waiting)) return 0;
  unsigned long long ns = 0;
  std::from_chars(waiting.data(), waiting.data() + waiting.size(), ns);
  return static_cast<double>(ns) / 1e9;
}

// The live descendants of this process, by pid.
std::vector<std::string> live_descendants() {
  std::map<long, ProcStat> all;
  if (DIR* d = opendir("/proc")) {
    while (dirent* e = readdir(d)) {
      const std::string_view name = e->d_name;
      if (name.empty() || name.find_first_not_of("0123456789") != std::string_view::npos) continue;
      ProcStat s;
      if (read_stat(std::string(name), &s)) {
        long pid = 0;
        std::from_chars(name.data(), name.data() + name.size(), pid);
        all[pid] = s;
      }
    }
    closedir(d);
  }
  const long self = static_cast<long>(getpid());
  std::vector<std::string> out;
  for (const auto& [pid, s] : all) {
    // Is `pid` below this process? (a bounded walk up its parents)
    long p = s.ppid;
    for (int depth = 0; depth < 64 && p > 1 && p != self; ++depth) {
      const auto it = all.find(p);
      if (it == all.end()) break;
      p = it->second.ppid;
    }
    if (p == self && pid != self) out.push_back(std::to_string(pid));
  }
  return out;
}

// CPU seconds of the live descendants of this process (and of what they
// waited for).
double descendants_cpu_seconds() {
  double cpu = 0;
  for (const std::string& pid : live_descendants()) {
    ProcStat s;
    if (read_stat(pid, &s)) cpu += s.cpu;
  }
  return cpu;
}

}  // namespace

double run_cpu_seconds() {
  rusage self{}, children{};
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_CHILDREN, &children);
  return seconds_of(self) + seconds_of(children) + descendants_cpu_seconds();
}

double own_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) / 1e9;
}

double run_queue_seconds() {
  double waited = 0;
  if (DIR* d = opendir("/proc/self/task")) {  // every thread of vgc
    while (dirent* e = readdir(d))
      if (e->d_name[0] != '.') waited += schedstat_wait_seconds(std::string("/proc/self/task/") + e->d_name + "/schedstat");
    closedir(d);
  }
  for (const std::string& pid : live_descendants()) waited += schedstat_wait_seconds("/proc/" + pid + "/schedstat");
  return waited;
}

namespace {
std::chrono::steady_clock::duration seconds_duration(double s) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(s));
}
}  // namespace

RunBudget::RunBudget(double seconds) : seconds_(seconds) {
  cpu0_ = last_cpu_ = run_cpu_seconds();
  queued0_ = run_queue_seconds();
  const auto now = std::chrono::steady_clock::now();
  start_ = next_read_ = read_at_ = now;
  own_at_read_ = own_cpu_seconds();
  wall_guard_ = seconds > 0 ? now + seconds_duration(kWallGuardFactor * seconds)
                            : std::chrono::steady_clock::time_point::max();
}

bool RunBudget::spent() {
  if (spent_ || seconds_ <= 0) return spent_;
  const auto now = std::chrono::steady_clock::now();
  if (now >= wall_guard_) {
    // The guard is for waiting that computes nothing (a hang, a host that
    // is not vgc's): the time vgc and the implementation waited for a CPU
    // on a loaded machine moves it on by as much.
    const auto moved = start_ + seconds_duration(kWallGuardFactor * seconds_ +
                                                 std::max(0.0, run_queue_seconds() - queued0_));
    if (now >= moved) return spent_ = by_wall_ = true;
    wall_guard_ = moved;
  }
  // Read every budget/300 (50 ms to 1 s: a scan of /proc costs a few
  // milliseconds); a budget under a second is read every time. A process
  // starved of CPU gets little of it between two reads: a read then waits
  // until vgc has computed 10 times what the last read cost, or 1 s has
  // passed (so the implementation's own computing is still seen), and the
  // budget is not spent on reading it.
  if (now < next_read_ && seconds_ >= 1) return false;
  const double own = own_cpu_seconds();
  if (own - own_at_read_ < 10 * read_cost_ && now - read_at_ < std::chrono::seconds(1)) return false;
  next_read_ = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                         std::chrono::duration<double>(std::min(1.0, std::max(0.05, seconds_ / 300))));
  last_cpu_ = run_cpu_seconds();
  own_at_read_ = own_cpu_seconds();
  read_cost_ = own_at_read_ - own;
  read_at_ = now;
  return spent_ = last_cpu_ - cpu0_ >= seconds_;
}

std::string RunBudget::why() const {
  if (by_wall_)
    return "the wall-clock guard (" + budget_seconds_text(kWallGuardFactor * seconds_) + " s, " +
           budget_seconds_text(kWallGuardFactor) +
           " x --budget, not counting the time spent waiting for a CPU) ran out: the run waited far more than it "
           "computed";
  return "the budget (--budget " + budget_seconds_text(seconds_) + ": CPU seconds of vgc and the implementation) ran out";
}

std::string budget_seconds_text(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", seconds);
  return buf;
}

}  // namespace vgc
