// cmd_replay.cpp — `vgc replay FILE --impl ...`: re-run one counterexample
// command file against an implementation, command by command, with the
// same comparison certify uses, and say where it diverges.
//
// Exit codes: 0 the implementation agrees with the reference on the whole
// file; 1 it does not (the finding is printed); 2 usage error or a file
// that does not parse (line and column named).
#include <fmt/core.h>

#include <fstream>
#include <memory>
#include <sstream>

#include "check_step.h"
#include "clause.h"
#include "command_text.h"
#include "implementation.h"
#include "runner.h"
#include "subcommand.h"

namespace vgc::cli {
namespace {

struct Options {
  std::string file;
  std::string impl = "reference";
  double timeout = 5;
};

int run(const Options& o) {
  std::ifstream in(o.file, std::ios::binary);
  if (!in) {
    fmt::print(stderr, "vgc replay: cannot read {}\n", o.file);
    return 2;
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  Program program;
  std::vector<std::size_t> lines;
  TextError error;
  if (!parse_commands(ss.str(), &program.commands, &error, &lines)) {
    fmt::print(stderr, "{}:{}:{}: error: {}\n", o.file, error.line, error.column, error.message);
    return 2;
  }
  OpenOptions open;
  open.timeout_seconds = o.timeout;
  std::string open_error;
  auto sut = open_implementation(o.impl, open, &open_error);
  if (!sut) {
    fmt::print(stderr, "vgc replay: {}\n", open_error);
    return 2;
  }
  const ReplayResult r = replay_program(program, *sut);
  for (const auto& n : r.notes) fmt::print("note     {:<24} {}\n", n.clause, n.message);
  if (!r.failure) {
    fmt::print("{}: agrees with the reference on all {} commands of {}\n", o.impl, program.commands.size(), o.file);
    return 0;
  }
  const Clause* clause = find_clause(r.failure->clause);
  if (r.failed_at >= 0)
    fmt::print("{}:{}: {}\n", o.file, lines[static_cast<std::size_t>(r.failed_at)],
               print_command(program.commands[static_cast<std::size_t>(r.failed_at)]));
  fmt::print("{} {} ({}): {}\n", finding_status_name(r.failure->status), r.failure->clause,
             clause ? clause_level_name(clause->level) : "?", r.failure->message);
  if (clause) fmt::print("spec ({}): {}\n", clause->source, clause->text);
  return 1;
}

void add(CLI::App& app, int* exit_code) {
  auto o = std::make_shared<Options>();
  auto* sub = app.add_subcommand("replay", "Replay a counterexample command file against an implementation");
  sub->add_option("file", o->file, "Command file (a counterexample from reports/, or any command file)")->required();
  sub->add_option("--impl", o->impl, "reference | exec:CMD | plugin:PATH")->capture_default_str();
  sub->add_option("--timeout", o->timeout, "Seconds an out-of-process implementation has per answer")
      ->capture_default_str();
  sub->callback([o, exit_code] { *exit_code = run(*o); });
}

const Subcommand kReplay{add};

}  // namespace
}  // namespace vgc::cli
