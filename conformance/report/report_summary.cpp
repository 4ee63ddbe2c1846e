// report_summary.cpp — summary.md, the file a person reads first.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "command_text.h"
#include "finding_cause.h"
#include "program_text.h"
#include "report.h"
#include "report_sections.h"
#include "rule_clauses.h"

namespace vgc {

namespace {

// The Verse wire: what the host sent back after the counterexample's last
// command, as vgc's mirror applied it (Finding::host_sent); empty on
// routes that answer for themselves.
std::string host_sent_paragraph(const Finding& f) {
  if (!f.host_sent_seen) return {};
  if (f.host_sent.empty()) return "**What the host sent back after the last command:** nothing.\n\n";
  std::string out = "**What the host sent back after the last command** (as vgc's mirror applied it";
  if (f.host_sent_count > f.host_sent.size())
    out += fmt::format(", the first {} of {}", f.host_sent.size(), f.host_sent_count);
  out += "):\n\n```\n";
  for (const std::string& line : f.host_sent) out += line + "\n";
  return out + "```\n\n";
}

// The headline, the tallies, the re-run line and the route's limits.
void write_summary_head(const RunResult& run, const Verdict& v, const ReportContext& ctx, std::string& out) {
  const char* headline = verdict_kind_headline(v.kind);
  out += fmt::format("# vgc certify: {} — {}\n\n", ctx.implementation_spec, headline);
  const std::string tally = shown_status_tally(run, v);  // the same counts as every other report
  out += fmt::format("{} clauses: {}. Seed {}, {} cases per property, {:.1f} s{}.\n\n", run.clauses.size(), tally,
                     run.options.seed, run.options.cases, run.seconds,
                     v.strict ? ", --strict (IMPLEMENTATION-DEFINED readings gate)" : "");
  out += fmt::format("New failures: {}. Known (baseline): {}. Profile differences: {}. SHOULD not met: {}. "
                     "Unchecked: {}.\n\n",
                     v.new_failures.size(), v.known_failures.size(), v.profile_differences.size(),
                     v.should_failures.size(), v.unchecked.size());
  if (!ctx.implementation_identity.empty() && ctx.implementation_identity != ctx.implementation_spec)
    out += "Implementation: " + ctx.implementation_identity + "\n\n";
  out += "Re-run exactly: `" + ctx.command_line + "`\n\n";
  if (!run.route.empty()) {
    std::string ids;
    for (const auto& co : run.clauses)
      if (co.status == ClauseStatus::NotApplicable) ids += (ids.empty() ? "" : ", ") + std::string(co.clause->id);
    if (!ids.empty())
      out += fmt::format("Not judgeable over {} (not-applicable; the clause table says why for each): {}.\n\n",
                         run.route, ids);
    else  // a declared profile of words this vgc does not know (declared_profile.h): named all the same
      out += fmt::format("Route: {}.\n\n", run.route);
  }
}

// What could not be judged: avoided classes, a failed preflight, stopped
// properties and unchecked clauses.
void write_summary_unjudged(const RunResult& run, const Verdict& v, std::string& out) {
  if (!run.avoided_classes.empty()) {
    out += "Classes of input that cost a time-out, found once and not drawn again:\n\n";
    for (const auto& note : run.avoided_classes) out += "- " + note + "\n";
    out += "\n";
  }
  if (run.preflight)
    out += fmt::format("**The implementation could not show a fresh node** ({}: {}); nothing else was judged.\n\n",
                       run.preflight->clause, run.preflight->message);
  const bool incomplete = v.kind == VerdictKind::Incomplete;
  if (incomplete || !v.unchecked.empty()) {
    out += incomplete ? "The run is incomplete: the verdict is neither a pass nor a failure.\n\n"
                      : "Not everything could be judged:\n\n";
    for (const auto& p : run.properties)
      if (p.status == PropertyStatus::Stopped) out += fmt::format("- property `{}` stopped: {}\n", p.id, p.note);
    for (const auto& co : run.clauses)
      if (co.status == ClauseStatus::Unchecked) out += fmt::format("- clause {} is unchecked: {}\n", co.clause->id, co.note);
    out += "\n";
  }
}

// Findings with one cause (finding_cause.h), said once before the
// findings; each grouped finding points here.
void write_summary_cause_groups(const std::vector<CauseGroup>& groups, std::string& out) {
  if (groups.empty()) return;
  out += fmt::format("## {}\n\n", report_section_title(ReportSection::CauseGroups));
  for (const auto& g : groups) {
    std::string ids;
    for (const auto& c : g.clauses) ids += (ids.empty() ? "" : ", ") + c;
    out += fmt::format("- **{}**: {}. Each clause keeps its own status below.\n", ids, g.cause);
  }
  out += "\n";
}

// A finding's counterexample and its replay line.
void write_summary_counterexample(const ClauseOutcome& co, const ReportContext& ctx, std::string& out) {
  const std::string file = (std::filesystem::path(ctx.run_dir) / counterexample_path(co)).string();
  const std::string drawn = co.program_origin.empty() ? fmt::format(", seed {}", co.seed) : "";
  out += fmt::format("{} ({}, from a fresh node; found by `{}`{}):\n\n```\n{}```\n\n", counterexample_heading(co),
                     commands_counted(co.program.commands.size()), co.found_by, drawn, inline_program(co));
  out += fmt::format("Replay: `{}`\n\n", replay_command(file, ctx));
}

// One section of findings: each clause in ids that has a finding, with
// its counterexample and replay line.
void write_summary_findings(const RunResult& run, const Verdict& v, const ReportContext& ctx,
                            const std::vector<CauseGroup>& groups, const std::vector<std::string>& ids,
                            const std::string& title, const std::string& intro, std::string& out) {
  if (ids.empty()) return;
  out += "## " + title + "\n\n";
  if (!intro.empty()) out += intro + "\n\n";
  for (const auto& co : run.clauses) {
    if (!co.finding) continue;
    if (std::find(ids.begin(), ids.end(), std::string(co.clause->id)) == ids.end()) continue;
    out += fmt::format("### {} ({}) — {}\n\n", co.clause->id, clause_level_name(co.clause->level),
                       shown_status(co, v));
    if (const CauseGroup* g = cause_group_of(groups, std::string(co.clause->id))) {
      std::string others;
      for (const auto& c : g->clauses)
        if (c != co.clause->id) others += (others.empty() ? "" : ", ") + c;
      out += fmt::format("One cause with {} (\"Findings with one cause\" above).\n\n", others);
    }
    out += fmt::format("> {} ({})\n\n", co.clause->text, co.clause->source);
    out += fmt::format("Suite's reading: {}\n\n", co.clause->reading);
    out += fmt::format("**What the implementation did:** {}\n\n", co.finding->message);
    out += host_sent_paragraph(*co.finding);
    if (ctx.baseline && ctx.baseline->reasons.count(std::string(co.clause->id)))
      out += fmt::format("Baseline says: {}\n\n", ctx.baseline->reasons.at(std::string(co.clause->id)));
    write_summary_counterexample(co, ctx, out);
    for (const ClauseOutcome& other : co.other_findings) {
      out += fmt::format("#### {}, another finding ({}: another difference)\n\n", co.clause->id,
                         clause_status_name(clause_status_of(other.finding->status)));
      out += fmt::format("**What the implementation did:** {}\n\n", other.finding->message);
      out += host_sent_paragraph(*other.finding);
      write_summary_counterexample(other, ctx, out);
    }
  }
}

// The tables: clauses, properties, commands judged, rules used.
void write_summary_tables(const RunResult& run, const Verdict& v, std::string& out) {
  out += fmt::format("## {}\n\n| clause | level | status | exercised |\n|---|---|---|---|\n",
                     report_section_title(ReportSection::Clauses));
  for (const auto& co : run.clauses)
    out += fmt::format("| {} | {} | {}{} | {} |\n", co.clause->id, clause_level_name(co.clause->level), shown_status(co, v),
                       co.note.empty() ? "" : " (" + co.note + ")", co.exercised);
  out += "\n## " + std::string(report_section_title(ReportSection::Properties)) + "\n\n| property | status | cases | judged | set aside | not judged | findings | seed | seconds |\n"
         "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& p : run.properties) {
    std::string found;
    for (const auto& f : p.findings) found += (found.empty() ? "" : ", ") + f.finding.clause;
    out += fmt::format("| {} | {}{} | {}/{} | {} | {} | {} | {} | {} | {:.2f} |\n", p.id, property_status_name(p.status),
                       p.note.empty() ? "" : " (" + p.note + ")", p.cases, p.cases_target, p.judged, p.set_aside,
                       p.not_judged, found.empty() ? "-" : found, p.seed, p.seconds);
  }
  out += "\n## " + std::string(report_section_title(ReportSection::CommandsJudged)) + "\n\n| command | sent | applied | rejected |\n|---|---|---|---|\n";
  for (const auto& [kind, k] : run.command_kinds) {
    std::string rej;
    for (const auto& [reason, n] : k.rejected) rej += fmt::format("{}{} {}", rej.empty() ? "" : ", ", n, reason);
    out += fmt::format("| {} | {} | {} | {} |\n", kind, k.sent, k.applied, rej.empty() ? "-" : rej);
  }
  if (!run.rule_uses.empty()) {
    out += "\n## " + std::string(report_section_title(ReportSection::RulesUsed)) + "\n\nJudged uses of each rule of the reference node and of its derived document "
           "(docs/clauses.md lists a clause's rules): how often a judged step reached it.\n\n| rule | clause | judged uses |\n|---|---|---|\n";
    for (const auto& [rule, n] : run.rule_uses) out += fmt::format("| {} | {} | {} |\n", rule, rule_name_clause(rule), n);
  }
}

}  // namespace

std::string render_summary(const RunResult& run, const Verdict& v, const ReportContext& ctx) {
  std::string out;
  write_summary_head(run, v, ctx, out);
  write_summary_unjudged(run, v, out);
  const std::vector<CauseGroup> groups = group_findings_by_cause(run);
  write_summary_cause_groups(groups, out);
  auto findings = [&](const std::vector<std::string>& ids, const std::string& title, const std::string& intro) {
    write_summary_findings(run, v, ctx, groups, ids, title, intro, out);
  };
  for (const FindingSection& s : finding_sections(v))
    findings(*s.ids, report_section_title(s.section), report_section_intro(s.section));
  if (!v.stale_baseline.empty()) {
    out += fmt::format("## {}\n\n", report_section_title(ReportSection::StaleBaseline));
    for (const auto& id : v.stale_baseline) out += "- " + id + "\n";
    out += "\n";
  }
  write_summary_tables(run, v, out);
  return out;
}

}  // namespace vgc
