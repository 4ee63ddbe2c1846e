// cmd_replay.cpp — `vgc replay FILE --impl ...`: re-run one counterexample
// command file against an implementation, command by command, with the
// same comparison certify uses, and say where it diverges. A file that ends
// with a capability directive ("#! capability NAME variant N",
// program_text.h) then repeats that capability check, judged by the same
// oracles certify registers.
//
// Exit codes: 0 the implementation agrees with the reference on the whole
// file (and passes its capability check); 1 it does not (the finding and
// its clause are printed, in certify's words: the status as certify shows
// it, "profile difference" for one that does not gate, the level, and
// what it does to certify's verdict; exit 1 whatever the level: the
// divergence reproduced). A SHOULD clause not met (wrong reason code) is
// printed as certify shows it, "fail (SHOULD)", the verdict standing, and
// does not change the exit code, as in certify; 2 usage error, a file that does not parse (line
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
#include "option_values.h"
#include "program_text.h"
#include "read_file.h"
#include "runner.h"
#include "subcommand.h"
#include "verdict.h"
#include "mesh_certification.h"
#include "wire_fuzz.h"
#include "terminal_text.h"

namespace vgc::cli {
namespace {

struct Options {
  std::string file;
  ImplOptions impl;  // --impl and its family (open_impl.h)
  bool strict = false;  // as certify --strict: IMPLEMENTATION-DEFINED readings gate
  bool wire = false;    // the file is a `vgc fuzz wire` transcript (fuzz/wire/wire_fuzz.h)
};

int run(const Options& o) {
  if (o.wire) {
    if (o.impl.route.kind != RouteKind::Verse) {
      say(stderr, "vgc replay --wire: a wire transcript is sent to a Verse host: --impl verse:HOST[:PORT]\n");
      return 2;
    }
    fuzz::WireFuzzOptions w;
    w.impl = o.impl.route;
    w.timeout_s = o.impl.timeout;
    w.login_timeout_s = o.impl.start_timeout;
    if (o.impl.verse_bone_form != "auto") w.verse_bone_form = o.impl.verse_bone_form;
    w.host_cmd = o.impl.host_cmd;
    return fuzz::replay_wire_transcript(o.file, w);
  }
  std::string text;
  if (!read_file(o.file, &text)) {
    say(stderr,
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
    say(stderr, "{}:{}:{}: error: {}\n", o.file, error.line, error.column, error.message);
    return 2;
  }
  auto sut = open_impl_or_report("replay", o.impl);
  if (!sut) return 2;
  register_oracle_checks();  // as certify: the oracles judge the capability checks
  // A user's mesh is judged as certify --mesh judged it (same requests).
  const ReplayResult r = program.mesh ? replay_mesh_program(program, *sut) : replay_program(program, *sut);
  // A SHOULD clause not met is said as certify says it ("fail (SHOULD)",
  // the verdict stands); other notes are choices the model followed.
  int should_not_met = 0;
  for (const auto& n : r.notes) {
    const Clause* nc = find_clause(n.clause);
    if (nc && nc->level == ClauseLevel::Should) {
      ++should_not_met;
      say("fail (SHOULD) {} (SHOULD): {}\n", n.clause, n.message);
      say("verdict: a SHOULD clause not met: certify reports it as \"fail (SHOULD)\" and the verdict "
                 "stands (not gating)\n");
    } else {
      say("note     {:<24} {}\n", n.clause, n.message);
    }
  }
  if (!r.failure) {
    if (should_not_met)
      say("{}: agrees with the reference on all {} commands of {} but for {} SHOULD clause(s) not met "
                 "(above; the verdict stands)\n",
                 o.impl.route.spec, program.commands.size(), o.file, should_not_met);
    else
      say("{}: agrees with the reference on all {} commands of {}\n", o.impl.route.spec, program.commands.size(),
                 o.file);
    if (!program.request) return 0;
    if (!r.not_judged.empty()) {
      say("{}:{}: cannot repeat the capability check: {}\n", o.file, directive_line, r.not_judged);
      return 2;
    }
    say("{}: passes the check of capability \"{}\" (variant {}) of {}\n", o.impl.route.spec,
        program.request->capability, program.request->variant, capability_clauses(program.request->capability));
    return 0;
  }
  const Clause* clause = find_clause(r.failure->clause);
  const auto at = static_cast<std::size_t>(r.failed_at);
  if (r.failed_at >= 0 && at < program.commands.size())
    say("{}:{}: {}\n", o.file, lines[at], print_command(program.commands[at]));
  else if (program.request && at == program.commands.size())
    say("{}:{}: {}", o.file, directive_line, print_capability_directive(*program.request));
  // The finding in certify's words (verdict.h): its shown status, level,
  // and what it does to the verdict. The exit code says the divergence
  // reproduced (1), whatever the level: scripts and `vgc fuzz` rely on it.
  const std::string status = finding_status_name(r.failure->status);
  if (!clause) {
    say("{} {} (?): {}\n", status, r.failure->clause, r.failure->message);
    return 1;
  }
  ClauseOutcome co;
  co.clause = clause;
  co.status = clause_status_of(r.failure->status);
  co.finding = *r.failure;
  const bool gates = finding_gates(co, o.strict);
  const std::string shown = clause->level == ClauseLevel::Should ? status + " (SHOULD)"
                            : gates                              ? status
                                                                 : std::string("profile difference");
  say("{} {} ({}): {}\n", shown, r.failure->clause, clause_level_name(clause->level), r.failure->message);
  for (const Finding& also : r.also_failed)  // what the same end shows besides (the late view's)
    say("also {} {}: {}\n", finding_status_name(also.status), also.clause, also.message);
  if (r.failure->host_sent_seen) {  // the Verse wire: what the host sent back after the command
    say("the host sent back {} message(s) after it{}\n", r.failure->host_sent_count,
        r.failure->host_sent.empty() ? "" : ", as vgc's mirror applied them:");
    for (const std::string& line : r.failure->host_sent) say("  {}\n", line);
    if (r.failure->host_sent_count > r.failure->host_sent.size())
      say("  ... and {} more\n", r.failure->host_sent_count - r.failure->host_sent.size());
  }
  say("spec ({}): {}\n", clause->source, clause->text);
  if (clause->level == ClauseLevel::Should)
    say("verdict: a SHOULD clause not met: certify reports it as \"{}\" and the verdict stands (not "
               "gating)\n", shown);
  else if (!gates)
    say("verdict: an IMPLEMENTATION-DEFINED reading not followed: certify reports it as a profile "
               "difference, not gating; with --strict it gates (not-conformant)\n");
  else
    say("verdict: certify reports it as \"{}\" and the run is not-conformant (gating{})\n", shown,
               clause->level == ClauseLevel::ImplementationDefined && r.failure->status == FindingStatus::Fail
                   ? ", --strict"
                   : "");
  return 1;
}

void add(CLI::App& app, int* exit_code) {
  auto o = std::make_shared<Options>();
  auto* sub = app.add_subcommand("replay", "Replay a counterexample command file against an implementation");
  sub->add_option("file", o->file, "Command file (a counterexample from reports/, or any command file)")->required();
  add_impl_options(sub, &o->impl, kTimeout | kStartTimeout | kBoneForm | kHostCmd,
                   "reference | exec:CMD | plugin:PATH | verse:HOST[:PORT]");
  sub->add_flag("--wire", o->wire,
                "FILE is a `vgc fuzz wire` transcript: send its packets again to a fresh node of --impl "
                "verse:HOST and check the host answers and holds what it acknowledged (exit 1 when not)");
  sub->add_flag("--strict", o->strict,
                "Say the verdict as certify --strict would (IMPLEMENTATION-DEFINED readings gate); the exit "
                "code is the same");
  sub->callback([o, exit_code] {
    if (const std::string misuse = impl_options_misuse(o->impl); !misuse.empty()) {
      say(stderr, "vgc replay: {}\n", misuse);
      *exit_code = 2;
      return;
    }
    *exit_code = run(*o);
  });
}

const Subcommand kReplay{add};

}  // namespace
}  // namespace vgc::cli
