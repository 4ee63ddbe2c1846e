// cmd_replay.cpp — `vgc replay FILE --impl ...`: re-run one counterexample
// command file against an implementation, command by command, with the
// same comparison certify uses, and say where it diverges. A file that ends
// with a capability directive ("#! capability NAME variant N",
// program_text.h) then repeats that capability check, judged by the same
// oracles certify registers.
//
// Exit codes: 0 the implementation agrees with the reference on the whole
// file (and passes its capability check); 1 it does not (the finding and
// its clause are printed); 2 usage error, a file that does not parse (line
// and column named), an implementation that cannot be started, or a
// capability check that cannot be judged (the implementation does not
// claim the capability, this vgc has no oracle for it, or the oracle cannot
// be asked about this state, e.g. OpenSubdiv refuses the mesh): it never
// says "passes" for a check that compared nothing.
#include <fmt/core.h>

#include <memory>

#include "check_step.h"
#include "clause.h"
#include "command_text.h"
#include "implementation.h"
#include "open_impl.h"
#include "program_text.h"
#include "read_file.h"
#include "runner.h"
#include "subcommand.h"

namespace vgc::cli {
namespace {

struct Options {
  std::string file;
  std::string impl = "reference";
  double timeout = 5;
  std::string verse_bone_form = "auto";  // --verse-bone-form
};

int run(const Options& o) {
  std::string text;
  if (!read_file(o.file, &text)) {
    fmt::print(stderr,
               "vgc replay: cannot read {} ({}): give the path of a command file (docs/commands.md), e.g. "
               "reports/latest/counterexamples/<CLAUSE>.vgc\n",
               o.file, read_failure(o.file));
    return 2;
  }
  Program program;
  std::vector<std::size_t> lines;
  std::size_t directive_line = 0;
  TextError error;
  if (!parse_program(text, &program, &error, &lines, &directive_line)) {
    fmt::print(stderr, "{}:{}:{}: error: {}\n", o.file, error.line, error.column, error.message);
    return 2;
  }
  auto sut = open_impl_or_report("replay", o.impl, o.timeout, o.verse_bone_form);
  if (!sut) return 2;
  register_oracle_checks();  // as certify: the oracles judge the capability checks
  const ReplayResult r = replay_program(program, *sut);
  for (const auto& n : r.notes) fmt::print("note     {:<24} {}\n", n.clause, n.message);
  if (!r.failure) {
    fmt::print("{}: agrees with the reference on all {} commands of {}\n", o.impl, program.commands.size(), o.file);
    if (!program.request) return 0;
    if (!r.not_judged.empty()) {
      fmt::print("{}:{}: cannot repeat the capability check: {}\n", o.file, directive_line, r.not_judged);
      return 2;
    }
    fmt::print("{}: passes the check of capability \"{}\" (variant {}) of {}\n", o.impl, program.request->capability,
               program.request->variant, capability_clauses(program.request->capability));
    return 0;
  }
  const Clause* clause = find_clause(r.failure->clause);
  const auto at = static_cast<std::size_t>(r.failed_at);
  if (r.failed_at >= 0 && at < program.commands.size())
    fmt::print("{}:{}: {}\n", o.file, lines[at], print_command(program.commands[at]));
  else if (program.request && at == program.commands.size())
    fmt::print("{}:{}: {}", o.file, directive_line, print_capability_directive(*program.request));
  fmt::print("{} {} ({}): {}\n", finding_status_name(r.failure->status), r.failure->clause,
             clause ? clause_level_name(clause->level) : "?", r.failure->message);
  if (clause) fmt::print("spec ({}): {}\n", clause->source, clause->text);
  return 1;
}

void add(CLI::App& app, int* exit_code) {
  auto o = std::make_shared<Options>();
  auto* sub = app.add_subcommand("replay", "Replay a counterexample command file against an implementation");
  sub->add_option("file", o->file, "Command file (a counterexample from reports/, or any command file)")->required();
  sub->add_option("--impl", o->impl, "reference | exec:CMD | plugin:PATH | verse:HOST[:PORT]")->capture_default_str();
  sub->add_option("--timeout", o->timeout, "Seconds an out-of-process implementation has per answer")
      ->capture_default_str();
  sub->add_option("--verse-bone-form", o->verse_bone_form,
                  "verse: the bone_create form to speak: auto (the form the host answers a probe in), spec "
                  "(Verse spec 2.6.3) or r6 (r6's last release; docs/verse_wire.md section 4)")
      ->check(CLI::IsMember({"auto", "spec", "r6"}))
      ->capture_default_str();
  sub->callback([o, exit_code] { *exit_code = run(*o); });
}

const Subcommand kReplay{add};

}  // namespace
}  // namespace vgc::cli
