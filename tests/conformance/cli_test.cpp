// cli_test.cpp — `vgc certify`, `vgc replay`, `vgc clauses` and `vgc apply`
// end to end: the real binary (VGC_BINARY) through a shell, in a temporary
// directory, checked by exit code and by the files and lines it writes. The
// three routes (in process, exec, plugin) certify the reference; a seeded
// fault (libvgc_fault_plugin.so behind `vgc serve`) is rejected naming its
// clause, replays, and passes with a baseline.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
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
  // A run this short prints one status line at the start, then only the
  // per-property lines (status lines come at most every 10 s in a log).
  std::istringstream lines(r.err);
  std::string l;
  int bracketed = 0;
  while (std::getline(lines, l)) bracketed += l.rfind("[", 0) == 0;
  EXPECT_LE(bracketed, static_cast<int>(property_catalog().size()) + 1) << r.err;
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
  EXPECT_NE(r.out.find("re-run: VGC_FAULT='bone-cycles-accepted' ./vgc certify --impl"), std::string::npos)
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
  // The replay line that summary.md prints, run as printed (from the source
  // tree's ./vgc wrapper it would build first; here the binary itself).
  const std::regex replay_line("Replay: `([^`]*)\\./vgc (replay [^`]*)`");
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
        // It carries the environment the run needed (VGC_FAULT), before ./vgc.
        const auto at = line.find("./vgc ");
        ASSERT_NE(at, std::string::npos) << line;
        const std::string printed_env = line.substr(0, at);
        EXPECT_NE(printed_env.find("VGC_FAULT="), std::string::npos) << line;
        const Result printed = vgc(line.substr(at + 6), printed_env);
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
