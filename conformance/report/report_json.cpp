// report_json.cpp — report.json (docs/certify.md "What a run writes" lists every field;
// docs/diagnosing.md "report.json fields for diagnosis" says what each tells).
#include <nlohmann/json.hpp>

#include <filesystem>

#include "command_text.h"
#include "confirm_finding.h"  // finding_kind
#include "finding_cause.h"
#include "finding_picture.h"
#include "report.h"
#include "version.h"

namespace vgc {

namespace {

using nlohmann::json;

// The run as a whole: what was certified, how, the verdict and its lists.
void add_run_fields(json& j, const RunResult& run, const Verdict& v, const ReportContext& ctx) {
  j["vgc_report_version"] = kReportFormatVersion;
  j["implementation"] = ctx.implementation_spec;
  if (!ctx.implementation_identity.empty()) j["implementation_identity"] = ctx.implementation_identity;
  j["implementation_name"] = run.implementation;
  j["merge_identity"] = ctx.merge_identity.empty() ? ctx.implementation_spec : ctx.merge_identity;
  j["verdict"] = v.name;
  j["exit_code"] = v.exit_code;
  if (!run.cancelled_by.empty()) j["cancelled_by"] = run.cancelled_by;  // cancelled: what was found so far
  j["started"] = ctx.started;
  j["seconds"] = run.seconds;
  j["seed"] = run.options.seed;
  j["cases_per_property"] = run.options.cases;
  j["max_size"] = run.options.max_size;
  j["budget_seconds"] = run.options.budget_seconds;
  j["clauses_selected"] = run.options.clause_glob;
  j["shard"] = std::to_string(run.options.shard_index + 1) + "/" + std::to_string(run.options.shard_count);
  j["rerun"] = ctx.command_line;
  j["new_failures"] = v.new_failures;
  j["known_failures"] = v.known_failures;
  j["should_failures"] = v.should_failures;
  j["stale_baseline"] = v.stale_baseline;
  j["profile_differences"] = v.profile_differences;
  j["unchecked"] = v.unchecked;
  j["strict"] = v.strict;
  j["unreported_verdicts"] = run.unreported_verdicts;
  if (!run.avoided_classes.empty()) j["avoided_classes"] = run.avoided_classes;
  // A route that cannot show every clause (RouteLimits): its clauses are
  // `not-applicable` with notes naming it.
  if (!run.route.empty()) j["route_limits"] = run.route;
  if (run.preflight)
    j["preflight"] = {{"clause", run.preflight->clause},
                      {"status", finding_status_name(run.preflight->status)},
                      {"message", run.preflight->message}};
  if (ctx.baseline) j["baseline"] = ctx.baseline_path;
  // The VGC_* variables of the run, as the replay commands start with them.
  j["environment_prefix"] = ctx.environment_prefix.value_or(vgc_environment_prefix());
}

// Per shown status (verdict.h), the same counts as stdout, summary.md and
// report.html: "fail" is a failure that gates; a SHOULD one is counted
// under "fail (SHOULD)", a baselined one under "fail (baseline)", an
// IMPLEMENTATION-DEFINED one without --strict under "profile difference".
json shown_counts_json(const RunResult& run, const Verdict& v) {
  json counts = {{"pass", 0},      {"fail", 0},           {"crash", 0},       {"timeout", 0},
                 {"unchecked", 0}, {"not-applicable", 0}, {"not-claimed", 0}, {"skipped", 0}};
  for (const auto& [status, n] : shown_status_counts(run, v)) counts[status] = n;
  return counts;
}

// A clause's finding: its message, counterexample and replay, and what the
// implementation showed.
void add_finding_fields(json& c, const ClauseOutcome& co, const ReportContext& ctx) {
  const std::string file = counterexample_path(co);
  c["message"] = co.finding->message;
  c["found_by"] = co.found_by;
  c["seed"] = co.seed;
  c["counterexample"] = file;
  // The final mesh (report.html draws it), when the final state holds one.
  if (picture_of_finding(co).has_mesh) c["counterexample_mesh"] = counterexample_obj_path(co);
  json lines = json::array();
  for (const auto& cmd : co.program.commands) lines.push_back(print_command(cmd));
  c["counterexample_commands"] = lines;
  if (co.tolerated_from_start) c["tolerated_from_start"] = true;
  c["kind"] = finding_kind(*co.finding);  // read back by vgc merge: the finding's kind is no longer in its message alone
  if (co.program.history_kind) c["history_kind"] = finding_kind_name(*co.program.history_kind);
  if (!co.program_origin.empty()) c["program_origin"] = co.program_origin;
  // What the implementation showed (report.html's picture is drawn from
  // it; `vgc merge` reads it back): the document or capability request,
  // its whole text, the first differing lines.
  const Finding& f = *co.finding;
  if (!f.shown_by.empty()) c["shown_by"] = f.shown_by;
  // (Up to 4 MiB: an answer about a user's whole mesh, certify --mesh, can
  // be far larger; report.html then draws that finding from the run itself.)
  if (!f.observed_document.empty() && f.observed_document.size() <= (4u << 20))
    c["observed_document"] = f.observed_document;
  if (!f.expected_line.empty()) c["expected_line"] = f.expected_line;
  if (!f.observed_line.empty()) c["observed_line"] = f.observed_line;
  if (f.host_sent_seen) {  // the Verse wire: what the host sent back after the last command
    c["host_sent"] = f.host_sent;
    c["host_sent_count"] = f.host_sent_count;
  }
  if (!f.difference.empty()) c["difference"] = f.difference;
  if (co.program.request) {  // the capability check vgc replay repeats after the commands
    c["capability_check"] = {{"capability", co.program.request->capability},
                             {"variant", co.program.request->variant}};
    if (co.program.request->draw) c["capability_check"]["draw"] = *co.program.request->draw;
  }
  c["replay"] = replay_command((std::filesystem::path(ctx.run_dir) / file).string(), ctx);
}

json clause_json(const ClauseOutcome& co, const Verdict& v, const ReportContext& ctx) {
  json c;
  c["id"] = co.clause->id;
  c["group"] = co.clause->group;
  c["level"] = clause_level_name(co.clause->level);
  c["status"] = clause_status_name(co.status);
  c["shown_status"] = shown_status(co, v);
  c["properties"] = co.properties;
  c["exercised"] = co.exercised;
  if (co.derived_only > 0) c["derived_only"] = co.derived_only;
  if (!co.route_limit.empty()) c["route_limit"] = co.route_limit;
  if (!co.note.empty()) c["note"] = co.note;
  if (ctx.baseline && ctx.baseline->reasons.count(std::string(co.clause->id)))
    c["baseline_reason"] = ctx.baseline->reasons.at(std::string(co.clause->id));
  if (co.finding) add_finding_fields(c, co, ctx);
  // The clause's other findings (ClauseOutcome::other_findings), each with
  // the fields of the one shown and its own status.
  for (const ClauseOutcome& other : co.other_findings) {
    json o;
    o["status"] = clause_status_name(clause_status_of(other.finding->status));
    add_finding_fields(o, other, ctx);
    c["other_findings"].push_back(o);
  }
  return c;
}

json property_json(const PropertyOutcome& p) {
  json o = {{"id", p.id},         {"status", property_status_name(p.status)},           {"seed", p.seed},
            {"cases", p.cases},   {"cases_target", p.cases_target}, {"judged", p.judged},
            {"set_aside", p.set_aside}, {"steps_taken_out", p.steps_taken_out}, {"not_judged", p.not_judged}, {"rounds", p.rounds},     {"seconds", p.seconds}};
  if (!p.note.empty()) o["note"] = p.note;
  if (p.skip != PropertySkip::None) o["skip"] = property_skip_name(p.skip);
  json found = json::array();
  for (const auto& f : p.findings) found.push_back(f.finding.clause);
  o["findings"] = found;
  return o;
}

}  // namespace

std::string render_report_json(const RunResult& run, const Verdict& v, const ReportContext& ctx) {
  json j;
  // 2: exercised counts, unchecked, findings per property, command lines;
  // 3: counts per shown status (verdict.h), each clause's shown_status.
  add_run_fields(j, run, v, ctx);
  json clauses = json::array();
  for (const ClauseOutcome& co : run.clauses) clauses.push_back(clause_json(co, v, ctx));
  j["counts"] = shown_counts_json(run, v);
  j["clauses"] = clauses;
  // Findings of several clauses with one cause (finding_cause.h): the
  // cause once, the clauses' statuses as they are above.
  json groups = json::array();
  for (const CauseGroup& g : group_findings_by_cause(run)) groups.push_back({{"cause", g.cause}, {"clauses", g.clauses}});
  j["cause_groups"] = groups;
  json props = json::array();
  for (const PropertyOutcome& p : run.properties) props.push_back(property_json(p));
  j["properties"] = props;
  json kinds = json::object();
  for (const auto& [kind, k] : run.command_kinds)
    kinds[kind] = {{"sent", k.sent}, {"applied", k.applied}, {"rejected", k.rejected}};
  j["command_kinds"] = kinds;
  json rules = json::object();
  for (const auto& [rule, n] : run.rule_uses) rules[rule] = n;
  j["rule_uses"] = rules;
  // Invalid UTF-8 from an implementation becomes U+FFFD instead of an exception.
  return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace vgc
