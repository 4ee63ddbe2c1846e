// report_summary.cpp — summary.md, the file a person reads first.
#include <fmt/format.h>

#include <filesystem>

#include "command_text.h"
#include "program_text.h"
#include "report.h"

namespace vgc {

std::string render_summary(const RunResult& run, const Verdict& v, const ReportContext& ctx) {
  std::string out;
  int pass = 0, fail = 0, crash = 0, timeout = 0, skipped = 0, not_claimed = 0;
  for (const auto& co : run.clauses) {
    if (co.status == "pass") ++pass;
    else if (co.status == "fail") ++fail;
    else if (co.status == "crash") ++crash;
    else if (co.status == "timeout") ++timeout;
    else if (co.status == "not-claimed") ++not_claimed;
    else ++skipped;
  }
  const char* headline = v.name == "conformant"       ? "CONFORMANT"
                         : v.name == "not-conformant" ? "NOT CONFORMANT"
                                                      : "INCOMPLETE";
  out += fmt::format("# vgc certify: {} — {}\n\n", ctx.implementation_spec, headline);
  out += fmt::format("{} clauses: {} pass, {} fail, {} crash, {} timeout, {} skipped, {} not claimed. Seed {}, {} cases per "
                     "property, {:.1f} s.\n\n",
                     run.clauses.size(), pass, fail, crash, timeout, skipped, not_claimed, run.options.seed, run.options.cases,
                     run.seconds);
  out += "Re-run exactly: `" + ctx.command_line + "`\n\n";
  if (v.name == "incomplete") {
    // Why: a property the budget cut short, or a selected clause nothing
    // judged (e.g. a claimed capability this vgc has no oracle for).
    out += "The run is incomplete: the verdict is neither a pass nor a failure.\n\n";
    for (const auto& p : run.properties)
      if (p.status == "incomplete") out += fmt::format("- property `{}` did not finish: {}\n", p.id, p.note);
    for (const auto& co : run.clauses)
      if (co.status == "skipped" && co.note.find("shard") == std::string::npos)
        out += fmt::format("- clause {} was not judged: {}\n", co.clause->id, co.note);
    out += "\n";
  }

  auto section = [&](const std::vector<std::string>& ids, const std::string& title) {
    if (ids.empty()) return;
    out += "## " + title + "\n\n";
    for (const auto& co : run.clauses) {
      if (!co.finding) continue;
      if (std::find(ids.begin(), ids.end(), std::string(co.clause->id)) == ids.end()) continue;
      const std::string file = (std::filesystem::path(ctx.run_dir) / counterexample_path(co)).string();
      out += fmt::format("### {} ({}) — {}\n\n", co.clause->id, clause_level_name(co.clause->level), co.status);
      out += fmt::format("> {} ({})\n\n", co.clause->text, co.clause->source);
      out += fmt::format("Suite's reading: {}\n\n", co.clause->reading);
      out += fmt::format("**Finding:** {}\n\n", co.finding->message);
      if (ctx.baseline && ctx.baseline->reasons.count(std::string(co.clause->id)))
        out += fmt::format("Baseline says: {}\n\n", ctx.baseline->reasons.at(std::string(co.clause->id)));
      out += fmt::format("Shrunk counterexample ({} commands, from a fresh node; found by `{}`, seed {}):\n\n```\n{}```\n\n",
                         co.program.commands.size(), co.found_by, co.seed, print_program(co.program));
      out += fmt::format("Replay: `{}`\n\n", replay_command(file, ctx.implementation_spec));
    }
  };
  section(v.new_failures, "Failures");
  section(v.known_failures, "Known deviations (in the baseline)");
  section(v.should_failures, "SHOULD clauses not met (the verdict stands)");
  if (!v.stale_baseline.empty()) {
    out += "## Baseline entries that now pass — remove them\n\n";
    for (const auto& id : v.stale_baseline) out += "- " + id + "\n";
    out += "\n";
  }
  out += "## Clauses\n\n| clause | level | status |\n|---|---|---|\n";
  for (const auto& co : run.clauses)
    out += fmt::format("| {} | {} | {}{} |\n", co.clause->id, clause_level_name(co.clause->level), co.status,
                       co.note.empty() ? "" : " (" + co.note + ")");
  out += "\n## Properties\n\n| property | status | cases | seed | seconds |\n|---|---|---|---|---|\n";
  for (const auto& p : run.properties)
    out += fmt::format("| {} | {}{} | {} | {} | {:.2f} |\n", p.id, p.status, p.note.empty() ? "" : " (" + p.note + ")",
                       p.cases, p.seed, p.seconds);
  return out;
}

}  // namespace vgc
