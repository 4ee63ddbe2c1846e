// report_json.cpp — report.json (docs/reports.md lists every field).
#include <nlohmann/json.hpp>

#include <filesystem>

#include "command_text.h"
#include "finding_picture.h"
#include "report.h"

namespace vgc {

std::string render_report_json(const RunResult& run, const Verdict& v, const ReportContext& ctx) {
  using nlohmann::json;
  json j;
  j["vgc_report_version"] = 2;  // 2: exercised counts, unchecked, findings per property, command lines
  j["implementation"] = ctx.implementation_spec;
  if (!ctx.implementation_identity.empty()) j["implementation_identity"] = ctx.implementation_identity;
  j["implementation_name"] = run.implementation;
  j["verdict"] = v.name;
  j["exit_code"] = v.exit_code;
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
  // A route that cannot show every clause (RouteLimits): its clauses are
  // `not-applicable` with notes naming it.
  if (!run.route.empty()) j["route_limits"] = run.route;
  if (run.preflight)
    j["preflight"] = {{"clause", run.preflight->clause},
                      {"status", finding_status_name(run.preflight->status)},
                      {"message", run.preflight->message}};
  if (ctx.baseline) j["baseline"] = ctx.baseline_path;

  json counts = {{"pass", 0},      {"fail", 0},           {"crash", 0},       {"timeout", 0},
                 {"unchecked", 0}, {"not-applicable", 0}, {"not-claimed", 0}, {"skipped", 0}};
  json clauses = json::array();
  for (const ClauseOutcome& co : run.clauses) {
    counts[co.status] = counts.value(co.status, 0) + 1;
    json c;
    c["id"] = co.clause->id;
    c["group"] = co.clause->group;
    c["level"] = clause_level_name(co.clause->level);
    c["status"] = co.status;
    c["properties"] = co.properties;
    c["exercised"] = co.exercised;
    if (!co.note.empty()) c["note"] = co.note;
    if (ctx.baseline && ctx.baseline->reasons.count(std::string(co.clause->id)))
      c["baseline_reason"] = ctx.baseline->reasons.at(std::string(co.clause->id));
    if (co.finding) {
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
      if (co.program.request) {  // the capability check vgc replay repeats after the commands
        c["capability_check"] = {{"capability", co.program.request->capability},
                                 {"variant", co.program.request->variant}};
        if (co.program.request->draw) c["capability_check"]["draw"] = *co.program.request->draw;
      }
      c["replay"] = replay_command((std::filesystem::path(ctx.run_dir) / file).string(), ctx.implementation_spec);
    }
    clauses.push_back(c);
  }
  j["counts"] = counts;
  j["clauses"] = clauses;

  json props = json::array();
  for (const PropertyOutcome& p : run.properties) {
    json o = {{"id", p.id},         {"status", p.status},           {"seed", p.seed},
              {"cases", p.cases},   {"cases_target", p.cases_target}, {"judged", p.judged},
              {"set_aside", p.set_aside}, {"not_judged", p.not_judged}, {"rounds", p.rounds},     {"seconds", p.seconds}};
    if (!p.note.empty()) o["note"] = p.note;
    json found = json::array();
    for (const auto& f : p.findings) found.push_back(f.finding.clause);
    o["findings"] = found;
    props.push_back(o);
  }
  j["properties"] = props;
  json kinds = json::object();
  for (const auto& [kind, k] : run.command_kinds)
    kinds[kind] = {{"sent", k.sent}, {"applied", k.applied}, {"rejected", k.rejected}};
  j["command_kinds"] = kinds;
  return j.dump(2) + "\n";
}

}  // namespace vgc
