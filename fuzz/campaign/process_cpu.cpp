// process_cpu.cpp — CPU seconds of a process group, read from /proc (see
// process_cpu.h).
#include "process_cpu.h"

#include <dirent.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

namespace vgc::fuzz {

namespace {

// Fields of /proc/PID/stat after the command name, which is in parentheses
// and may itself contain spaces and parentheses: the last ')' ends it.
// Field 5 is pgrp, 14-17 utime, stime, cutime, cstime (proc(5)).
bool read_stat(const char* pid, long* pgrp, unsigned long long* ticks) {
  char path[64];
  std::snprintf(path, sizeof path, "/proc/%s/stat", pid);
  FILE* f = std::fopen(path, "r");
  if (!f) return false;
  char buf[1024];
  const std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
  std::fclose(f);
  buf[n] = '\0';
  const char* p = std::strrchr(buf, ')');
  if (!p) return false;
  ++p;
  // state ppid pgrp session tty_nr tpgid flags minflt cminflt majflt cmajflt utime stime cutime cstime:
  // fields 0 to 14 after the name, each read with std::from_chars.
  std::string_view rest(p);
  long long field[15] = {};
  for (int i = 0; i < 15; ++i) {
    const auto start = rest.find_first_not_of(' ');
    if (start == std::string_view::npos) return false;
    rest.remove_prefix(start);
    const std::size_t len = std::min(rest.find(' '), rest.size());
    if (i > 0) {  // field 0 is the state letter
      const auto [end, ec] = std::from_chars(rest.data(), rest.data() + len, field[i]);
      if (ec != std::errc() || end != rest.data() + len) return false;
    }
    rest.remove_prefix(len);
  }
  *pgrp = static_cast<long>(field[2]);
  long long sum = 0;
  for (int i = 11; i <= 14; ++i) sum += field[i] < 0 ? 0 : field[i];
  *ticks = static_cast<unsigned long long>(sum);
  return true;
}

}  // namespace

double process_group_cpu_seconds(pid_t pgid) {
  DIR* d = opendir("/proc");
  if (!d) return 0;
  unsigned long long total = 0;
  while (const dirent* e = readdir(d)) {
    if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
    long pgrp = 0;
    unsigned long long ticks = 0;
    if (read_stat(e->d_name, &pgrp, &ticks) && pgrp == static_cast<long>(pgid)) total += ticks;
  }
  closedir(d);
  const long hz = sysconf(_SC_CLK_TCK);
  return static_cast<double>(total) / static_cast<double>(hz > 0 ? hz : 100);
}

}  // namespace vgc::fuzz
