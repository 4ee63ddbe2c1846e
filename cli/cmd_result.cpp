// cmd_result.cpp — `vgc result RUN_DIR CLAUSE`: one clause's result from a
// certify run's report.json (clause_result.h), for one CTest test per
// clause (cmake/vgc_certification.cmake).
//
// Exit codes: 0 the clause passes (or its finding does not gate), 1 a gating
// finding, 2 unchecked, no readable report, or an empty or unknown clause
// id, 77 not judged in this run (CTest's SKIP_RETURN_CODE).
#include <memory>
#include <string>

#include "clause.h"
#include "clause_result.h"
#include "subcommand.h"
#include "terminal_text.h"

namespace vgc::cli {
namespace {

struct ResultOptions {
  std::string run_dir;
  std::string clause;
};

void add_result(CLI::App& app, int* exit_code) {
  auto o = std::make_shared<ResultOptions>();
  auto* sub = app.add_subcommand("result", "Print one clause's result from a certify run directory, exit by it");
  sub->add_option("run_dir", o->run_dir, "A run directory (reports/latest, or reports/<impl>/<run>)")->required();
  sub->add_option("clause", o->clause, "A clause id (vgc clauses lists them)")->required();
  sub->callback([o, exit_code] {
    // A misspelt id would be "not judged in this run" (77): CTest would skip
    // the test instead of failing it.
    if (!find_clause(o->clause)) {
      say(stderr, "vgc result: clause: unknown clause id '{}': use an id that `vgc clauses` lists\n", o->clause);
      *exit_code = 2;
      return;
    }
    const ClauseResult r = clause_result(o->run_dir, o->clause);
    say("{}", r.text);
    *exit_code = r.exit_code;
  });
}

const Subcommand kResult{add_result};

}  // namespace
}  // namespace vgc::cli
