// cmd_fuzz.cpp — `vgc fuzz`: run a libFuzzer campaign on one fuzz target and
// report it; convert between binary streams and command files.
//
//   vgc fuzz TARGET [--time S] [--jobs N] [--impl plugin:PATH] [--seed N]
//   vgc fuzz --to-text STREAM          binary stream -> command file (stdout)
//   vgc fuzz --to-binary FILE -o OUT   command file -> binary stream
//
// Spec: docs/fuzzing.md. TARGET is stream, text, differential, verse_packet,
// mesh_manifold, mesh_subdivision or property_<group> (fuzz_ prefix
// optional). The libFuzzer binaries come from the clang fuzz build
// (default: build-fuzz next to this program's build directory, or
// $VGC_FUZZ_BUILD_DIR); the ./vgc script configures and builds it before
// running `vgc fuzz`. A run lives in reports/fuzz/<target>/<run>/: corpus/
// (seeded from corpora/fuzz/<target>/), crashes/, counterexamples/,
// fuzzer.log, summary.json and summary.md.
//
// Exit codes: 0 the campaign ran and found nothing; 1 it found crashes (each
// deduplicated one has a counterexample and a replay command); 2 usage or
// infrastructure error (no fuzz build, unreadable file).
#include <fmt/core.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "command_binary.h"
#include "command_text.h"
#include "read_file.h"
#include "subcommand.h"

namespace vgc::cli {
namespace {

namespace fs = std::filesystem;

struct FuzzOptions {
  std::string target;
  double time_s = 60;
  int jobs = 1;
  std::string impl;
  unsigned seed = 1;
  std::size_t max_len = 1024;
  std::string fuzz_build;
  std::string source_dir;
  std::string to_text;
  std::string to_binary;
  std::string output;
};

bool write_file(const fs::path& p, const std::string& s) {
  std::ofstream out(p, std::ios::binary);
  out << s;
  return static_cast<bool>(out);
}

// A binary stream as a command file: the commands that decode, then a
// comment naming what follows them, if anything.
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

fs::path self_exe() {
  std::error_code ec;
  fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path{} : p;
}

// The build directory this program was built in (…/build/cli/vgc).
fs::path own_build_dir() { return self_exe().parent_path().parent_path(); }

fs::path source_dir(const FuzzOptions& o) {
  if (!o.source_dir.empty()) return o.source_dir;
  if (const char* e = std::getenv("VGC_SOURCE_DIR"); e && *e) return e;
  std::string cache;
  if (read_file(own_build_dir() / "CMakeCache.txt", &cache)) {
    std::smatch m;
    if (std::regex_search(cache, m, std::regex("CMAKE_HOME_DIRECTORY:INTERNAL=([^\n]*)"))) return m[1].str();
  }
  return fs::current_path();
}

fs::path fuzz_build_dir(const FuzzOptions& o) {
  if (!o.fuzz_build.empty()) return o.fuzz_build;
  if (const char* e = std::getenv("VGC_FUZZ_BUILD_DIR"); e && *e) return e;
  return own_build_dir().parent_path() / "build-fuzz";
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string utc_stamp() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%dT%H%M%SZ", &tm);
  return buf;
}

struct Progress {
  long long execs = 0;
  long long exec_s = 0;
  long long cov = 0;
  long long ft = 0;
  long long corp = 0;
  long long crashes = 0;
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

// Runs argv with env additions, stdout+stderr into `on_line` line by line.
int run_streaming(const std::vector<std::string>& argv, const std::vector<std::string>& env_add,
                  const std::function<void(const std::string&)>& on_line) {
  int fds[2];
  if (pipe(fds) != 0) return -1;
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    dup2(fds[1], 1);
    dup2(fds[1], 2);
    close(fds[0]);
    close(fds[1]);
    for (const std::string& kv : env_add) putenv(const_cast<char*>(kv.c_str()));
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    std::perror("execv");
    _exit(127);
  }
  close(fds[1]);
  FILE* in = fdopen(fds[0], "r");
  char* buf = nullptr;
  std::size_t cap = 0;
  ssize_t n;
  while ((n = getline(&buf, &cap, in)) > 0) {
    std::string line(buf, static_cast<std::size_t>(n));
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    on_line(line);
  }
  std::free(buf);
  std::fclose(in);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
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

// Digits folded to N, except inside clause ids (BONE-FOREST-1), which stay
// exact: "bones.stateful: BONE-FOREST-1 (MUST, fail): bone 3" becomes
// "bones.stateful: BONE-FOREST-1 (MUST, fail): bone N".
std::string fold_digits_keep_clauses(const std::string& s) {
  static const std::regex digits(R"(\d+)");
  static const std::regex clause(R"(\b[A-Z][A-Z0-9]*(-[A-Z0-9]+)*-[0-9]+\b)");
  std::string out;
  auto from = s.cbegin();
  for (std::sregex_iterator it(s.begin(), s.end(), clause), end; it != end; ++it) {
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
      return {std::regex_replace(s, digits, "N"), fold_digits_keep_clauses(s)};
    }
    if (auto at = line.find("runtime error: "); at != std::string::npos) {
      // "file:line:col: runtime error: what"
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

int run_campaign(const FuzzOptions& o) {
  const std::string name = normalize_target(o.target);
  // property_<group>: a conformance property as a target (fuzz/property_target.cpp).
  const bool property = name.rfind("property_", 0) == 0;
  static const char* const kGroups[] = {"layers", "polygons", "creases", "bones", "values", "ids", "commands"};
  bool known_group = false;
  for (const char* g : kGroups) known_group = known_group || name == std::string("property_") + g;
  // mesh_*: a mesh (fuzz/mesh_bytes.h) into the derived-geometry oracles.
  const bool mesh = name == "mesh_manifold" || name == "mesh_subdivision";
  if (name != "stream" && name != "text" && name != "differential" && name != "verse_packet" && !mesh &&
      !known_group) {
    fmt::print(stderr,
               "vgc fuzz: unknown target '{}': expected stream, text, differential, verse_packet, mesh_manifold, "
               "mesh_subdivision or property_<group> "
               "(layers, polygons, creases, bones, values, ids, commands)\n",
               o.target);
    return 2;
  }
  const std::string target = "fuzz_" + name;
  const fs::path src = source_dir(o);
  const fs::path fbuild = fuzz_build_dir(o);
  const fs::path binary = fbuild / "fuzz" / target;
  if (!fs::exists(binary)) {
    fmt::print(stderr,
               "vgc fuzz: no libFuzzer binary {}\n"
               "  `./vgc fuzz ...` builds it; by hand: CC=clang CXX=clang++ cmake -S {} -B {} -DVGC_FUZZ=ON"
               " && cmake --build {} --target {}\n",
               binary.string(), src.string(), fbuild.string(), fbuild.string(), target);
    return 2;
  }
  std::vector<std::string> env_add;
  std::string plugin;
  if (!o.impl.empty() && o.impl != "reference") {
    if ((name != "differential" && !property) || o.impl.rfind("plugin:", 0) != 0) {
      fmt::print(stderr,
                 "vgc fuzz: --impl takes plugin:PATH (or reference), for the differential and property targets only\n");
      return 2;
    }
    plugin = fs::absolute(o.impl.substr(7)).string();
    if (!fs::exists(plugin)) {
      fmt::print(stderr, "vgc fuzz: no such plugin {}\n", plugin);
      return 2;
    }
    env_add.push_back("VGC_FUZZ_PLUGIN=" + plugin);
  }

  const std::string run = utc_stamp() + "-seed" + std::to_string(o.seed);
  const fs::path dir = src / "reports" / "fuzz" / target / run;
  const fs::path corpus = dir / "corpus", crashes = dir / "crashes", cex = dir / "counterexamples";
  std::error_code ec;
  fs::create_directories(corpus, ec);
  fs::create_directories(crashes, ec);
  fs::create_directories(cex, ec);
  if (ec) {
    fmt::print(stderr, "vgc fuzz: cannot create {}: {}\n", dir.string(), ec.message());
    return 2;
  }
  std::size_t seeds = 0;
  if (fs::is_directory(src / "corpora" / "fuzz" / target))
    for (const auto& e : fs::directory_iterator(src / "corpora" / "fuzz" / target))
      if (e.is_regular_file()) {
        fs::copy_file(e.path(), corpus / e.path().filename(), fs::copy_options::overwrite_existing, ec);
        ++seeds;
      }
  const fs::path dict = src / "corpora" / "fuzz" / (target + ".dict");

  std::vector<std::string> argv = {binary.string(),
                                   "-fork=" + std::to_string(std::max(1, o.jobs)),
                                   "-ignore_crashes=1",
                                   "-max_total_time=" + std::to_string(static_cast<long long>(o.time_s)),
                                   "-seed=" + std::to_string(o.seed),
                                   "-artifact_prefix=" + crashes.string() + "/",
                                   "-print_final_stats=1",
                                   "-max_len=" + std::to_string(o.max_len)};
  if (fs::exists(dict)) argv.push_back("-dict=" + dict.string());
  argv.push_back(corpus.string());
  std::string cmdline;
  for (const auto& a : argv) cmdline += (cmdline.empty() ? "" : " ") + shell_quote(a);
  if (!plugin.empty()) cmdline = "VGC_FUZZ_PLUGIN=" + shell_quote(plugin) + " " + cmdline;
  fmt::print(stderr, "vgc fuzz: {} for {} s, {} job(s), seed {}, {} seed inputs\n  run: {}\n  {}\n", target,
             o.time_s, o.jobs, o.seed, seeds, dir.string(), cmdline);

  std::ofstream log(dir / "fuzzer.log");
  Progress p;
  const bool tty = isatty(2);
  const auto t0 = std::chrono::steady_clock::now();
  auto last_print = t0 - std::chrono::seconds(60);
  const int rc = run_streaming(argv, env_add, [&](const std::string& line) {
    log << line << '\n';
    if (!parse_progress(line, &p)) return;
    const auto now = std::chrono::steady_clock::now();
    const double t = std::chrono::duration<double>(now - t0).count();
    const std::string status =
        fmt::format("[{:5.0f}/{:.0f} s] execs {}  exec/s {}  cov {}  ft {}  corpus {}  crashes {}", t, o.time_s,
                    p.execs, p.exec_s, p.cov, p.ft, p.corp, p.crashes);
    if (tty) {
      fmt::print(stderr, "\r{:<100}", status);
    } else if (now - last_print >= std::chrono::seconds(10)) {
      fmt::print(stderr, "{}\n", status);
      last_print = now;
    }
  });
  log.close();
  if (tty) fmt::print(stderr, "\n");
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // Crashes: re-run each saved input alone, sign it, keep the smallest per signature.
  struct Crash {
    std::string signature;                 // the dedup key (digits folded)
    std::map<fs::path, std::string> shown;  // per input: its signature with exact clause ids
    std::vector<fs::path> files;
    std::map<fs::path, std::string> printed;  // the target's own counterexample block, per input
  };
  std::map<std::string, Crash> unique;
  std::size_t crash_files = 0;
  std::vector<fs::path> saved;
  for (const auto& e : fs::directory_iterator(crashes))
    if (e.is_regular_file()) saved.push_back(e.path());
  std::sort(saved.begin(), saved.end());
  for (const fs::path& f : saved) {
    ++crash_files;
    std::string env;
    if (!plugin.empty()) env = "VGC_FUZZ_PLUGIN=" + shell_quote(plugin) + " ";
    const std::string out =
        run_capture("timeout 60 env " + env + shell_quote(binary.string()) + " " + shell_quote(f.string()) + " 2>&1");
    const CrashSignature sig = crash_signature(out);
    Crash& c = unique[sig.key];
    c.signature = sig.key;
    c.shown[f] = sig.shown;
    c.files.push_back(f);
    // A target finding prints the commands up to the failing one (finding.h),
    // a mesh target the mesh (mesh_bytes.h).
    const std::string open = mesh ? "----8<---- mesh.txt\n" : "----8<---- counterexample.vgc\n";
    if (auto a = out.find(open); a != std::string::npos) {
      if (auto b = out.find("----8<----\n", a + open.size()); b != std::string::npos)
        c.printed[f] = out.substr(a + open.size(), b - a - open.size());
    }
  }
  nlohmann::json crashes_json = nlohmann::json::array();
  std::size_t k = 0;
  for (auto& [sig, c] : unique) {
    std::sort(c.files.begin(), c.files.end(),
              [](const fs::path& a, const fs::path& b) { return fs::file_size(a) < fs::file_size(b); });
    const fs::path& rep = c.files.front();
    // Shown: the smallest input's signature, then any other exact form in
    // the group (BONE-FOREST-1 and BONE-FOREST-2 share a key).
    const std::string shown = c.shown[rep];
    std::vector<std::string> also;
    for (const auto& [file, text] : c.shown)
      if (text != shown && std::find(also.begin(), also.end(), text) == also.end()) also.push_back(text);
    std::string bytes;
    read_file(rep, &bytes);
    ++k;
    const fs::path cex_file = cex / fmt::format("crash-{}.{}", k, name == "text" ? "txt" : mesh ? "mesh.txt" : "vgc");
    std::string replay_fuzzer = (plugin.empty() ? "" : "VGC_FUZZ_PLUGIN=" + shell_quote(plugin) + " ") +
                                shell_quote(binary.string()) + " " + shell_quote(rep.string());
    std::string replay;
    if (name == "text") {
      write_file(cex_file, bytes);  // the input is text already
      replay = replay_fuzzer;
    } else if (mesh) {  // no command file: a mesh the node may not hold; the input replays
      std::string text = "# vgc fuzz " + target + " counterexample: " + sig + "\n# from " + rep.string() + "\n";
      auto printed = c.printed.find(rep);
      text += printed != c.printed.end() ? printed->second : "# the target printed no mesh (a sanitizer finding)\n";
      write_file(cex_file, text);
      replay = replay_fuzzer;
    } else {
      std::string text = "# vgc fuzz " + target + " counterexample: " + shown + "\n# from " + rep.string() +
                         "\n# replay: vgc apply " + cex_file.string() + "\n";
      auto printed = c.printed.find(rep);
      if (printed != c.printed.end()) text += printed->second;
      else if (property) text += "# the target printed no command file (a sanitizer finding): replay the input\n";
      else text += stream_to_text(bytes);
      write_file(cex_file, text);
      // A property finding replays as a certify counterexample, against the same implementation.
      replay = property ? "vgc replay " + shell_quote(cex_file.string()) + " --impl " +
                              shell_quote(plugin.empty() ? std::string("reference") : "plugin:" + plugin)
                        : "vgc apply " + shell_quote(cex_file.string());
    }
    crashes_json.push_back({{"signature", shown},
                            {"also", also},
                            {"dedup_key", sig},
                            {"inputs", c.files.size()},
                            {"input", rep.string()},
                            {"counterexample", cex_file.string()},
                            {"replay", replay},
                            {"replay_fuzzer", replay_fuzzer}});
  }
  std::size_t corpus_files = 0, corpus_bytes = 0;
  for (const auto& e : fs::directory_iterator(corpus))
    if (e.is_regular_file()) {
      ++corpus_files;
      corpus_bytes += e.file_size();
    }
  nlohmann::json summary = {{"target", target},
                            {"run", run},
                            {"run_dir", dir.string()},
                            {"binary", binary.string()},
                            {"implementation", plugin.empty() ? "reference" : "plugin:" + plugin},
                            {"seed", o.seed},
                            {"jobs", o.jobs},
                            {"time_s", o.time_s},
                            {"wall_s", wall},
                            {"executions", p.execs},
                            {"exec_per_s_last", p.exec_s},
                            {"exec_per_s_mean", wall > 0 ? static_cast<double>(p.execs) / wall : 0.0},
                            {"coverage", {{"cov", p.cov}, {"ft", p.ft}}},
                            {"corpus", {{"files", corpus_files}, {"bytes", corpus_bytes}, {"seed_files", seeds}}},
                            {"crash_inputs", crash_files},
                            {"crashes", crashes_json},
                            {"libfuzzer_exit", rc},
                            {"command", cmdline}};
  write_file(dir / "summary.json", summary.dump(2) + "\n");

  std::string md = fmt::format(
      "# vgc fuzz {} — {}\n\n"
      "| | |\n|---|---|\n| implementation | {} |\n| seed, jobs, time | {}, {}, {} s (wall {:.0f} s) |\n"
      "| executions | {} |\n| exec/s | {:.0f} mean, {} last reported |\n| coverage | cov {}, ft {} |\n"
      "| corpus | {} files, {} bytes ({} seeds) |\n| crash inputs | {} ({} unique) |\n\n"
      "Command: `{}`\n\n",
      target, run, plugin.empty() ? "reference" : "plugin:" + plugin, o.seed, o.jobs, o.time_s, wall, p.execs,
      summary["exec_per_s_mean"].get<double>(), p.exec_s, p.cov, p.ft, corpus_files, corpus_bytes, seeds,
      crash_files, unique.size(), cmdline);
  if (!unique.empty()) {
    md += "## Crashes\n\n";
    for (const auto& c : crashes_json) {
      md += fmt::format("- **{}** ({} inputs)\n", c["signature"].get<std::string>(), c["inputs"].get<std::size_t>());
      for (const auto& a : c["also"]) md += fmt::format("  - also: {}\n", a.get<std::string>());
      md += fmt::format("  - counterexample: `{}`\n  - replay: `{}`\n  - replay the input: `{}`\n",
                        c["counterexample"].get<std::string>(), c["replay"].get<std::string>(),
                        c["replay_fuzzer"].get<std::string>());
    }
  }
  write_file(dir / "summary.md", md);
  fmt::print("{}", md);
  fmt::print("summary: {}\n", (dir / "summary.json").string());
  if (p.execs == 0 && crash_files == 0) {
    fmt::print(stderr, "vgc fuzz: libFuzzer ran no inputs (exit {}); see {}\n", rc, (dir / "fuzzer.log").string());
    return 2;
  }
  return unique.empty() ? 0 : 1;
}

int run_fuzz(const FuzzOptions& o) {
  if (!o.to_text.empty()) {
    std::string bytes;
    if (!read_file(o.to_text, &bytes)) {
      fmt::print(stderr, "vgc fuzz: cannot read {}\n", o.to_text);
      return 2;
    }
    const std::string text = stream_to_text(bytes);
    if (o.output.empty()) {
      fmt::print("{}", text);
    } else if (!write_file(o.output, text)) {
      fmt::print(stderr, "vgc fuzz: cannot write {}\n", o.output);
      return 2;
    }
    return 0;
  }
  if (!o.to_binary.empty()) {
    std::string text;
    if (!read_file(o.to_binary, &text)) {
      fmt::print(stderr, "vgc fuzz: cannot read {}\n", o.to_binary);
      return 2;
    }
    std::vector<Command> cs;
    TextError e;
    if (!parse_commands(text, &cs, &e)) {
      fmt::print(stderr, "{}:{}:{}: error: {}\n", o.to_binary, e.line, e.column, e.message);
      return 2;
    }
    std::string bytes;
    for (const Command& c : cs)
      if (!encode_command(c, &bytes)) {
        fmt::print(stderr, "vgc fuzz: a name is too long to encode: {}\n", print_command(c));
        return 2;
      }
    if (o.output.empty()) {
      fmt::print(stderr, "vgc fuzz: --to-binary needs -o OUT\n");
      return 2;
    }
    return write_file(o.output, bytes) ? 0 : 2;
  }
  if (o.target.empty()) {
    fmt::print(stderr, "vgc fuzz: name a target (stream, text, differential, verse_packet, mesh_manifold, mesh_subdivision, property_<group>) or use --to-text / --to-binary\n");
    return 2;
  }
  return run_campaign(o);
}

void add_fuzz(CLI::App& app, int* exit_code) {
  auto opts = std::make_shared<FuzzOptions>();
  CLI::App* sub = app.add_subcommand("fuzz", "Run a libFuzzer campaign on a fuzz target, or convert fuzz inputs");
  sub->add_option("target", opts->target, "stream, text, differential, verse_packet, mesh_manifold, mesh_subdivision or property_<group>");
  sub->add_option("--time", opts->time_s, "Campaign length in seconds (default 60)");
  sub->add_option("--jobs", opts->jobs, "Parallel fuzzing jobs (libFuzzer -fork=N, default 1)");
  sub->add_option("--impl", opts->impl, "differential: the implementation under test, plugin:PATH");
  sub->add_option("--seed", opts->seed, "libFuzzer seed (default 1)");
  sub->add_option("--max-len", opts->max_len, "Longest input in bytes (libFuzzer -max_len, default 1024)");
  sub->add_option("--fuzz-build", opts->fuzz_build, "The clang -DVGC_FUZZ=ON build directory");
  sub->add_option("--source-dir", opts->source_dir, "The vgc source tree (corpora/, reports/)");
  sub->add_option("--to-text", opts->to_text, "Print the binary stream FILE as a command file");
  sub->add_option("--to-binary", opts->to_binary, "Encode the command file FILE as a binary stream (-o OUT)");
  sub->add_option("-o,--output", opts->output, "Output file of --to-text / --to-binary");
  sub->callback([opts, exit_code] { *exit_code = run_fuzz(*opts); });
}

const Subcommand kFuzz{add_fuzz};

}  // namespace

}  // namespace vgc::cli
