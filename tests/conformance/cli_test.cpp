// cli_test.cpp — `vgc certify`, `vgc replay`, `vgc clauses` and `vgc apply`
// end to end: the real binary (VGC_BINARY) through a shell, in a temporary
// directory, checked by exit code and by the files and lines it writes. The
// three routes (in process, exec, plugin) certify the reference; a seeded
// fault (libvgc_fault_plugin.so behind `vgc serve`) is rejected naming its
// clause, replays, and passes with a baseline.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "clause.h"
#include "command_text.h"
#include "exec_implementation.h"  // shell_quote
#include "faulty_node.h"
#include "program_text.h"
#include "property.h"

namespace vgc {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Result {
  int exit_code = -1;
  std::string out, err;
};

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("vgc_cli_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    if (!HasFailure()) fs::remove_all(dir_, ec);  // kept for a look when something failed
  }

  // Runs `env vgc args` in the temporary directory.
  Result vgc(const std::string& args, const std::string& env = "") {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = "cd " + shell_quote(dir_.string()) + " && " + env + (env.empty() ? "" : " ") +
                                shell_quote(VGC_BINARY) + " " + args + " >" + shell_quote(out.string()) + " 2>" +
                                shell_quote(err.string()) + " </dev/null";
    const int status = std::system(command.c_str());
    Result r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    r.out = read(out);
    r.err = read(err);
    last_command_ = command;
    return r;
  }
  std::string context(const Result& r) const {
    return "command: " + last_command_ + "\nstdout:\n" + r.out + "\nstderr:\n" + r.err;
  }
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

  fs::path dir_;
  std::string last_command_;
};

const std::string kFast = " --quiet --cases 30 --max-size 30 --seed 3";

std::string serve(const std::string& impl = "") {
  return std::string(VGC_BINARY) + " serve" + (impl.empty() ? "" : " --impl " + impl);
}

// Runs `command` (sh -c) with a pseudo-terminal as its stdin, stdout and
// stderr; returns everything it wrote there and sets *exit_code.
std::string on_a_terminal(const std::string& command, int* exit_code) {
  int master = -1;
  const pid_t pid = forkpty(&master, nullptr, nullptr, nullptr);
  if (pid < 0) return "forkpty failed";
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  std::string screen;
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(master, buf, sizeof buf);
    if (n <= 0) break;  // EIO once the child has exited and the pty is closed
    screen.append(buf, static_cast<std::size_t>(n));
  }
  ::close(master);
  int status = 0;
  waitpid(pid, &status, 0);
  *exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return screen;
}

// The status lines drawn in place (progress_line.h): each is "\r\033[K"
// then the text, ending in its elapsed time ("  12.3 s"); a bare "\r\033[K"
// clears the line and is not counted.
std::vector<std::string> redrawn_lines(const std::string& screen) {
  const std::string redraw = "\r\033[K";
  const std::regex elapsed("  [0-9]+\\.[0-9] s$");
  std::vector<std::string> lines;
  for (std::size_t at = screen.find(redraw); at != std::string::npos; at = screen.find(redraw, at + 1)) {
    const std::size_t from = at + redraw.size();
    const std::string line = screen.substr(from, screen.find_first_of("\r\n", from) - from);
    if (std::regex_search(line, elapsed)) lines.push_back(line);
  }
  return lines;
}

double last_elapsed(const std::string& line) {
  std::smatch m;
  return std::regex_search(line, m, std::regex("  ([0-9]+\\.[0-9]) s$")) ? std::stod(m[1]) : 0;
}

void expect_report_files(const fs::path& reports, const std::string& verdict) {
  const fs::path latest = reports / "latest";
  ASSERT_TRUE(fs::is_symlink(latest)) << latest;
  for (const char* f : {"report.json", "junit.xml", "summary.md"})
    EXPECT_TRUE(fs::is_regular_file(latest / f)) << f;
  const auto j = nlohmann::json::parse(read(latest / "report.json"));
  EXPECT_EQ(j.at("verdict"), verdict);
  EXPECT_EQ(j.at("seed"), 3);
  // The cases really ran (a route that answered nothing would not get here with 30).
  // (Properties over derived geometry may run fewer cases of their own.)
  ASSERT_FALSE(j.at("properties").empty());
  int full = 0;
  for (const auto& p : j.at("properties")) {
    if (p.at("status") == "pass") {
      EXPECT_GE(p.at("cases").get<int>(), 1) << p.dump();
    }
    full += p.at("cases") == 30;
  }
  // The seven command properties run all 30 cases unless one found a failure.
  EXPECT_GE(full, verdict == "conformant" ? 7 : 1) << "the command properties did not run their 30 cases";
}

TEST_F(Cli, CertifyTheReferenceInProcess) {
  const Result r = vgc("certify --impl reference --reports rep" + kFast);
  ASSERT_EQ(r.exit_code, 0) << context(r);
  expect_report_files(dir_ / "rep", "conformant");
  EXPECT_NE(r.out.find("conformant"), std::string::npos) << context(r);
  const auto j = nlohmann::json::parse(read(dir_ / "rep" / "latest" / "report.json"));
  EXPECT_EQ(j.at("clauses").size(), clause_catalog().size());
}

// Without --quiet, in a log (stderr not a terminal): one line per property
// that ran, as it finishes, with its status and cases.
TEST_F(Cli, CertifyLogsOneLinePerProperty) {
  const Result r = vgc("certify --impl reference --reports rep --cases 30 --max-size 30 --seed 3");
  ASSERT_EQ(r.exit_code, 0) << context(r);
  for (const auto& p : property_catalog()) {
    const std::regex line("\\[[0-9]+/[0-9]+\\] " + std::string(p.id) + " +pass +[0-9]+/[0-9]+ cases \\([0-9]+ judged, 0 set aside\\)");
    EXPECT_TRUE(std::regex_search(r.err, line)) << p.id << " has no line in\n" << r.err;
  }
  EXPECT_EQ(r.err.find("\033["), std::string::npos) << "terminal control codes in a log";
  // One status line at the start, the per-property lines, and between them
  // status lines at most every 10 s in a log: a loaded machine makes the run
  // longer, never the log denser (the bound follows the run's own seconds).
  std::istringstream lines(r.err);
  std::string l;
  int bracketed = 0;
  while (std::getline(lines, l)) bracketed += l.rfind("[", 0) == 0;
  const auto j = nlohmann::json::parse(read(dir_ / "rep" / "latest" / "report.json"));
  const int status_lines = 1 + static_cast<int>(j.at("seconds").get<double>() / 10);
  EXPECT_LE(bracketed, static_cast<int>(property_catalog().size()) + status_lines) << r.err;
}

// On a terminal, a run over a slow implementation shows it is alive: the
// status line is redrawn in place with its elapsed time, at least once a
// second, even while one case takes seconds. The implementation is the
// reference behind a shell loop that holds every `?reset` for 3 s, so the
// run (a fresh-node check and one case) lasts about 6 s with few runner
// events. Counted, not timed: at least one redraw per second of the run
// (the ticker redraws twice a second; without it there are about three).
TEST_F(Cli, CertifyOnATerminalRedrawsItsStatusEverySecond) {
  const std::string slow = "sh -c " + shell_quote("while IFS= read -r l; do case \"$l\" in '?reset') sleep 3;; esac; "
                                                  "printf '%s\\n' \"$l\"; done | " + serve());
  const std::string command = "cd " + shell_quote(dir_.string()) + " && exec " + shell_quote(VGC_BINARY) +
                              " certify --impl " + shell_quote("exec:" + slow) +
                              " --reports rep --cases 1 --max-size 5 --clauses LAYER-BASE-1 --timeout 20";
  int exit_code = -1;
  const std::string screen = on_a_terminal(command, &exit_code);
  EXPECT_EQ(exit_code, 0) << screen;
  const std::vector<std::string> lines = redrawn_lines(screen);
  const int draws = static_cast<int>(lines.size());
  const double last = draws ? last_elapsed(lines.back()) : 0;
  const std::regex property_line("^\\[[0-9]+/[0-9]+\\] [a-z_.]+ +[0-9]+/1 cases, 0 found  [0-9.]+ s$");
  int property_draws = 0;
  for (const std::string& line : lines) property_draws += std::regex_search(line, property_line);
  EXPECT_GE(last, 5.0) << "the slow implementation was not slow:\n" << screen;
  EXPECT_GE(draws, static_cast<int>(last)) << draws << " redraws in " << last << " s:\n" << screen;
  EXPECT_GE(property_draws, 1) << "no status line with the property, its cases and findings:\n" << screen;
  // The permanent line per property is there too, and the status line is
  // cleared before the verdict is printed.
  EXPECT_NE(screen.find("layers"), std::string::npos) << screen;
  const std::size_t verdict = screen.find(": conformant (");
  ASSERT_NE(verdict, std::string::npos) << screen;
  const std::size_t line_start = screen.rfind('\n', verdict) + 1;
  EXPECT_EQ(screen.substr(line_start, 5), "exec:") << "the verdict shares its line with a status line:\n" << screen;
}

// The same for a fuzz campaign: a stand-in for the libFuzzer binary (the
// normal build has none; `vgc fuzz --fuzz-build` names where it is) prints
// one status line, then nothing for 5 s, as a fuzzer deep in a slow input
// would. The line is still redrawn, its elapsed time moving.
TEST_F(Cli, FuzzOnATerminalRedrawsItsStatusEverySecond) {
  fs::create_directories(dir_ / "fb" / "fuzz");
  fs::create_directories(dir_ / "src");
  const fs::path fuzzer = write("fb/fuzz/fuzz_stream",
                                "#!/bin/sh\n"
                                "echo '#2\tINITED cov: 5 ft: 6 corp: 1/1b exec/s: 0 rss: 30Mb'\n"
                                "sleep 5\n"
                                "echo '#9\tDONE   cov: 5 ft: 6 corp: 1/1b exec/s: 2 rss: 30Mb'\n");
  fs::permissions(fuzzer, fs::perms::owner_all);
  const std::string command = "cd " + shell_quote(dir_.string()) + " && exec " + shell_quote(VGC_BINARY) +
                              " fuzz stream --time 5 --fuzz-build fb --source-dir src";
  int exit_code = -1;
  const std::string screen = on_a_terminal(command, &exit_code);
  EXPECT_EQ(exit_code, 0) << screen;
  const std::vector<std::string> lines = redrawn_lines(screen);
  const int draws = static_cast<int>(lines.size());
  const double last = draws ? last_elapsed(lines.back()) : 0;
  EXPECT_GE(last, 4.0) << "the stand-in fuzzer was not slow:\n" << screen;
  EXPECT_GE(draws, static_cast<int>(last)) << draws << " redraws in " << last << " s:\n" << screen;
  int status_draws = 0;
  for (const std::string& line : lines) status_draws += line.find("execs 2  exec/s 0  cov 5") != std::string::npos;
  EXPECT_GE(status_draws, 1) << "no line with libFuzzer's figures:\n" << screen;
}

TEST_F(Cli, CertifyTheReferenceThroughExec) {
  const Result r = vgc("certify --impl " + shell_quote("exec:" + serve()) + " --reports rep" + kFast);
  ASSERT_EQ(r.exit_code, 0) << context(r);
  expect_report_files(dir_ / "rep", "conformant");
}

TEST_F(Cli, CertifyTheReferencePlugin) {
  const Result r = vgc("certify --impl " + shell_quote(std::string("plugin:") + VGC_REFERENCE_PLUGIN) + " --reports rep" + kFast);
  ASSERT_EQ(r.exit_code, 0) << context(r);
  expect_report_files(dir_ / "rep", "conformant");
}

TEST_F(Cli, AFaultIsRejectedReplaysAndCanBeBaselined) {
  const std::string env = "VGC_FAULT=bone-cycles-accepted";
  const std::string impl = "exec:" + serve(std::string("plugin:") + VGC_FAULT_PLUGIN);
  // BONE-FOREST-1 is IMPLEMENTATION-DEFINED: without --strict the stored
  // cycle is a profile difference, reported and not gating.
  const Result lax = vgc("certify --impl " + shell_quote(impl) + " --reports rep0" + kFast, env);
  EXPECT_EQ(lax.exit_code, 0) << context(lax);
  EXPECT_NE(lax.out.find("profile  BONE-FOREST-1"), std::string::npos) << context(lax);
  const Result r = vgc("certify --strict --impl " + shell_quote(impl) + " --reports rep" + kFast, env);
  ASSERT_EQ(r.exit_code, 1) << context(r);
  expect_report_files(dir_ / "rep", "not-conformant");
  EXPECT_NE(r.out.find("BONE-FOREST-1"), std::string::npos) << context(r);
  EXPECT_NE(r.out.find("re-run: VGC_FAULT='bone-cycles-accepted' " + std::string(VGC_BINARY) + " certify --impl"),
            std::string::npos)
      << "the re-run line lacks the environment the run needed: " << context(r);
  EXPECT_NE(r.out.find(" --strict"), std::string::npos) << context(r);

  const fs::path run_dir = fs::canonical(dir_ / "rep" / "latest");
  const fs::path file = run_dir / "counterexamples" / "BONE-FOREST-1.vgc";
  ASSERT_TRUE(fs::is_regular_file(file));
  std::vector<Command> commands;
  TextError error;
  ASSERT_TRUE(parse_commands(read(file), &commands, &error)) << error.to_string();
  ASSERT_FALSE(commands.empty());
  const std::string summary = read(run_dir / "summary.md");
  EXPECT_NE(summary.find("NOT CONFORMANT"), std::string::npos);
  EXPECT_NE(summary.find("BONE-FOREST-1"), std::string::npos);
  EXPECT_NE(summary.find(print_commands(commands)), std::string::npos) << "the shrunk counterexample is not in summary.md";
  // The last command is the bone_create that closes a cycle.
  EXPECT_TRUE(std::holds_alternative<cmd::BoneCreate>(commands.back())) << print_command(commands.back());

  // Replay against the same faulty implementation: exit 1, naming the clause.
  const Result again = vgc("replay " + shell_quote(file.string()) + " --impl " + shell_quote(impl), env);
  EXPECT_EQ(again.exit_code, 1) << context(again);
  EXPECT_NE(again.out.find("BONE-FOREST-1"), std::string::npos) << context(again);
  // The replay line that summary.md prints, run as printed (the build
  // tree's program by its absolute path, so that it works from any directory).
  const std::regex replay_line("Replay: `([^`]*)" + std::string(VGC_BINARY) + " (replay [^`]*)`");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(summary, m, replay_line)) << summary;
  EXPECT_EQ(m[1].str(), "VGC_FAULT='bone-cycles-accepted' ") << "the replay line carries the environment";
  const Result printed = vgc(m[2].str(), m[1].str());
  EXPECT_EQ(printed.exit_code, 1) << context(printed);

  // Against the reference it agrees: exit 0.
  const Result clean = vgc("replay " + shell_quote(file.string()) + " --impl reference");
  EXPECT_EQ(clean.exit_code, 0) << context(clean);

  // With BONE-FOREST-1 in a baseline the same run passes.
  write("baseline.txt", "# our host stores bone cycles\nBONE-FOREST-1 stored as roots, see ticket 12\n");
  const Result known =
      vgc("certify --strict --impl " + shell_quote(impl) + " --reports rep2 --baseline baseline.txt" + kFast, env);
  EXPECT_EQ(known.exit_code, 0) << context(known);
  EXPECT_NE(known.out.find("known"), std::string::npos) << context(known);
}

// One story in every report (issue 17 item 6): a run with a MUST, a SHOULD
// and an IMPLEMENTATION-DEFINED failure gives the same counts per status on
// stdout, in summary.md, in report.html and in report.json, and `vgc
// replay` of the SHOULD finding says what certify says of it. Before, stdout
// and summary.md counted all three as "fail" where report.html said
// "fail (SHOULD)" and "profile difference" (seen: stdout "3 fail", HTML
// "1 fail, 1 profile difference, 1 fail (SHOULD)"), and replay of the
// SHOULD finding said only "note REASON-1" and "agrees with the reference".
std::map<std::string, int> tally_of(const std::string& text) {  // "1 fail, 2 fail (SHOULD)" -> counts
  std::map<std::string, int> out;
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    std::size_t at = item.find_first_not_of(' ');
    if (at == std::string::npos) continue;
    item = item.substr(at);
    const std::size_t space = item.find(' ');
    out[item.substr(space + 1)] += std::stoi(item.substr(0, space));
  }
  return out;
}

TEST_F(Cli, EveryReportGivesTheSameCountsPerStatus) {
  const std::string env = "VGC_FAULT=polygon-delete-ignored,wrong-reason-codes,recreate-resets-data";
  const std::string impl = std::string("plugin:") + VGC_FAULT_PLUGIN;
  const Result r = vgc("certify --impl " + shell_quote(impl) + " --reports rep --quiet --cases 100 --seed 1", env);
  ASSERT_EQ(r.exit_code, 1) << context(r);
  const fs::path run_dir = fs::canonical(dir_ / "rep" / "latest");

  // stdout: "IMPL: not-conformant (N of M clauses pass, 1 fail, ...; 1.0 s)"
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(\((\d+) of (\d+) clauses pass((?:, [^,;]+)*); )")))
      << context(r);
  std::map<std::string, int> from_stdout = tally_of(m[3].str());
  from_stdout["pass"] = std::stoi(m[1].str());
  const int clauses = std::stoi(m[2].str());

  // summary.md: "M clauses: N pass, 1 fail, .... Seed ..."
  const std::string summary = read(run_dir / "summary.md");
  ASSERT_TRUE(std::regex_search(summary, m, std::regex(R"((\d+) clauses: ([^\n]*?)\. Seed)"))) << summary;
  EXPECT_EQ(std::stoi(m[1].str()), clauses);
  const std::map<std::string, int> from_summary = tally_of(m[2].str());

  // report.html: <p class="counts">M clauses: <span ...>N pass</span>...</p>
  const std::string html = read(run_dir / "report.html");
  ASSERT_TRUE(std::regex_search(html, m, std::regex(R"(<p class="counts">(\d+) clauses: (.*?)</p>)"))) << html;
  EXPECT_EQ(std::stoi(m[1].str()), clauses);
  std::map<std::string, int> from_html;
  const std::string spans = m[2].str();
  const std::regex span(R"(<span class="st [^"]*">(\d+) ([^<]*)</span>)");
  for (std::sregex_iterator it(spans.begin(), spans.end(), span), end; it != end; ++it)
    from_html[(*it)[2].str()] += std::stoi((*it)[1].str());

  // report.json: "counts", the non-zero ones.
  const auto j = nlohmann::json::parse(read(run_dir / "report.json"));
  std::map<std::string, int> from_json;
  for (const auto& [status, n] : j.at("counts").items())
    if (n.get<int>() != 0) from_json[status] = n.get<int>();

  EXPECT_EQ(from_stdout, from_summary) << context(r) << summary;
  EXPECT_EQ(from_stdout, from_html);
  EXPECT_EQ(from_stdout, from_json);
  int total = 0;
  for (const auto& [status, n] : from_stdout) total += n;
  EXPECT_EQ(total, clauses);
  // Each kind of failure is counted under its own status.
  EXPECT_EQ(from_stdout["fail"], 1) << "POLY-DELETE-1 (MUST) only: " << context(r);
  EXPECT_EQ(from_stdout["fail (SHOULD)"], 1) << "REASON-1: " << context(r);
  EXPECT_EQ(from_stdout["profile difference"], 1) << "LAYER-RECREATE-1: " << context(r);
  EXPECT_NE(summary.find("| REASON-1 | SHOULD | fail (SHOULD) |"), std::string::npos) << summary;

  // vgc replay of the SHOULD finding: certify's words for it.
  const fs::path file = run_dir / "counterexamples" / "REASON-1.vgc";
  ASSERT_TRUE(fs::is_regular_file(file));
  const Result again = vgc("replay " + shell_quote(file.string()) + " --impl " + shell_quote(impl), env);
  EXPECT_EQ(again.exit_code, 0) << "as in certify, a SHOULD clause not met leaves the verdict: " << context(again);
  EXPECT_NE(again.out.find("fail (SHOULD) REASON-1 (SHOULD): "), std::string::npos) << context(again);
  EXPECT_NE(again.out.find("the verdict stands (not gating)"), std::string::npos) << context(again);
  // ... and of the IMPLEMENTATION-DEFINED one: a profile difference, gating only with --strict.
  const fs::path impl_file = run_dir / "counterexamples" / "LAYER-RECREATE-1.vgc";
  ASSERT_TRUE(fs::is_regular_file(impl_file));
  const Result lax = vgc("replay " + shell_quote(impl_file.string()) + " --impl " + shell_quote(impl), env);
  EXPECT_NE(lax.out.find("profile difference LAYER-RECREATE-1 (IMPLEMENTATION-DEFINED): "), std::string::npos)
      << context(lax);
  const Result strict = vgc("replay --strict " + shell_quote(impl_file.string()) + " --impl " + shell_quote(impl), env);
  EXPECT_NE(strict.out.find("fail LAYER-RECREATE-1 (IMPLEMENTATION-DEFINED): "), std::string::npos)
      << context(strict);
  EXPECT_NE(strict.out.find("not-conformant"), std::string::npos) << context(strict);
}

// A capability fault (one whose clause a capability property declares):
// certify fails it through the plugin route; the counterexample records the
// check to repeat ("#! capability NAME variant N") and still runs under
// `vgc apply`; `vgc replay` repeats the check and fails naming the clause,
// passes against the reference, and says it cannot judge an implementation
// that no longer claims the capability (exit 2).
TEST_F(Cli, ACapabilityFaultReplaysItsCapabilityCheck) {
  int tried = 0;
  for (const auto& fault : faults::fault_catalog()) {
    const PropertySpec* property = nullptr;
    for (const PropertySpec& p : property_catalog())
      if (!p.capability.empty())
        for (auto c : p.clauses)
          if (c == fault.expected_clause) property = &p;
    if (!property) continue;
    ++tried;
    const std::string clause(fault.expected_clause), capability(property->capability);
    SCOPED_TRACE(std::string(fault.name) + " / " + clause);
    const std::string env = "VGC_FAULT=" + std::string(fault.name);
    const std::string impl = std::string("plugin:") + VGC_FAULT_PLUGIN_REQUESTS;
    const std::string reports = "rep-" + clause;
    const Result r = vgc("certify --impl " + shell_quote(impl) + " --reports " + reports + " --clauses " + clause +
                             " --quiet --cases 100 --max-size 30 --seed 1",
                         env);
    ASSERT_EQ(r.exit_code, 1) << context(r);
    EXPECT_NE(r.out.find(clause), std::string::npos) << context(r);

    const fs::path run_dir = fs::canonical(dir_ / reports / "latest");
    const fs::path file = run_dir / "counterexamples" / (clause + ".vgc");
    ASSERT_TRUE(fs::is_regular_file(file)) << file;
    const std::string text = read(file);
    Program program;
    TextError error;
    ASSERT_TRUE(parse_program(text, &program, &error)) << error.to_string() << "\n" << text;
    ASSERT_TRUE(program.request.has_value()) << "no capability directive in\n" << text;
    EXPECT_EQ(program.request->capability, capability);
    EXPECT_GE(program.request->variant, 1);
    EXPECT_LE(program.request->variant, 3);
    // The commands alone, as any command-file reader sees them: the same ones.
    std::vector<Command> commands;
    ASSERT_TRUE(parse_commands(text, &commands, &error)) << error.to_string();
    EXPECT_EQ(print_commands(commands), print_commands(program.commands));
    const Result applied = vgc("apply " + shell_quote(file.string()));
    EXPECT_EQ(applied.exit_code, 0) << context(applied);
    // report.json names the same check.
    const auto j = nlohmann::json::parse(read(run_dir / "report.json"));
    bool in_json = false;
    for (const auto& c : j.at("clauses"))
      if (c.at("id") == clause) {
        in_json = true;
        EXPECT_EQ(c.at("status"), "fail");
        EXPECT_EQ(c.at("capability_check").at("capability"), capability) << c.dump();
        EXPECT_EQ(c.at("capability_check").at("variant"), program.request->variant) << c.dump();
      }
    EXPECT_TRUE(in_json);

    // Replay against the same faulty implementation: the check fails again.
    const Result again = vgc("replay " + shell_quote(file.string()) + " --impl " + shell_quote(impl), env);
    EXPECT_EQ(again.exit_code, 1) << context(again);
    EXPECT_NE(again.out.find("fail " + clause), std::string::npos) << context(again);
    EXPECT_NE(again.out.find("#! capability " + capability), std::string::npos) << context(again);
    // The replay line report.json prints, run as printed.
    for (const auto& c : j.at("clauses"))
      if (c.at("id") == clause) {
        const std::string line = c.at("replay");
        // It carries the environment the run needed (VGC_FAULT), before the
        // program (its absolute path).
        const std::string program = std::string(VGC_BINARY) + " ";
        const auto at = line.find(program);
        ASSERT_NE(at, std::string::npos) << line;
        const std::string printed_env = line.substr(0, at);
        EXPECT_NE(printed_env.find("VGC_FAULT="), std::string::npos) << line;
        const Result printed = vgc(line.substr(at + program.size()), printed_env);
        EXPECT_EQ(printed.exit_code, 1) << context(printed);
      }
    // Against the reference: exit 0, the check passes.
    const Result clean = vgc("replay " + shell_quote(file.string()) + " --impl reference");
    EXPECT_EQ(clean.exit_code, 0) << context(clean);
    EXPECT_NE(clean.out.find("passes the check of capability \"" + capability + "\""), std::string::npos)
        << context(clean);
    // The same fault without the requests (claims nothing): the check cannot be repeated.
    const Result unclaimed =
        vgc("replay " + shell_quote(file.string()) + " --impl " + shell_quote(std::string("plugin:") + VGC_FAULT_PLUGIN),
            env);
    EXPECT_EQ(unclaimed.exit_code, 2) << context(unclaimed);
    EXPECT_NE(unclaimed.out.find("does not claim the capability \"" + capability + "\""), std::string::npos)
        << context(unclaimed);
    EXPECT_NE(unclaimed.out.find(clause), std::string::npos) << context(unclaimed);
  }
  EXPECT_GE(tried, 2) << "no seeded capability faults";
}

TEST_F(Cli, AMalformedCapabilityDirectiveNamesLineAndColumn) {
  const std::string cube = read(std::string(VGC_SOURCE_DIR) + "/corpora/examples/cube.vgc");
  const std::size_t lines = static_cast<std::size_t>(std::count(cube.begin(), cube.end(), '\n'));
  write("bad_variant.vgc", cube + "#! capability subdivision variant two\n");
  const Result bad = vgc("replay bad_variant.vgc --impl reference");
  EXPECT_EQ(bad.exit_code, 2) << context(bad);
  EXPECT_NE(bad.err.find("bad_variant.vgc:" + std::to_string(lines + 1) + ":35:"), std::string::npos) << context(bad);
  write("early.vgc", "#! capability manifold variant 1\n" + cube);
  const Result early = vgc("replay early.vgc --impl reference");
  EXPECT_EQ(early.exit_code, 2) << context(early);
  EXPECT_NE(early.err.find("early.vgc:1:1:"), std::string::npos) << context(early);
  // `vgc apply` reads both as plain command files.
  EXPECT_EQ(vgc("apply bad_variant.vgc").exit_code, 0);
  // A drawn value out of range names its column (a check_drawn check's draw).
  write("bad_draw.vgc", cube + "#! capability edits variant 1 draw 4294967296\n");
  const Result big = vgc("replay bad_draw.vgc --impl reference");
  EXPECT_EQ(big.exit_code, 2) << context(big);
  EXPECT_NE(big.err.find("bad_draw.vgc:" + std::to_string(lines + 1) + ":36:"), std::string::npos) << context(big);
  // A well-formed drawn edit on the cube: the reference passes it.
  write("cube_edit.vgc", cube + "#! capability edits variant 2 draw 123456789\n");
  const Result edit = vgc("replay cube_edit.vgc --impl reference");
  EXPECT_EQ(edit.exit_code, 0) << context(edit);
  EXPECT_NE(edit.out.find("passes the check"), std::string::npos) << context(edit);
  // A well-formed one on the cube: the reference passes it.
  write("cube_manifold.vgc", cube + "#! capability manifold variant 1\n");
  const Result fine = vgc("replay cube_manifold.vgc --impl reference");
  EXPECT_EQ(fine.exit_code, 0) << context(fine);
}

TEST_F(Cli, UsageErrorsExitTwo) {
  for (const char* shard : {"0/2", "3/2", "1/0", "x"}) {
    const Result r = vgc(std::string("certify --shard ") + shard + " --reports rep" + kFast);
    EXPECT_EQ(r.exit_code, 2) << shard << "\n" << context(r);
    EXPECT_NE(r.err.find("--shard"), std::string::npos) << context(r);
  }
  write("bad_baseline.txt", "BONE-FOREST-1 fine\n\nLAYER-BASE-99 no such clause\n");
  const Result b = vgc("certify --baseline bad_baseline.txt --reports rep" + kFast);
  EXPECT_EQ(b.exit_code, 2) << context(b);
  EXPECT_NE(b.err.find("bad_baseline.txt:3:"), std::string::npos) << context(b);
  EXPECT_NE(b.err.find("LAYER-BASE-99"), std::string::npos) << context(b);
  EXPECT_FALSE(fs::exists(dir_ / "rep")) << "a usage error still wrote reports";

  const Result impl = vgc("certify --impl nonsense:x --reports rep" + kFast);
  EXPECT_EQ(impl.exit_code, 2) << context(impl);
}

// Every mistake a newcomer can make on the command line is exit 2 with a
// message that names what is wrong and what to do next, and writes no
// report. Each row: the arguments, then text the message must hold (the
// mistake, then the fix).
TEST_F(Cli, EveryUsageErrorSaysWhatToDo) {
  write("bad_baseline.txt", "# known\nLAYER-BASE-2 fine\n  BONE-FORREST-1 a typo\n");
  write("no_reason.txt", "LAYER-BASE-2\n");
  write("twice.txt", "ATOMIC-1 a\nATOMIC-1 b\n");
  write("not_a_library.so", "hello\n");
  write("a_file", "");
  write("not_executable.sh", "#!/bin/sh\necho vgc-exec 1 x\n");  // written without the x bit
  Dl_info libc{};
  ASSERT_NE(dladdr(reinterpret_cast<void*>(&std::printf), &libc), 0);  // a library without vgc_plugin_v1
  const std::string fault = std::string(VGC_FAULT_PLUGIN);
  struct Row {
    std::string args;
    std::vector<std::string> says;
  };
  const std::vector<Row> rows = {
      {"certify --impl nonsense:x", {"unknown implementation 'nonsense:x'", "expected reference, exec:CMD", "plugin:PATH"}},
      {"certify --impl exec:", {"names no command", "expected reference, exec:CMD"}},
      {"certify --impl plugin:", {"names no library", "plugin:PATH"}},
      {"certify --impl exec:./no-such-host", {"no-such-host: not found", "what to do: the shell found no such program"}},
      {"certify --impl exec:./not_executable.sh", {"status 126", "what to do: the program is not executable: chmod +x"}},
      {"certify --impl exec:cat", {"answered ?hello with", "what to do: check that the program speaks the exec protocol"}},
      {"certify --impl plugin:no_such.so", {"no_such.so is not there", "give the path of your plugin's shared library"}},
      {"certify --impl plugin:not_a_library.so", {"cannot load the library", "what to do: the plugin must be a shared library"}},
      {"certify --impl " + shell_quote(std::string("plugin:") + libc.dli_fname),
       {"does not export the function vgc_plugin_v1", "nm -D PATH | grep vgc_plugin_v1"}},
      {"replay " + shell_quote(std::string(VGC_SOURCE_DIR) + "/corpora/examples/cube.vgc") + " --impl plugin:no_such.so",
       {"vgc replay: plugin:no_such.so", "give the path of your plugin"}},
      {"certify --baseline no_such.txt", {"no_such.txt: cannot read the baseline file", "give the path of a file of known deviations"}},
      {"certify --baseline bad_baseline.txt", {"bad_baseline.txt:3:3: unknown clause id 'BONE-FORREST-1'", "clauses` lists (one clause id, then the reason, per line)"}},
      {"certify --baseline no_reason.txt", {"no_reason.txt:1:13: clause LAYER-BASE-2 needs a reason", "write why"}},
      {"certify --baseline twice.txt", {"twice.txt:2:1: clause ATOMIC-1 is listed twice (first on line 1)", "keep one"}},
      {"certify --clauses 'LAYER-*,BONEE-*'", {"--clauses pattern 'BONEE-*' matches no clause id", "`vgc clauses` lists them"}},
      {"certify --clauses ','", {"matches no clause id", "`vgc clauses` lists them"}},
      {"certify --seed abc", {"--seed", "takes a whole number", "vgc certify --help"}},
      {"certify --seed -1", {"--seed", "takes a whole number", "got '-1'"}},
      {"certify --cases x", {"--cases", "vgc certify --help"}},
      {"certify --cases 0", {"--cases: takes a whole number of cases per property from 1", "got '0'"}},
      {"certify --max-size 0", {"--max-size: takes a whole number", "from 1 to 100000", "got '0'"}},
      {"certify --budget 0", {"--budget: takes a positive number of seconds", "got '0'"}},
      {"certify --timeout -2", {"--timeout: takes a positive number of seconds", "got '-2'"}},
      {"certify --budget inf", {"--budget: takes a positive number of seconds", "got 'inf'"}},
      {"certify --seed 18446744073709551616", {"--seed: takes a whole number", "got '18446744073709551616'"}},
      {"certify --reports ''", {"--reports: is empty"}},
      {"certify --levels 3", {"--levels requires --mesh"}},
      {"certify --shard 4/3", {"--shard takes I/N", "for example --shard 2/3"}},
      {"certify --reports a_file/reports", {"cannot write reports under 'a_file/reports'", "give --reports a directory you can write"}},
      {"certify --no-such-option", {"--no-such-option", "vgc certify --help"}},
      {"certfy", {"unknown command 'certfy'", "use one of", "certify"}},
      {"replay", {"file is required", "vgc replay --help"}},
      {"replay no_such.vgc", {"cannot read no_such.vgc (no such file)", "give the path of a command file"}},
      {"apply no_such.vgc", {"cannot read no_such.vgc (no such file)", "give the path of a command file"}},
      {"apply .", {"cannot read . (it is a directory)", "give the path of a command file"}},
      {"fuzz no_such_target", {"unknown target 'no_such_target'", "expected stream, text, differential"}},
  };
  for (const Row& row : rows) {
    SCOPED_TRACE(row.args);
    const bool certify = row.args.rfind("certify", 0) == 0;
    const bool own_reports = row.args.find("--reports") != std::string::npos;
    const Result r = vgc(row.args + (certify ? (own_reports ? " --quiet" : " --reports rep --quiet") : ""));
    EXPECT_EQ(r.exit_code, 2) << context(r);
    for (const std::string& text : row.says) EXPECT_NE(r.err.find(text), std::string::npos) << text << "\n" << context(r);
    EXPECT_EQ(r.err.find("terminate called"), std::string::npos) << context(r);
    EXPECT_FALSE(fs::exists(dir_ / "rep")) << "a usage error wrote reports: " << context(r);
  }
}

TEST_F(Cli, ClausesListsTheWholeCatalog) {
  const Result r = vgc("clauses");
  ASSERT_EQ(r.exit_code, 0) << context(r);
  std::set<std::string> listed;
  std::istringstream in(r.out);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string first;
    if (words >> first) listed.insert(first);
  }
  std::set<std::string> catalog;
  for (const Clause& c : clause_catalog()) catalog.insert(std::string(c.id));
  EXPECT_EQ(listed, catalog);
  const Result md = vgc("clauses --markdown");
  ASSERT_EQ(md.exit_code, 0);
  for (const Clause& c : clause_catalog())
    EXPECT_NE(md.out.find("### " + std::string(c.id) + " "), std::string::npos) << c.id;
  // The header says what each level does to the verdict: an
  // IMPLEMENTATION-DEFINED failure is a profile difference that gates only
  // with --strict (it said "counts like MUST"); and docs/clauses.md is the
  // generated text, not an older one.
  EXPECT_EQ(md.out.find("counts like MUST"), std::string::npos);
  EXPECT_NE(md.out.find("`profile difference`, not gating; `vgc certify --strict` makes it gate"), std::string::npos);
  EXPECT_EQ(read(fs::path(VGC_SOURCE_DIR) / "docs" / "clauses.md"), md.out)
      << "docs/clauses.md is stale: ./vgc clauses --markdown > docs/clauses.md";
}

TEST_F(Cli, AMalformedFileNamesLineAndColumn) {
  // Line 2, column 25 is the "x" where a vertex id should be.
  const fs::path file = write("bad.vgc", "# a comment\nvertex_set_xyz_real64 0 x 1 1 1\n");
  const Result apply = vgc("apply bad.vgc");
  EXPECT_EQ(apply.exit_code, 2) << context(apply);
  EXPECT_NE(apply.err.find("bad.vgc:2:25:"), std::string::npos) << context(apply);
  const Result replay = vgc("replay bad.vgc --impl reference");
  EXPECT_EQ(replay.exit_code, 2) << context(replay);
  EXPECT_NE(replay.err.find("bad.vgc:2:25:"), std::string::npos) << context(replay);
  const Result fine = vgc("apply " + shell_quote(std::string(VGC_SOURCE_DIR) + "/corpora/examples/cube.vgc"));
  EXPECT_EQ(fine.exit_code, 0) << context(fine);
}

}  // namespace
}  // namespace vgc
