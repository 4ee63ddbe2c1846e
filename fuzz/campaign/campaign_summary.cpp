// campaign_summary.cpp — a campaign's summary as JSON (summary.json) and
// Markdown (summary.md, and what `vgc fuzz` prints): see campaign.h.
//
// Spec: docs/fuzzing.md "Running a campaign" (the summary's fields).
#include "campaign.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "display_text.h"

namespace vgc::fuzz {

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
    return "not seen: a Verse host vgc did not start is not given the shared memory (start it with --host-cmd "
           "CMD); libFuzzer was guided by vgc's own code only";
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

}  // namespace vgc::fuzz
