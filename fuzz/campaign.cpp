// campaign.cpp — see campaign.h.
#include "campaign.h"

#include "campaign_html.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>

#include "baseline.h"
#include "clause.h"
#include "command_binary.h"
#include "command_text.h"
#include "display_text.h"
#include "program_command.h"
#include "exec_implementation.h"
#include "coverage_record.h"
#include "live_implementation.h"
#include "restartable_host.h"
#include "minimize_finding.h"
#include "minimize_input.h"
#include "sign_budget.h"
#include "symbolize_functions.h"
#include "process_cpu.h"

namespace vgc::fuzz {
namespace {

namespace fs = std::filesystem;

bool read_file(const fs::path& p, std::string* out) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

bool write_file(const fs::path& p, const std::string& s) {
  std::ofstream out(p, std::ios::binary);
  out << s;
  return static_cast<bool>(out);
}

fs::path self_exe() {
  std::error_code ec;
  fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path{} : p;
}

// The build directory this program was built in (…/build/cli/vgc).
fs::path own_build_dir() { return self_exe().parent_path().parent_path(); }

fs::path source_dir(const CampaignOptions& o) {
  if (!o.source_dir.empty()) return o.source_dir;
  if (const char* e = std::getenv("VGC_SOURCE_DIR"); e && *e) return e;
  std::string cache;
  if (read_file(own_build_dir() / "CMakeCache.txt", &cache)) {
    std::smatch m;
    if (std::regex_search(cache, m, std::regex("CMAKE_HOME_DIRECTORY:INTERNAL=([^\n]*)"))) return m[1].str();
  }
  return fs::current_path();
}

fs::path fuzz_build_dir(const CampaignOptions& o) {
  if (!o.fuzz_build.empty()) return o.fuzz_build;
  if (const char* e = std::getenv("VGC_FUZZ_BUILD_DIR"); e && *e) return e;
  return own_build_dir().parent_path() / "build-fuzz";
}


struct Progress {
  long long execs = 0, exec_s = 0, cov = 0, ft = 0, corp = 0, crashes = 0;
};

// Reads one libFuzzer status line ("#1234 NEW cov: 5 ft: 6 corp: 7/80b ...
// exec/s: 9", or in fork mode "#1234: cov: 5 ft: 6 corp: 7 exec/s 9
// oom/timeout/crash: 0/0/1 ..."). Returns false for any other line.
bool parse_progress(const std::string& line, Progress* p) {
  if (line.empty() || line[0] != '#') return false;
  static const std::regex head(R"(^#(\d+))");
  std::smatch m;
  if (!std::regex_search(line, m, head)) return false;
  if (line.find("cov: ") == std::string::npos) return false;
  p->execs = std::stoll(m[1]);
  auto field = [&](const char* re, long long* out) {
    std::smatch f;
    if (std::regex_search(line, f, std::regex(re))) *out = std::stoll(f[1]);
  };
  field(R"(cov: (\d+))", &p->cov);
  field(R"(ft: (\d+))", &p->ft);
  field(R"(corp: (\d+))", &p->corp);
  field(R"(exec/s:? (\d+))", &p->exec_s);
  field(R"(oom/timeout/crash: \d+/\d+/(\d+))", &p->crashes);
  return true;
}

struct RunResult {
  int exit = -1;
  bool killed = false;  // still running at the deadline: its process group was killed
  bool cpu_spent = false;  // stopped because the group had used its CPU budget (cpu_limit_s)
  double cpu_s = 0;     // user + system of the child and the descendants it waited for
};

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

// Runs argv (in a process group of its own) with env additions,
// stdout+stderr into `on_line` line by line, until it exits or `deadline`
// passes; then SIGTERM to the whole group, SIGKILL 2 s later. With
// cpu_limit_s > 0 the group is also stopped so once it has used that many
// CPU seconds (process_cpu.h, read at most once a second); its CPU time is
// then the larger of that reading and the kernel's rusage, which misses a
// job killed before its parent waited for it.
RunResult run_streaming(const std::vector<std::string>& argv, const std::vector<std::string>& env_add,
                        std::chrono::steady_clock::time_point deadline,
                        const std::function<void(const std::string&)>& on_line,
                        const std::function<bool()>& stop_now, double cpu_limit_s = 0) {
  RunResult result;
  const std::vector<std::string> env = child_environment(env_add);
  std::vector<char*> args, envp;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  for (const std::string& kv : env) envp.push_back(const_cast<char*>(kv.c_str()));
  envp.push_back(nullptr);
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return result;
  const pid_t pid = fork();
  if (pid < 0) return result;
  if (pid == 0) {
    setpgid(0, 0);
    dup2(fds[1], 1);  // dup2 clears O_CLOEXEC on 1 and 2
    dup2(fds[1], 2);
    execve(args[0], args.data(), envp.data());
    static const char msg[] = "execve failed\n";
    (void)!write(2, msg, sizeof msg - 1);
    _exit(127);
  }
  setpgid(pid, pid);  // also here: no race with the child's own call
  close(fds[1]);
  std::string pending;
  char buf[4096];
  bool open = true;
  // waitpid that keeps the child's CPU time (its rusage counts the
  // descendants it waited for: libFuzzer's fork-mode jobs).
  auto reap = [&](int* status, int options) {
    rusage ru{};
    const pid_t w = wait4(pid, status, options, &ru);
    if (w == pid)
      result.cpu_s = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
                     static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) / 1e6;
    return w;
  };
  auto kill_group = [&](bool late) {
    result.killed = late;
    kill(-pid, SIGTERM);
    const auto hard = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (std::chrono::steady_clock::now() < hard) {
      if (reap(nullptr, WNOHANG) == pid) {
        kill(-pid, SIGKILL);  // any job of the group still alive
        return true;
      }
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
      if (!late) reaped = reaped || reap(nullptr, 0) == pid;
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
      if (w == pid) break;
      if (std::chrono::steady_clock::now() >= deadline) {
        if (!kill_group(true)) reap(&status, 0);
        break;
      }
      usleep(50 * 1000);
    }
  }
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
  FILE* p = popen(command.c_str(), "r");
  if (!p) return out;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  pclose(p);
  return out;
}

const std::regex& clause_re() {
  static const std::regex clause(R"(\b[A-Z][A-Z0-9]*(-[A-Z0-9]+)*-[0-9]+\b)");
  return clause;
}

// Digits folded to N, except inside clause ids (BONE-FOREST-1), which stay
// exact: "bones.stateful: BONE-FOREST-1 (MUST, fail): bone 3" becomes
// "bones.stateful: BONE-FOREST-1 (MUST, fail): bone N".
std::string fold_digits_keep_clauses(const std::string& s) {
  static const std::regex digits(R"(\d+)");
  std::string out;
  auto from = s.cbegin();
  for (std::sregex_iterator it(s.begin(), s.end(), clause_re()), end; it != end; ++it) {
    out += std::regex_replace(std::string(from, (*it)[0].first), digits, "N");
    out += it->str();
    from = (*it)[0].second;
  }
  return out + std::regex_replace(std::string(from, s.cend()), digits, "N");
}

// How a crash is signed, from the output of re-running it: `key` groups
// crashes (digits folded everywhere, clause ids included, so that one bug
// reached with different ids or counts is one crash); `shown` is what the
// summary prints, the same text with clause ids exact.
struct CrashSignature {
  std::string key, shown;
};

// The fuzz target's own FINDING line (data in quotes dropped), else the
// sanitizer's error kind and first frame of ours, else the first UBSan
// "runtime error", else "unknown".
CrashSignature crash_signature(const std::string& output) {
  std::istringstream in(output);
  std::string line, kind;
  static const std::regex digits(R"(\d+)");
  while (std::getline(in, line)) {
    if (auto at = line.find("vgc-fuzz: FINDING in "); at != std::string::npos) {
      std::string s = line.substr(at + 10);
      s = s.substr(0, s.find('"'));
      // A finding named by its clause is grouped by the target, the clause
      // and its status ("CLAUSE (LEVEL, status)"), not by the message: one
      // bug shown with other values or commands is one finding.
      static const std::regex named(R"(^(.*?: [A-Z][A-Z0-9]*(?:-[A-Z0-9]+)*-[0-9]+ \([A-Z-]+, [a-z-]+\)): )");
      std::smatch m;
      if (std::regex_search(s, m, named)) return {std::regex_replace(m[1].str(), digits, "N"), fold_digits_keep_clauses(s)};
      return {std::regex_replace(s, digits, "N"), fold_digits_keep_clauses(s)};
    }
    if (auto at = line.find("runtime error: "); at != std::string::npos) {
      const std::string u =
          "ubsan: " + std::regex_replace(line.substr(0, at), std::regex(R"(^.*/)"), "") + line.substr(at + 15);
      return {u, u};
    }
    if (auto at = line.find("ERROR: AddressSanitizer: "); at != std::string::npos && kind.empty()) {
      kind = line.substr(at + 25);
      kind = kind.substr(0, kind.find(' '));
    }
    if (auto at = line.find("ERROR: libFuzzer: "); at != std::string::npos && kind.empty())
      kind = line.substr(at + 18);
    if (!kind.empty()) {
      std::smatch m;
      static const std::regex frame(R"(#\d+ 0x[0-9a-f]+ in (\S+))");
      if (std::regex_search(line, m, frame)) {
        const std::string f = m[1];
        if (f.find("__sanitizer") == std::string::npos && f.find("fuzzer::") == std::string::npos &&
            f.find("__asan") == std::string::npos && f.find("__ubsan") == std::string::npos &&
            f != "abort" && f != "raise" && f != "__GI_abort" && f != "__GI_raise" &&
            f.find("pthread_kill") == std::string::npos && f.find("libc.so") == std::string::npos)
          return {kind + " in " + f, kind + " in " + f};
      }
    }
  }
  const std::string k = kind.empty() ? "unknown" : kind;
  return {k, k};
}

std::string normalize_target(std::string t) {
  if (t.rfind("fuzz_", 0) == 0) t = t.substr(5);
  return t;
}

// NAME=value of every VGC_* variable of this process, sorted.
std::vector<std::string> vgc_environment() {
  std::vector<std::string> vars;
  for (char** e = environ; e && *e; ++e) {
    const std::string entry(*e);
    if (entry.rfind("VGC_", 0) == 0 && entry.find('=') != std::string::npos) vars.push_back(entry);
  }
  std::sort(vars.begin(), vars.end());
  return vars;
}

// `NAME='value' ` for each, for the start of a shell command.
std::string env_prefix(const std::vector<std::string>& vars) {
  std::string out;
  for (const std::string& v : vars) {
    const auto eq = v.find('=');
    out += v.substr(0, eq) + "=" + shell_quote(v.substr(eq + 1)) + " ";
  }
  return out;
}

std::optional<double> seconds_since(const fs::path& f, fs::file_time_type start) {
  std::error_code ec;
  const auto t = fs::last_write_time(f, ec);
  if (ec) return std::nullopt;
  return std::max(0.0, std::chrono::duration<double>(t - start).count());
}

// Which implementation a campaign fuzzes (--impl) and the environment
// variables that name it to the target: VGC_FUZZ_PLUGIN for a plugin in
// process; VGC_FUZZ_IMPL (and VGC_FUZZ_TIMEOUT, VGC_FUZZ_VERSE_BONE_FORM,
// VGC_FUZZ_RESTART) for a live one (fuzz/live_implementation.h).
struct ImplementationChoice {
  std::string plugin;             // absolute path, or ""
  std::optional<Route> live;      // exec:CMD or verse:..., or none
  std::vector<std::string> env;   // NAME=value
  std::string spec() const {
    return live ? live->spec : plugin.empty() ? "reference" : route_spec(RouteKind::Plugin, plugin);
  }
  // Whether the live implementation is of `kind`.
  bool live_on(RouteKind kind) const { return live && live->kind == kind; }
};

bool is_implementation_variable(const std::string& v) {
  for (const char* n : {"VGC_FUZZ_PLUGIN=", "VGC_FUZZ_IMPL=", "VGC_FUZZ_TIMEOUT=", "VGC_FUZZ_VERSE_BONE_FORM=",
                        "VGC_FUZZ_RESTART=", "VGC_FUZZ_BASELINE=", "VGC_FUZZ_IMPL_COVERAGE=",
                        "VGC_FUZZ_IMPL_COVERAGE_DIR=", "VGC_COVERAGE_SHM="})
    if (v.rfind(n, 0) == 0) return true;
  return false;
}

bool choose_implementation(const CampaignOptions& o, const std::string& name, bool property,
                           ImplementationChoice* out) {
  const bool live = o.impl && !o.impl->traits().in_process;
  const bool exec = o.impl && o.impl->kind == RouteKind::Exec;
  if (o.impl_coverage != "guide" && o.impl_coverage != "guide-counts" && o.impl_coverage != "observe" &&
      o.impl_coverage != "off") {
    fmt::print(stderr, "vgc fuzz: --impl-coverage takes guide, guide-counts, observe or off, not '{}'\n",
               o.impl_coverage);
    return false;
  }
  if (o.impl_coverage != "guide" && !exec) {
    fmt::print(stderr, "vgc fuzz: --impl-coverage is for --impl exec:CMD (a program vgc starts)\n");
    return false;
  }
  if (o.coverage_report && (!exec || o.impl_coverage == "off")) {
    fmt::print(stderr, "vgc fuzz: --coverage-report is for --impl exec:CMD with its coverage on (not "
                       "--impl-coverage off)\n");
    return false;
  }
  if (!live && (o.call_timeout_s > 0 || !o.verse_bone_form.empty() || !o.restart.empty())) {
    fmt::print(stderr, "vgc fuzz: --timeout, --verse-bone-form and --restart are for --impl exec:CMD or verse:HOST\n");
    return false;
  }
  if (!o.restart.empty() && o.impl->traits().restartable) {
    fmt::print(stderr, "vgc fuzz: --restart is for --impl verse:HOST (an exec: program is restarted by vgc)\n");
    return false;
  }
  if (!o.impl || o.impl->kind == RouteKind::Reference) return true;
  if (live) {
    if (name != "differential") {
      fmt::print(stderr, "vgc fuzz: --impl {} (a live implementation) is for the differential target only\n",
                 o.impl->form());
      return false;
    }
    out->live = o.impl;
    out->env.push_back("VGC_FUZZ_IMPL=" + o.impl->spec);
    if (o.call_timeout_s > 0) out->env.push_back(fmt::format("VGC_FUZZ_TIMEOUT={}", o.call_timeout_s));
    if (!o.verse_bone_form.empty()) out->env.push_back("VGC_FUZZ_VERSE_BONE_FORM=" + o.verse_bone_form);
    if (!o.restart.empty()) out->env.push_back("VGC_FUZZ_RESTART=" + o.restart);
    // The implementation's own coverage (live_coverage.h; exec: only).
    if (o.impl_coverage != "guide" && exec)
      out->env.push_back("VGC_FUZZ_IMPL_COVERAGE=" + o.impl_coverage);
    // Known deviations do not stop libFuzzer (live_implementation.h).
    if (!o.baseline.empty()) out->env.push_back("VGC_FUZZ_BASELINE=" + fs::absolute(o.baseline).string());
    return true;
  }
  if ((name != "differential" && !property) || o.impl->kind != RouteKind::Plugin) {
    fmt::print(stderr,
               "vgc fuzz: --impl takes plugin:PATH (or reference) for the differential and property targets, or "
               "exec:CMD / verse:HOST[:PORT] for the differential target\n");
    return false;
  }
  out->plugin = fs::absolute(o.impl->target).string();
  if (!fs::exists(out->plugin)) {
    fmt::print(stderr, "vgc fuzz: no such plugin {}: give --impl plugin:PATH the path of your plugin's shared library\n",
               out->plugin);
    return false;
  }
  out->env.push_back("VGC_FUZZ_PLUGIN=" + out->plugin);
  return true;
}

// The status a finding line names ("CLAUSE (LEVEL, status): ..."), or "".
std::string status_of_finding(const std::string& line) {
  static const std::regex form(R"(-[0-9]+ \([A-Z-]+, ([a-z-]+)\): )");
  std::smatch m;
  return std::regex_search(line, m, form) ? m[1].str() : std::string{};
}

// ` --timeout T --verse-bone-form F` for `vgc replay` of a live
// implementation's counterexample, as the campaign ran it.
std::string replay_options(const CampaignOptions& o) {
  std::string out;
  if (o.call_timeout_s > 0) out += fmt::format(" --timeout {}", o.call_timeout_s);
  if (!o.verse_bone_form.empty()) out += " --verse-bone-form " + shell_quote(o.verse_bone_form);
  return out;
}

// Plain-mode rounds of a live implementation's campaign (see run_campaign):
// while libFuzzer stopped at a finding and a second or more of --time
// is left, it runs again on the same corpus with the next seed. Returns
// the last round's result with the CPU time of all of them.
RunResult run_more_rounds(std::vector<std::string> argv, const std::vector<std::string>& env_add,
                          std::chrono::steady_clock::time_point deadline,
                          const std::function<void(const std::string&)>& on_line, const CampaignOptions& o,
                          std::chrono::steady_clock::time_point t0, RunResult rr, Progress* p,
                          long long* execs_before, std::ofstream* log) {
  using clock = std::chrono::steady_clock;
  for (unsigned round = 1; !rr.killed && rr.exit != 0; ++round) {
    const double left = o.time_s - std::chrono::duration<double>(clock::now() - t0).count();
    if (left < 1 || p->execs == 0) break;  // no time left, or the round ran nothing (it could not start)
    *execs_before += p->execs;
    p->execs = 0;
    for (std::string& a : argv) {
      if (a.rfind("-max_total_time=", 0) == 0) a = "-max_total_time=" + std::to_string(std::max(1LL, static_cast<long long>(left)));
      if (a.rfind("-seed=", 0) == 0) a = "-seed=" + std::to_string(o.seed + round);
    }
    *log << "vgc fuzz: libFuzzer stopped (exit " << rr.exit << ", a finding): round " << round + 1 << ", seed "
         << o.seed + round << ", " << static_cast<long long>(left) << " s left\n";
    const double cpu = rr.cpu_s;
    rr = run_streaming(argv, env_add, deadline, on_line, {});
    rr.cpu_s += cpu;
  }
  return rr;
}

}  // namespace

std::string stream_to_text(const std::string& bytes) {
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  std::vector<Command> cs;
  std::size_t pos = 0;
  DecodeStatus s = DecodeStatus::End;
  for (;;) {
    Command c;
    s = decode_command(data, bytes.size(), &pos, &c);
    if (s != DecodeStatus::Ok) break;
    cs.push_back(std::move(c));
  }
  std::string out = print_commands(cs);
  if (s != DecodeStatus::End)
    out += fmt::format("# the last {} bytes do not decode ({}) and were not run\n", bytes.size() - pos,
                       decode_status_name(s));
  return out;
}

std::string campaign_source_dir(const CampaignOptions& o) { return source_dir(o).string(); }
std::string campaign_fuzz_build_dir(const CampaignOptions& o) { return fuzz_build_dir(o).string(); }

std::string clause_of_finding(const std::string& line) {
  // "CLAUSE (LEVEL, status): " — the form of clause_finding.h.
  static const std::regex form(R"((?:^|: )([A-Z][A-Z0-9]*(?:-[A-Z0-9]+)*-[0-9]+) \([A-Z-]+, [a-z]+\): )");
  std::smatch m;
  if (!std::regex_search(line, m, form)) return {};
  return find_clause(m[1].str()) ? m[1].str() : std::string{};
}

namespace {

using clock = std::chrono::steady_clock;

// What the steps of one campaign share (run_campaign runs them in order).
struct CampaignRun {
  explicit CampaignRun(const CampaignOptions& opts) : o(opts) {}
  const CampaignOptions& o;
  std::string name;  // the target without fuzz_
  bool property = false, mesh = false;
  Baseline baseline;
  fs::path src, binary, dir, corpus, crashes, cex;
  ImplementationChoice impl;             // --impl: a plugin, a live implementation or the reference
  std::string plugin;                    // absolute path, "" for the reference or a live implementation
  std::vector<std::string> env_add;      // what the target runs with beyond this process's environment
  std::vector<std::string> run_env;      // VGC_* of this process, without the plugin (for vgc replay)
  std::vector<std::string> target_env;   // run_env and the plugin (for the target)
  CampaignSummary s;
  clock::time_point t0;
  fs::file_time_type sys0;
  SignBudget sign;                       // the budget of signing, minimizing and replaying crashes
  Progress progress;
  std::vector<CampaignSample> samples;   // for report.html's plots
  RunResult fuzzed;
  long long execs_before = 0;            // live rounds: executions of the rounds before the last
};

// The crash inputs of one signature.
struct CrashGroup {
  std::map<fs::path, std::string> shown;    // per input: its signature with exact clause ids
  std::vector<fs::path> files;              // smallest first
  std::map<fs::path, std::string> printed;  // the target's own counterexample block, per input
  std::map<fs::path, std::optional<double>> first_seen;
};

// The target's own counterexample block ("----8<---- counterexample.vgc"
// or, for the mesh targets, "----8<---- mesh.txt") in its output.
std::optional<std::string> printed_block(const CampaignRun& r, const std::string& output) {
  const std::string open = r.mesh ? "----8<---- mesh.txt\n" : "----8<---- counterexample.vgc\n";
  if (auto a = output.find(open); a != std::string::npos)
    if (auto b = output.find("----8<----\n", a + open.size()); b != std::string::npos)
      return output.substr(a + open.size(), b - a - open.size());
  return std::nullopt;
}

// Re-runs one input through the target alone (its output, stdout and stderr).
std::string rerun_input(const CampaignRun& r, const fs::path& f) {
  // A live implementation's input also starts it (a process, a login) and
  // confirms a crash on a fresh instance inside the target: more time.
  return run_capture(std::string(!r.impl.live ? "timeout 5" : "timeout 60") + " env " +
                     env_prefix(r.target_env) + shell_quote(r.binary.string()) + " " + shell_quote(f.string()) +
                     " 2>&1");
}

// The target's name, --time, --baseline, the binary and --impl, checked
// before anything runs; fills the run's name, paths and environments.
// Returns 0, or the exit code 2 with a message on stderr.
int check_campaign_options(CampaignRun* r) {
  const CampaignOptions& o = r->o;
  r->name = normalize_target(o.target);
  const std::string& name = r->name;
  r->property = name.rfind("property_", 0) == 0;
  static const char* const kGroups[] = {"layers", "polygons", "creases", "bones", "values", "ids", "commands"};
  bool known_group = false;
  for (const char* g : kGroups) known_group = known_group || name == std::string("property_") + g;
  r->mesh = name == "mesh_manifold" || name == "mesh_subdivision";
  if (name != "stream" && name != "text" && name != "differential" && name != "verse_packet" && !r->mesh &&
      !known_group) {
    fmt::print(stderr,
               "vgc fuzz: unknown target '{}': expected stream, text, differential, verse_packet, mesh_manifold, "
               "mesh_subdivision or property_<group> "
               "(layers, polygons, creases, bones, values, ids, commands)\n",
               o.target);
    return 2;
  }
  if (!(o.time_s > 0)) {
    fmt::print(stderr, "vgc fuzz: --time must be a positive number of seconds\n");
    return 2;
  }
  if (!o.baseline.empty()) {
    std::string error;
    if (!load_baseline(o.baseline, &r->baseline, &error)) {
      fmt::print(stderr, "vgc fuzz: --baseline: {}\n", escape_unprintable(error));
      return 2;
    }
  }
  const std::string target = "fuzz_" + name;
  r->src = fs::absolute(source_dir(o));
  const fs::path fbuild = fuzz_build_dir(o);
  r->binary = fbuild / "fuzz" / target;
  if (!fs::exists(r->binary)) {
    fmt::print(stderr,
               "vgc fuzz: no libFuzzer binary {}\n"
               "  `./vgc fuzz ...` builds it; by hand: CC=clang CXX=clang++ cmake -S {} -B {} -DVGC_FUZZ=ON"
               " && cmake --build {} --target {}\n",
               r->binary.string(), r->src.string(), fbuild.string(), fbuild.string(), target);
    return 2;
  }
  // The implementation under test and the variables that tell the target.
  if (!choose_implementation(o, name, r->property, &r->impl)) return 2;
  r->plugin = r->impl.plugin;
  r->env_add = r->impl.env;
  // Every VGC_* variable the target runs with: ours (VGC_FAULT,
  // VGC_FUZZ_MESH_FAULT, ...) and the implementation's (the plugin's path,
  // a live implementation's spec and options).
  r->run_env = vgc_environment();
  r->run_env.erase(std::remove_if(r->run_env.begin(), r->run_env.end(), is_implementation_variable), r->run_env.end());
  r->target_env = r->run_env;
  r->target_env.insert(r->target_env.end(), r->env_add.begin(), r->env_add.end());
  std::sort(r->target_env.begin(), r->target_env.end());
  CampaignSummary& s = r->s;
  s.target = target;
  s.seed = o.seed;
  s.jobs = std::max(1, o.jobs);
  s.time_s = o.time_s;
  s.binary = r->binary.string();
  s.implementation = r->impl.spec();
  s.environment = r->target_env;
  s.empty_corpus = o.empty_corpus;
  s.stop_at_first = o.stop_at_first;
  s.baseline = o.baseline;
  return 0;
}

// The run's directory, claimed with one mkdir: two campaigns of the same
// target and seed started in the same second (a script running seeds or
// faults side by side) get -2, -3, ... instead of sharing one directory
// (they did, and one of them aborted). Then its corpus: the committed one
// and the extra corpora. Returns 0, or 2 with a message.
int claim_run_directory(CampaignRun* r) {
  const CampaignOptions& o = r->o;
  CampaignSummary& s = r->s;
  const fs::path runs = r->src / "reports" / "fuzz" / s.target;
  const std::string stamp = utc_stamp() + "-seed" + std::to_string(o.seed);
  std::error_code ec;
  fs::create_directories(runs, ec);
  s.run = stamp;
  for (int k = 2; !ec && !fs::create_directory(runs / s.run, ec) && !ec; ++k) s.run = stamp + "-" + std::to_string(k);
  if (ec) {
    fmt::print(stderr, "vgc fuzz: cannot create a run directory under {}: {}\n", runs.string(), ec.message());
    return 2;
  }
  r->dir = runs / s.run;
  s.run_dir = r->dir.string();
  r->corpus = r->dir / "corpus", r->crashes = r->dir / "crashes", r->cex = r->dir / "counterexamples";
  fs::create_directories(r->corpus, ec);
  if (!ec) fs::create_directories(r->crashes, ec);
  if (!ec) fs::create_directories(r->cex, ec);
  if (ec) {
    fmt::print(stderr, "vgc fuzz: cannot create {}: {}\n", r->dir.string(), ec.message());
    return 2;
  }
  const fs::path committed = r->src / "corpora" / "fuzz" / s.target;
  if (!o.empty_corpus && fs::is_directory(committed))
    for (const auto& e : fs::directory_iterator(committed))
      if (e.is_regular_file()) {
        fs::copy_file(e.path(), r->corpus / e.path().filename(), fs::copy_options::overwrite_existing, ec);
        ++s.seed_files;
      }
  for (const std::string& extra : o.extra_corpora)
    if (fs::is_directory(extra, ec))
      for (const auto& e : fs::directory_iterator(extra, ec))
        if (e.is_regular_file())
          fs::copy_file(e.path(), r->corpus / e.path().filename(), fs::copy_options::skip_existing, ec);
  return 0;
}

// A live implementation with one job runs libFuzzer's plain mode in
// rounds: restarted on the same corpus after each finding until --time is
// spent (a fork-mode job logs in again every few seconds and first re-runs
// its share of the corpus: 50 instead of 140 exec/s against `vgc serve
// --verse`; docs/fuzzing.md "Throughput of a live implementation").
bool live_rounds(const CampaignRun& r) { return r.impl.live && r.s.jobs == 1 && !r.o.stop_at_first; }

// libFuzzer's command line. One job stopping at the first finding runs
// libFuzzer in its plain mode, which stops there by itself (so do the
// rounds of a live implementation); otherwise fork mode (-fork=N).
std::vector<std::string> libfuzzer_argv(const CampaignRun& r) {
  const CampaignOptions& o = r.o;
  const bool rounds = live_rounds(r);
  const bool plain = (o.stop_at_first && r.s.jobs == 1) || rounds;
  std::vector<std::string> argv = {r.binary.string(),
                                   plain ? "-runs=-1" : "-fork=" + std::to_string(r.s.jobs),
                                   "-max_total_time=" + std::to_string(std::max(1LL, static_cast<long long>(o.time_s))),
                                   "-seed=" + std::to_string(o.seed),
                                   "-artifact_prefix=" + r.crashes.string() + "/",
                                   "-print_final_stats=1",
                                   "-max_len=" + std::to_string(o.max_len),
                                   // An input still running after 10 s is a hang, saved as
                                   // a timeout-* finding (libFuzzer's default waits 20 min,
                                   // longer than most campaigns). A live implementation's
                                   // own hangs are bounded by the call time-out and
                                   // confirmed on a fresh instance inside the input: more time.
                                   !r.impl.live ? "-timeout=10" : "-timeout=120"};
  if (!o.stop_at_first && !rounds) argv.insert(argv.begin() + 2, "-ignore_crashes=1");
  // A live implementation runs in its own process: what LeakSanitizer could
  // find in the fuzzer is the adapter's state, which outlives every input
  // on purpose (its process or session, the recent history for confirming
  // a crash), so libFuzzer saw more mallocs than frees on nearly every
  // input and ran a leak scan each time: 27% of the time against `vgc
  // serve --verse`, 206 instead of 1200 exec/s against `vgc serve` over
  // exec (docs/fuzzing.md "Throughput of a live implementation").
  if (r.impl.live) argv.push_back("-detect_leaks=0");
  const fs::path dict = r.src / "corpora" / "fuzz" / (r.s.target + ".dict");
  if (fs::exists(dict)) argv.push_back("-dict=" + dict.string());
  argv.push_back(r.corpus.string());
  return argv;
}

// Runs libFuzzer until --time (and its grace) with progress on stderr or
// o.progress, its output into fuzzer.log.
void run_libfuzzer(CampaignRun* r) {
  const CampaignOptions& o = r->o;
  CampaignSummary& s = r->s;
  const std::vector<std::string> argv = libfuzzer_argv(*r);
  // --stop-at-first in fork mode: the campaign stops the jobs itself once
  // a crash input is saved (one plain job stops there by itself). Saved
  // means written whole: not empty and untouched for a second. Stopping at
  // the first directory entry killed libFuzzer between its fopen and its
  // fwrite now and then, which left an empty input that replayed to
  // nothing ("did not reproduce").
  std::function<bool()> stop_now;
  if (o.stop_at_first && !(s.jobs == 1))
    stop_now = [crashes = r->crashes] {
      std::error_code e;
      const auto now = fs::file_time_type::clock::now();
      for (const auto& f : fs::directory_iterator(crashes, e)) {
        std::error_code fe;
        if (!f.is_regular_file(fe) || f.file_size(fe) == 0 || fe) continue;
        const auto written = f.last_write_time(fe);
        if (!fe && now - written >= std::chrono::seconds(1)) return true;
      }
      return false;
    };
  std::string cmdline;
  for (const auto& a : argv) cmdline += (cmdline.empty() ? "" : " ") + shell_quote(a);
  cmdline = env_prefix(r->target_env) + cmdline;
  s.command = cmdline;
  if (!o.quiet)
    fmt::print(stderr, "vgc fuzz: {} for {} s, {} job(s), seed {}, {} seed inputs\n  run: {}\n  {}\n", s.target,
               o.time_s, s.jobs, o.seed, s.seed_files, r->dir.string(), cmdline);

  std::ofstream log(r->dir / "fuzzer.log");
  Progress& p = r->progress;
  r->t0 = clock::now();
  r->sys0 = fs::file_time_type::clock::now();
  const auto t0 = r->t0;
  // libFuzzer is asked to stop at --time; it gets 5 s (grace_s) more to
  // write its final stats, then its process group is killed.
  const double grace = o.grace_s > 0 ? o.grace_s : 5;
  const auto deadline = t0 + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(o.time_s + grace));
  auto last_print = t0 - std::chrono::seconds(60);
  const auto on_line = [&](const std::string& line) {
    log << line << '\n';
    if (!parse_progress(line, &p)) return;
    const auto now = clock::now();
    const double t = std::chrono::duration<double>(now - t0).count();
    r->samples.push_back({t, p.execs + r->execs_before, p.cov, p.ft, p.corp});
    const std::string figures = fmt::format("execs {}  exec/s {}  cov {}  ft {}  corpus {}  crashes {}",
                                            p.execs + r->execs_before, p.exec_s, p.cov, p.ft, p.corp, p.crashes);
    if (o.progress) {
      o.progress(fmt::format("{} for {:.0f} s: {}", s.target, o.time_s, figures));
    } else if (!o.quiet && now - last_print >= std::chrono::seconds(10)) {
      fmt::print(stderr, "[{:5.0f}/{:.0f} s] {}\n", t, o.time_s, figures);
      last_print = now;
    }
  };
  // An exec: implementation's coverage records go to the run's directory
  // (for the fuzzing only: a re-run of a saved input adds nothing to them).
  std::vector<std::string> env = r->env_add;
  if (r->impl.live_on(RouteKind::Exec) && o.impl_coverage != "off") {
    std::error_code ec;
    fs::create_directories(r->dir / "implementation_coverage", ec);
    env.push_back("VGC_FUZZ_IMPL_COVERAGE_DIR=" + (r->dir / "implementation_coverage").string());
  }
  r->fuzzed = run_streaming(argv, env, deadline, on_line, stop_now, o.cpu_time_s);
  if (live_rounds(*r))
    r->fuzzed = run_more_rounds(argv, env, deadline, on_line, o, t0, r->fuzzed, &p, &r->execs_before, &log);
  const RunResult& rr = r->fuzzed;
  if (rr.killed) log << "vgc fuzz: still running " << o.time_s + grace << " s after the start: process group killed\n";
  log.close();
  if (o.progress) o.progress("");
  s.libfuzzer_exit = rr.exit;
  s.killed_at_deadline = rr.killed;
  s.cpu_s = rr.cpu_s;
  s.cpu_budget_spent = rr.cpu_spent;
  if (rr.killed) fmt::print(stderr, "vgc fuzz: libFuzzer overran --time {} s: killed\n", o.time_s);
}

// Crashes: re-runs each saved input alone (smallest first, within a budget
// of its own: at most 200 inputs and max(10 s, --time / 10), replays and
// minimization of the counterexamples included), signs it, groups the
// inputs by signature (key: digits folded).
std::map<std::string, CrashGroup> sign_crash_inputs(CampaignRun* r) {
  CampaignSummary& s = r->s;
  std::map<std::string, CrashGroup> unique;
  std::vector<fs::path> saved;
  for (const auto& e : fs::directory_iterator(r->crashes))
    if (e.is_regular_file()) saved.push_back(e.path());
  std::sort(saved.begin(), saved.end(), [](const fs::path& a, const fs::path& b) {
    const auto sa = fs::file_size(a), sb = fs::file_size(b);
    return sa != sb ? sa < sb : a < b;
  });
  s.crash_inputs = saved.size();
  for (const fs::path& f : saved)
    if (auto t = seconds_since(f, r->sys0); t && (!s.time_to_first_finding_s || *t < *s.time_to_first_finding_s))
      s.time_to_first_finding_s = t;
  r->sign = SignBudget::starting_now(r->o.time_s);
  // A live implementation costs a process or a login per input re-run:
  // its inputs get half the budget, so that the unique findings are still
  // minimized and replayed on a fresh instance in the other half.
  const bool live = bool(r->impl.live);
  for (const fs::path& f : saved) {
    if (s.crash_inputs_signed >= 200) break;
    if (live ? r->sign.half_spent() : r->sign.spent()) {
      s.signing_stopped = r->sign.wall_guard_reached() ? "the wall guard" : "the CPU budget";
      break;
    }
    ++s.crash_inputs_signed;
    const std::string output = rerun_input(*r, f);
    CrashSignature sig = crash_signature(output);
    // A live implementation's finding that the input alone does not show
    // again (it depended on the instance's history or on timing; the
    // target's own confirmation says which in fuzzer.log): said so, not
    // "unknown".
    if (r->impl.live && sig.key == "unknown" && output.find("FINDING") == std::string::npos)
      sig = {"not reproduced", "not reproduced: the input alone, re-run on a fresh instance, showed nothing (the "
                               "finding depended on the implementation's history or timing; its FINDING line is in "
                               "fuzzer.log)"};
    CrashGroup& g = unique[sig.key];
    g.shown[f] = sig.shown;
    g.files.push_back(f);
    g.first_seen[f] = seconds_since(f, r->sys0);
    if (auto block = printed_block(*r, output)) g.printed[f] = *block;
  }
  return unique;
}

// The finding's summary fields from its group: signature, other forms,
// inputs, first seen, clause, level, baseline.
CampaignCrash describe_crash(const CampaignRun& r, const std::string& key, CrashGroup& g) {
  CampaignCrash c;
  const fs::path& rep = g.files.front();  // smallest (saved was sorted by size)
  c.dedup_key = key;
  c.signature = g.shown[rep];
  for (const auto& [file, text] : g.shown)
    if (text != c.signature && std::find(c.also.begin(), c.also.end(), text) == c.also.end()) c.also.push_back(text);
  c.inputs = g.files.size();
  c.input = rep.string();
  for (const fs::path& f : g.files)
    if (auto t = g.first_seen[f]; t && (!c.first_seen_s || *t < *c.first_seen_s)) c.first_seen_s = t;
  c.clause = clause_of_finding(c.signature);
  if (!c.clause.empty()) {
    if (const Clause* cl = find_clause(c.clause)) c.level = clause_level_name(cl->level);
    c.in_baseline = r.baseline.reasons.count(c.clause) > 0;
  }
  c.replay_fuzzer = env_prefix(r.target_env) + shell_quote(r.binary.string()) + " " + shell_quote(rep.string());
  return c;
}

// Whether the finding's counterexample is a command program that
// minimize_finding shrinks (a clause finding of a command-stream target);
// every other finding is raw bytes, minimized by libFuzzer.
bool shrinks_as_program(const CampaignRun& r, const CampaignCrash& c) {
  const bool command_stream = r.name != "text" && r.name != "verse_packet" && !r.mesh;
  return command_stream && !c.clause.empty();
}

// A raw-bytes finding's input minimized with libFuzzer's crash-minimizing
// steps (minimize_input.h) into minimized/, kept only when a fresh run signs
// it with the group's key. The minimization is bounded by steps, mutations
// and CPU seconds, seeded by the campaign's seed, so the same finding
// minimizes to the same bytes on an idle or a loaded machine; it is not cut
// by the signing budget (a wall-clock share of which used to leave it
// larger under load). Its wall guard (10 min) only stops a stuck step. On
// success the group's smallest input becomes the minimized one (with the
// target's printed block of it), and *bytes its contents.
void minimize_raw_input(CampaignRun* r, const std::string& key, CrashGroup& g, CampaignCrash* c,
                        std::string* bytes) {
  std::error_code ec;
  fs::create_directories(r->dir / "minimized", ec);
  const fs::path rep = c->input;
  const fs::path out = r->dir / "minimized" / rep.filename();
  std::string output;
  MinimizeLimits limits;
  limits.seed = r->o.seed;
  limits.cpu_seconds = 60;
  const MinimizedInput m = minimize_input(
      env_prefix(r->target_env) + shell_quote(r->binary.string()), rep.string(), out.string(),
      [&](const std::string& candidate) {
        output = rerun_input(*r, candidate);
        return crash_signature(output).key == key;
      },
      limits, clock::now() + std::chrono::minutes(10));
  c->minimize_note = m.note;
  if (!m.kept) return;
  c->minimized_input = m.file;
  c->input_bytes = m.before;
  c->minimized_bytes = m.after;
  read_file(m.file, bytes);
  if (auto block = printed_block(*r, output)) g.printed[m.file] = *block;
  g.files.front() = m.file;
  c->replay_fuzzer = env_prefix(r->target_env) + shell_quote(r->binary.string()) + " " + shell_quote(m.file);
}

// The counterexample of a finding of text, verse_packet or a mesh target:
// the input itself (text), its bytes in hex (a datagram) or the mesh the
// target printed; each replays through the target.
void write_input_counterexample(const CampaignRun& r, const CrashGroup& g, const std::string& bytes,
                                CampaignCrash* c) {
  const fs::path cex_file = c->counterexample;
  const std::string& target = r.s.target;
  auto printed = g.printed.find(g.files.front());
  c->replay = c->replay_fuzzer;
  if (r.name == "text") {
    write_file(cex_file, bytes);  // the input is text already
  } else if (r.name == "verse_packet") {  // one datagram: no command file; the input replays
    std::string text = "# vgc fuzz " + target + " counterexample: " + c->signature + "\n# from " +
                       g.files.front().string() + "\n# replay: " + c->replay_fuzzer + "\n# the datagram, " +
                       std::to_string(bytes.size()) + " bytes, in hex:\n";
    static const char* hex = "0123456789abcdef";
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      const auto b = static_cast<unsigned char>(bytes[i]);
      text += hex[b >> 4];
      text += hex[b & 15];
      text += (i % 16 == 15 || i + 1 == bytes.size()) ? '\n' : ' ';
    }
    if (printed != g.printed.end()) text += printed->second;
    write_file(cex_file, text);
  } else {  // a mesh: no command file (a mesh the node may not hold); the input replays
    std::string text = "# vgc fuzz " + target + " counterexample: " + c->signature + "\n# from " +
                       g.files.front().string() + "\n# replay: " + c->replay_fuzzer + "\n";
    text += printed != g.printed.end() ? printed->second : "# the target printed no mesh (a sanitizer finding)\n";
    write_file(cex_file, text);
  }
}

// The counterexample of a finding of a command-stream target (stream,
// differential, property_*): a command file. A finding named by clause
// replays as a certify counterexample, against the same implementation,
// with the same environment, minimized as certify shrinks. So does a crash
// of a plugin in fuzz_differential (in process it takes the fuzzer down
// unnamed): `vgc replay` runs the plugin isolated and names the clause, as
// certify would.
void write_program_counterexample(const CampaignRun& r, const CrashGroup& g, const std::string& bytes,
                                  CampaignCrash* c) {
  const fs::path cex_file = c->counterexample;
  const std::string vgc = r.o.vgc_binary.empty() ? self_exe().string() : r.o.vgc_binary;
  const std::string impl_spec = r.impl.spec();
  const CampaignOptions& o = r.o;
  const bool plugin_crash = c->clause.empty() && r.name == "differential" && !r.plugin.empty();
  const bool replayable = !c->clause.empty() || plugin_crash;
  const auto replay_line = [&] {
    return env_prefix(r.run_env) + program_command() + " replay " + shell_quote(cex_file.string()) + " --impl " +
           shell_quote(impl_spec) + replay_options(o);
  };
  const auto apply_line = [&] { return env_prefix(r.run_env) + program_command() + " apply " + shell_quote(cex_file.string()); };
  c->replay = replayable ? replay_line() : apply_line();
  std::string body;
  auto printed = g.printed.find(g.files.front());
  if (printed != g.printed.end()) body = printed->second;
  else if (r.property) body = "# the target printed no command file (a sanitizer finding): replay the input\n";
  else body = stream_to_text(bytes);
  const std::string status = status_of_finding(c->signature);
  const bool call_failure = status == "crash" || status == "timeout";
  // A wire host that crashed or hung cannot be replayed on a fresh
  // instance without the user's restart command.
  const bool wire = r.impl.live && !r.impl.live->traits().restartable;
  const bool confirmable = !call_failure || !wire || !o.restart.empty();
  if (!c->clause.empty() && !r.sign.spent() && !(call_failure && wire)) {
    // Minimized as certify shrinks, before it is written (minimize_finding.h);
    // a crash stays a crash (an exec: program crashed is restarted by the replay).
    OpenOptions open;
    if (o.call_timeout_s > 0) open.timeout_seconds = o.call_timeout_s;
    if (!o.verse_bone_form.empty()) open.verse_bone_form = o.verse_bone_form;
    const Minimized min = minimize_finding(body, c->clause, impl_spec, r.sign.wall_guard, 200, status, open);
    if (min.reproduced && min.after < min.before)
      body = fmt::format("# minimized from {} to {} commands ({} replays); the input replays the original\n",
                         min.before, min.after, min.replays) + min.text;
  }
  if (call_failure && !confirmable)
    c->confirmation = "not confirmed: the host is not restarted without --restart CMD, so the counterexample "
                      "was not replayed on a fresh instance";
  auto write_cex = [&] {
    write_file(cex_file, "# vgc fuzz " + r.s.target + " counterexample: " + c->signature + "\n# from " +
                             g.files.front().string() + "\n# replay: " + c->replay + "\n" + body);
  };
  write_cex();
  if (replayable && confirmable && fs::exists(vgc) && !r.sign.spent()) {
    // Which clause does it replay to? (`vgc replay` exits 1 naming it.)
    // For a crash or hang of a live implementation this is the
    // confirmation on a fresh instance: `vgc replay` starts a new exec:
    // process; a wire host is restarted by the user's command first.
    std::string restarted;
    if (call_failure && wire && !run_restart_command(o.restart, 60, &restarted))
      c->confirmation = "not confirmed: " + restarted;
    const std::string out = run_capture("timeout 60 env " + env_prefix(r.run_env) + shell_quote(vgc) + " replay " +
                                        shell_quote(cex_file.string()) + " --impl " + shell_quote(impl_spec) +
                                        replay_options(o) + " 2>&1; echo \"vgc-replay-exit=$?\"");
    static const std::regex named(R"(\b([A-Z][A-Z0-9]*(?:-[A-Z0-9]+)*-[0-9]+)\b)");
    std::string found;
    if (out.find("vgc-replay-exit=1") != std::string::npos)
      for (std::sregex_iterator it(out.begin(), out.end(), named), end; it != end; ++it)
        if (find_clause((*it)[1].str())) {
          if (found.empty() || (*it)[1].str() == c->clause) found = (*it)[1].str();
          if (found == c->clause) break;
        }
    c->replayed_clause = found;
    if (call_failure && c->confirmation.empty())
      c->confirmation = found == c->clause && out.find(status + " ") != std::string::npos
                            ? "confirmed: `vgc replay` on a fresh instance (" +
                                  std::string(wire ? "restarted by --restart" : "a new process") + ") shows the " +
                                  status + " again"
                            : "not confirmed: `vgc replay` on a fresh instance did not show the " + status +
                                  " (depends on the instance's history, or flaky)";
    if (plugin_crash) {
      if (!found.empty()) {
        c->clause = found;  // certify's name for the crash
        if (const Clause* cl = find_clause(c->clause)) c->level = clause_level_name(cl->level);
        c->in_baseline = r.baseline.reasons.count(c->clause) > 0;
      } else {
        c->replay = apply_line();
        write_cex();
      }
    }
  } else if (plugin_crash) {
    c->replay = apply_line();
    write_cex();
  }
}

// One finding per signature: described, its input minimized (raw bytes)
// or its program shrunk (clause findings), its counterexample written.
void write_findings(CampaignRun* r, std::map<std::string, CrashGroup>& unique) {
  std::size_t k = 0;
  for (auto& [key, g] : unique) {
    CampaignCrash c = describe_crash(*r, key, g);
    std::string bytes;
    read_file(c.input, &bytes);
    if (!shrinks_as_program(*r, c)) minimize_raw_input(r, key, g, &c, &bytes);
    ++k;
    const char* ext = r->name == "text" ? "txt" : r->mesh ? "mesh.txt" : r->name == "verse_packet" ? "packet.txt" : "vgc";
    c.counterexample = (r->cex / fmt::format("crash-{}{}.{}", k, c.clause.empty() ? "" : "-" + c.clause, ext)).string();
    if (r->name == "text" || r->name == "verse_packet" || r->mesh) write_input_counterexample(*r, g, bytes, &c);
    else write_program_counterexample(*r, g, bytes, &c);
    r->s.crashes.push_back(std::move(c));
  }
}

// The findings grouped by clause ("" last), and the count of new ones.
void group_by_clause(CampaignRun* r) {
  CampaignSummary& s = r->s;
  std::map<std::string, CampaignClause> by_clause;
  for (std::size_t i = 0; i < s.crashes.size(); ++i) {
    const CampaignCrash& c = s.crashes[i];
    CampaignClause& g = by_clause[c.clause];
    g.clause = c.clause;
    g.level = c.level;
    g.in_baseline = c.in_baseline;
    if (c.in_baseline) g.baseline_reason = r->baseline.reasons.at(c.clause);
    g.crashes.push_back(i);
    g.inputs += c.inputs;
    if (c.first_seen_s && (!g.first_seen_s || *c.first_seen_s < *g.first_seen_s)) g.first_seen_s = c.first_seen_s;
    if (!c.in_baseline) ++s.new_crashes;
  }
  for (auto& [id, g] : by_clause)
    if (!id.empty()) s.clauses.push_back(std::move(g));
  if (by_clause.count("")) s.clauses.push_back(std::move(by_clause[""]));
}

// The corpus and speed figures of the summary.
void count_corpus_and_speed(CampaignRun* r) {
  CampaignSummary& s = r->s;
  const Progress& p = r->progress;
  for (const auto& e : fs::directory_iterator(r->corpus))
    if (e.is_regular_file()) {
      ++s.corpus_files;
      s.corpus_bytes += e.file_size();
    }
  s.wall_s = std::chrono::duration<double>(clock::now() - r->t0).count();
  s.executions = p.execs + r->execs_before;
  s.exec_per_s_last = p.exec_s;
  s.cov = p.cov;
  s.ft = p.ft;
  const double grace = r->o.grace_s > 0 ? r->o.grace_s : 5;
  const double fuzz_wall = std::min(s.wall_s, r->o.time_s + grace);
  s.exec_per_s_mean = fuzz_wall > 0 ? static_cast<double>(s.executions) / fuzz_wall : 0.0;
}

// --coverage-report: the implementation's functions named
// (symbolize_functions.h), implementation_functions.md written, the ones
// never entered kept for the summary.
void write_function_report(CampaignRun* r, const CoverageTotals& t) {
  CampaignSummary& s = r->s;
  if (!t.seen) {
    s.coverage_report_note = "no report: the implementation's coverage was not seen";
    return;
  }
  if (t.functions.empty()) {
    s.coverage_report_note = "no report: the implementation has no PC table (build it with "
                             "-fsanitize-coverage=inline-8bit-counters,pc-table)";
    return;
  }
  std::string note;
  const std::vector<NamedFunction> named = symbolize_functions(t.functions, &note);
  const fs::path file = r->dir / "implementation_functions.md";
  if (!write_file(file, format_function_report(named, note))) {
    s.coverage_report_note = "cannot write " + file.string();
    return;
  }
  s.coverage_report = file.string();
  std::vector<const NamedFunction*> never;
  for (const NamedFunction& f : named)
    if (!f.entered) never.push_back(&f);
  std::sort(never.begin(), never.end(), [](const NamedFunction* a, const NamedFunction* b) { return place_before(*a, *b); });
  s.functions_never_entered_count = never.size();
  for (std::size_t i = 0; i < never.size() && i < 200; ++i)
    s.functions_never_entered.push_back(never[i]->name +
                                        (never[i]->location.empty() ? "" : " (" + never[i]->location + ")"));
  if (!note.empty()) s.coverage_report_note = note;
}

// The implementation's own coverage, from the records of the run's
// processes (coverage_record.h).
void count_implementation_coverage(CampaignRun* r) {
  CampaignSummary& s = r->s;
  if (r->impl.live_on(RouteKind::Verse)) s.impl_coverage_mode = "wire";
  if (!r->impl.live_on(RouteKind::Exec)) return;
  s.impl_coverage_mode = r->o.impl_coverage;
  if (r->o.impl_coverage == "off") return;
  const CoverageTotals t = merge_coverage_records((r->dir / "implementation_coverage").string());
  s.impl_coverage_seen = t.seen;
  s.impl_counters = t.counters;
  s.impl_counters_reached = t.reached;
  s.impl_function_entries = t.function_entries;
  s.impl_functions_entered = t.functions_entered;
  s.impl_counters_dropped = t.dropped;
  s.impl_modules = t.modules;
  // The records' clock (the epoch) on the campaign's (seconds since its start).
  const double now_epoch =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  const double start_epoch = now_epoch - std::chrono::duration<double>(clock::now() - r->t0).count();
  for (const auto& [when, n] : t.timeline) s.impl_timeline.emplace_back(std::max(0.0, when - start_epoch), n);
  if (r->o.coverage_report) write_function_report(r, t);
}

// summary.json and summary.md (each written whole or not at all: a
// temporary file, then renamed) and report.html. Returns 0, or 2.
int write_campaign_reports(CampaignRun* r) {
  const CampaignSummary& s = r->s;
  const std::string json = summary_json(s), md = summary_markdown(s);
  std::error_code ec;
  for (const auto& [file, text] : {std::pair{r->dir / "summary.json", json}, std::pair{r->dir / "summary.md", md}}) {
    fs::path tmp = file;
    tmp += ".tmp";
    if (!write_file(tmp, text)) {
      fmt::print(stderr, "vgc fuzz: cannot write {}\n", file.string());
      return 2;
    }
    fs::rename(tmp, file, ec);
  }
  // report.html: the same figures as a page, with coverage and corpus over time.
  CampaignReport page;
  page.target = s.target, page.run = s.run, page.command = s.command, page.implementation = s.implementation;
  page.seed = s.seed, page.jobs = s.jobs, page.time_s = s.time_s, page.wall_s = s.wall_s;
  page.executions = s.executions, page.exec_per_s_last = s.exec_per_s_last, page.exec_per_s_mean = s.exec_per_s_mean;
  page.coverage = s.cov, page.features = s.ft, page.corpus_files = s.corpus_files, page.corpus_bytes = s.corpus_bytes;
  page.seed_files = s.seed_files, page.crash_inputs = s.crash_inputs, page.samples = std::move(r->samples);
  if (!s.impl_coverage_mode.empty()) page.implementation_coverage = implementation_coverage_line(s);
  page.function_report = s.coverage_report;
  page.functions_never_entered = s.functions_never_entered;
  page.functions_never_entered_count = s.functions_never_entered_count;
  for (const auto& [t, n] : s.impl_timeline) {
    CampaignSample p;
    p.seconds = t;
    p.coverage = static_cast<long long>(n);
    page.implementation_samples.push_back(p);
  }
  for (const CampaignCrash& c : s.crashes) {
    CampaignFinding f;
    f.signature = c.signature, f.also = c.also, f.inputs = c.inputs, f.counterexample = c.counterexample;
    f.replay = c.replay, f.replay_fuzzer = c.replay_fuzzer;
    std::ifstream in(c.counterexample, std::ios::binary);
    f.counterexample_text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    page.findings.push_back(std::move(f));
  }
  if (std::string error; !write_campaign_html(r->dir.string(), page, &error)) fmt::print(stderr, "vgc fuzz: {}\n", error);
  if (!r->o.quiet) {
    fmt::print("{}", md);
    fmt::print("summary: {}\n", (r->dir / "summary.json").string());
  }
  return 0;
}

}  // namespace

int run_campaign(const CampaignOptions& o, CampaignSummary* out) {
  CampaignRun r(o);
  if (int rc = check_campaign_options(&r)) return rc;
  if (int rc = claim_run_directory(&r)) return rc;
  run_libfuzzer(&r);
  std::map<std::string, CrashGroup> unique = sign_crash_inputs(&r);
  write_findings(&r, unique);
  group_by_clause(&r);
  count_corpus_and_speed(&r);
  count_implementation_coverage(&r);
  if (int rc = write_campaign_reports(&r)) return rc;
  const bool ran_nothing = r.progress.execs == 0 && r.s.crash_inputs == 0;
  if (out) *out = r.s;
  if (ran_nothing) {
    fmt::print(stderr, "vgc fuzz: libFuzzer ran no inputs (exit {}); see {}\n", r.fuzzed.exit,
               (r.dir / "fuzzer.log").string());
    return 2;
  }
  return r.s.new_crashes == 0 ? 0 : 1;
}

std::string summary_json(const CampaignSummary& s) {
  using nlohmann::json;
  auto opt = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
  json crashes = json::array();
  for (const CampaignCrash& c : s.crashes)
    crashes.push_back({{"signature", c.signature},
                       {"also", c.also},
                       {"dedup_key", c.dedup_key},
                       {"clause", c.clause},
                       {"level", c.level},
                       {"in_baseline", c.in_baseline},
                       {"inputs", c.inputs},
                       {"input", c.input},
                       {"counterexample", c.counterexample},
                       {"replay", c.replay},
                       {"replay_fuzzer", c.replay_fuzzer},
                       {"replayed_clause", c.replayed_clause ? json(*c.replayed_clause) : json(nullptr)},
                       {"confirmation", c.confirmation},
                       {"first_seen_s", opt(c.first_seen_s)},
                       {"minimized", c.minimized_input.empty()
                                         ? json(nullptr)
                                         : json{{"input", c.minimized_input},
                                                {"from_bytes", c.input_bytes},
                                                {"to_bytes", c.minimized_bytes},
                                                {"by", "libFuzzer -minimize_crash_internal_step"},
                                                {"stopped", c.minimize_note}}},
                       {"minimize_note", c.minimize_note}});
  json clauses = json::array();
  for (const CampaignClause& g : s.clauses)
    clauses.push_back({{"clause", g.clause},
                       {"level", g.level},
                       {"in_baseline", g.in_baseline},
                       {"baseline_reason", g.baseline_reason},
                       {"crashes", g.crashes},
                       {"inputs", g.inputs},
                       {"first_seen_s", opt(g.first_seen_s)}});
  json j = {{"target", s.target},
            {"run", s.run},
            {"run_dir", s.run_dir},
            {"binary", s.binary},
            {"implementation", s.implementation},
            {"environment", s.environment},
            {"seed", s.seed},
            {"jobs", s.jobs},
            {"time_s", s.time_s},
            {"wall_s", s.wall_s},
            {"cpu_s", s.cpu_s},
            {"killed_at_deadline", s.killed_at_deadline},
            {"cpu_budget_spent", s.cpu_budget_spent},
            {"empty_corpus", s.empty_corpus},
            {"stop_at_first", s.stop_at_first},
            {"baseline", s.baseline},
            {"executions", s.executions},
            {"exec_per_s_last", s.exec_per_s_last},
            {"exec_per_s_mean", s.exec_per_s_mean},
            {"coverage", {{"cov", s.cov}, {"ft", s.ft}}},
            {"implementation_coverage",
             s.impl_coverage_mode.empty()
                 ? json(nullptr)
                 : json{{"mode", s.impl_coverage_mode},
                        {"seen", s.impl_coverage_seen},
                        {"counters", s.impl_counters},
                        {"counters_reached", s.impl_counters_reached},
                        {"function_entries", s.impl_function_entries},
                        {"functions_entered", s.impl_functions_entered},
                        {"counters_dropped", s.impl_counters_dropped},
                        {"modules", s.impl_modules},
                        {"over_time", s.impl_timeline},
                        {"coverage_report", s.coverage_report.empty() ? json(nullptr) : json(s.coverage_report)},
                        {"coverage_report_note", s.coverage_report_note},
                        {"functions_never_entered_count", s.functions_never_entered_count},
                        {"functions_never_entered", s.functions_never_entered}}},
            {"corpus", {{"files", s.corpus_files}, {"bytes", s.corpus_bytes}, {"seed_files", s.seed_files}}},
            {"crash_inputs", s.crash_inputs},
            {"crash_inputs_signed", s.crash_inputs_signed},
            {"signing_stopped_by", s.signing_stopped},
            {"time_to_first_finding_s", opt(s.time_to_first_finding_s)},
            {"new_crashes", s.new_crashes},
            {"crashes", crashes},
            {"clauses", clauses},
            {"libfuzzer_exit", s.libfuzzer_exit},
            {"command", s.command}};
  // Invalid UTF-8 from an implementation (a crash signature, a message)
  // becomes U+FFFD instead of an exception that loses the summary.
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string implementation_coverage_line(const CampaignSummary& s) {
  if (s.impl_coverage_mode == "off") return "off (--impl-coverage off)";
  if (s.impl_coverage_mode == "wire")
    return "not seen: a host on the Verse wire is not yet given the shared memory (exec: only); libFuzzer was "
           "guided by vgc's own code only";
  if (!s.impl_coverage_seen)
    return "not seen: the implementation was not built with -fsanitize-coverage=inline-8bit-counters and "
           "-lvgc_coverage (docs/fuzzing.md \"Coverage of the implementation\"); libFuzzer was guided by vgc's "
           "own code only";
  std::string line = fmt::format("{} of {} counters reached ({:.1f} %)", s.impl_counters_reached, s.impl_counters,
                                 s.impl_counters ? 100.0 * s.impl_counters_reached / s.impl_counters : 0.0);
  if (s.impl_function_entries)
    line += fmt::format(", {} of {} functions entered", s.impl_functions_entered, s.impl_function_entries);
  if (s.impl_counters_dropped) line += fmt::format(", {} counters not seen (past the region's size)", s.impl_counters_dropped);
  line += s.impl_coverage_mode == "guide"          ? "; guiding libFuzzer by edges"
          : s.impl_coverage_mode == "guide-counts" ? "; guiding libFuzzer by edges and hit counts"
                                                   : "; counted only (--impl-coverage observe)";
  return line;
}

std::string summary_markdown(const CampaignSummary& s) {
  auto secs = [](const std::optional<double>& v) { return v ? fmt::format("{:.1f} s", *v) : std::string("-"); };
  std::string md = fmt::format(
      "# vgc fuzz {} — {}\n\n"
      "| | |\n|---|---|\n| implementation | {} |\n| seed, jobs, time | {}, {}, {} s (wall {:.0f} s{}) |\n"
      "| CPU | {:.0f} s |\n"
      "| executions | {} |\n| exec/s | {:.0f} mean, {} last reported |\n| coverage | cov {}, ft {} |\n"
      "| corpus | {} files, {} bytes ({} seeds{}) |\n| crash inputs | {} ({} re-run and signed{}; {} unique, {} new) |\n"
      "| time to first finding | {} |\n",
      s.target, s.run, s.implementation, s.seed, s.jobs, s.time_s, s.wall_s,
      s.killed_at_deadline ? "; libFuzzer overran and was killed"
      : s.cpu_budget_spent ? "; stopped at its CPU budget"
                           : "",
      s.cpu_s, s.executions, s.exec_per_s_mean,
      s.exec_per_s_last, s.cov, s.ft, s.corpus_files, s.corpus_bytes, s.seed_files,
      s.empty_corpus ? ", started empty" : "", s.crash_inputs, s.crash_inputs_signed,
      s.signing_stopped.empty() ? "" : ", stopped by " + s.signing_stopped, s.crashes.size(),
      s.new_crashes, secs(s.time_to_first_finding_s));
  if (!s.impl_coverage_mode.empty()) md += "| implementation coverage | " + implementation_coverage_line(s) + " |\n";
  if (!s.coverage_report.empty())
    md += fmt::format("| functions never entered | {} (every function, named: `{}`) |\n",
                      s.functions_never_entered_count, s.coverage_report);
  else if (!s.coverage_report_note.empty())
    md += "| functions never entered | " + s.coverage_report_note + " |\n";
  if (!s.baseline.empty()) md += fmt::format("| baseline | {} |\n", s.baseline);
  md += fmt::format("\nCommand: `{}`\n\n", s.command);
  if (s.crashes.empty()) return escape_unprintable(md);
  md += "## Findings by clause\n\n";
  for (const CampaignClause& g : s.clauses) {
    md += fmt::format("### {}{}{} — {} crash(es), {} input(s), first after {}\n\n",
                      g.clause.empty() ? "(no clause: sanitizer or oracle finding)" : g.clause,
                      g.level.empty() ? "" : " (" + g.level + ")",
                      g.in_baseline ? " [baseline: " + g.baseline_reason + "]" : "", g.crashes.size(), g.inputs,
                      secs(g.first_seen_s));
    for (std::size_t i : g.crashes) {
      const CampaignCrash& c = s.crashes[i];
      md += fmt::format("- **{}** ({} inputs)\n", c.signature, c.inputs);
      for (const auto& a : c.also) md += fmt::format("  - also: {}\n", a);
      md += fmt::format("  - counterexample: `{}`\n  - replay: `{}`\n  - replay the input: `{}`\n", c.counterexample,
                        c.replay, c.replay_fuzzer);
      if (!c.minimized_input.empty())
        md += fmt::format("  - input minimized from {} to {} bytes (libFuzzer's minimizing steps; {}): `{}`\n",
                          c.input_bytes, c.minimized_bytes, c.minimize_note, c.minimized_input);
      else if (!c.minimize_note.empty())
        md += fmt::format("  - input not minimized: {}\n", c.minimize_note);
      if (!c.confirmation.empty()) md += fmt::format("  - {}\n", c.confirmation);
      if (c.replayed_clause)
        md += fmt::format("  - replayed: {}\n", c.replayed_clause->empty() ? "no clause named (did not reproduce)"
                                                 : *c.replayed_clause == c.clause ? "same clause"
                                                                                  : "names " + *c.replayed_clause);
    }
    md += "\n";
  }
  return escape_unprintable(md);  // signatures and messages are the implementation's bytes
}

// The run directories' time stamp (UTC, to the second).
std::string utc_stamp() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%dT%H%M%SZ", &tm);
  return buf;
}

}  // namespace vgc::fuzz
