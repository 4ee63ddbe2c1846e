// merge_runs.cpp — see merge_runs.h.
#include "merge_runs.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "clause.h"
#include "command_text.h"
#include "property.h"

namespace vgc {
namespace {

using nlohmann::json;

FindingStatus status_named(const std::string& s) {
  if (s == "crash") return FindingStatus::Crash;
  if (s == "timeout") return FindingStatus::Timeout;
  return FindingStatus::Fail;
}

int property_index(const std::string& id) {
  const auto& props = property_catalog();
  for (std::size_t i = 0; i < props.size(); ++i)
    if (props[i].id == id) return static_cast<int>(i);
  return static_cast<int>(props.size());
}

bool read_reports(const std::vector<std::string>& dirs, std::vector<json>* out, std::string* error) {
  for (const auto& d : dirs) {
    const std::string path = (std::filesystem::path(d) / "report.json").string();
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      *error = "cannot read " + path + ": give the run directories of the shards (reports/<impl>/<run>)";
      return false;
    }
    std::stringstream ss;
    ss << in.rdbuf();
    json j = json::parse(ss.str(), nullptr, false);
    if (j.is_discarded() || !j.contains("clauses") || !j.contains("shard")) {
      *error = path + " is not a vgc certify report.json";
      return false;
    }
    out->push_back(std::move(j));
  }
  return true;
}

// Same run but the shard; every shard 1..N exactly once.
bool check_shards(const std::vector<json>& reports, const std::vector<std::string>& dirs, std::string* error) {
  for (const char* key : {"seed", "cases_per_property", "max_size", "budget_seconds", "clauses_selected",
                          "implementation", "strict", "environment_prefix"}) {
    for (std::size_t i = 1; i < reports.size(); ++i)
      if (reports[i].value(key, json()) != reports[0].value(key, json())) {
        *error = "the runs differ in " + std::string(key) + ": " + dirs[0] + " has " + reports[0].value(key, json()).dump() +
                 ", " + dirs[i] + " has " + reports[i].value(key, json()).dump() + ": give the shards of one run";
        return false;
      }
  }
  int count = 0;
  std::map<int, std::string> seen;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    int k = 0, n = 0;
    if (std::sscanf(reports[i]["shard"].get<std::string>().c_str(), "%d/%d", &k, &n) != 2 || k < 1 || k > n) {
      *error = dirs[i] + ": unreadable shard " + reports[i]["shard"].dump();
      return false;
    }
    if (count && n != count) {
      *error = "the runs differ in their shard count: " + dirs[0] + " is one of " + std::to_string(count) + ", " +
               dirs[i] + " one of " + std::to_string(n);
      return false;
    }
    count = n;
    if (seen.count(k)) {
      *error = "shard " + std::to_string(k) + "/" + std::to_string(n) + " is given twice: " + seen[k] + " and " + dirs[i];
      return false;
    }
    seen[k] = dirs[i];
  }
  for (int k = 1; k <= count; ++k)
    if (!seen.count(k)) {
      *error = "shard " + std::to_string(k) + "/" + std::to_string(count) + " is missing: run it (--shard " +
               std::to_string(k) + "/" + std::to_string(count) + ") and give its run directory too";
      return false;
    }
  return true;
}

PropertyOutcome property_from(const json& p) {
  PropertyOutcome o;
  o.id = p.value("id", std::string());
  o.status = p.value("status", std::string());
  o.note = p.value("note", std::string());
  o.seed = p.value("seed", std::uint64_t{0});
  o.cases = p.value("cases", 0);
  o.cases_target = p.value("cases_target", 0);
  o.judged = p.value("judged", 0);
  o.set_aside = p.value("set_aside", 0);
  o.not_judged = p.value("not_judged", 0);
  o.rounds = p.value("rounds", 0);
  o.steps_taken_out = p.value("steps_taken_out", 0);
  o.seconds = p.value("seconds", 0.0);
  for (const auto& f : p.value("findings", json::array())) {
    PropertyFinding pf;
    pf.finding.clause = f.get<std::string>();
    o.findings.push_back(pf);
  }
  return o;
}

// The shard that ran a property (others list it as skipped "in shard ...").
void merge_properties(const std::vector<json>& reports, RunResult* run) {
  for (const PropertySpec& spec : property_catalog()) {
    const json* chosen = nullptr;
    for (const auto& r : reports)
      for (const auto& p : r["properties"])
        if (p.value("id", std::string()) == spec.id) {
          const bool elsewhere = p.value("status", std::string()) == "skipped" &&
                                 p.value("note", std::string()).rfind("in shard", 0) == 0;
          if (!chosen || !elsewhere) chosen = &p;
          if (!elsewhere) goto found;
        }
  found:
    if (chosen) {
      PropertyOutcome o = property_from(*chosen);
      if (o.status == "skipped" && o.note.rfind("in shard", 0) == 0) o.note = "no selected clause";
      run->properties.push_back(o);
    }
  }
}

ClauseOutcome clause_from(const Clause& clause, const json& c) {
  ClauseOutcome co;
  co.clause = &clause;
  co.status = c.value("status", std::string());
  co.note = c.value("note", std::string());
  co.exercised = c.value("exercised", 0L);
  for (const auto& p : c.value("properties", json::array())) co.properties.push_back(p.get<std::string>());
  if (c.contains("message")) {
    co.finding = Finding(std::string(clause.id), status_named(co.status), c["message"].get<std::string>());
    co.found_by = c.value("found_by", std::string());
    co.seed = c.value("seed", std::uint64_t{0});
    co.tolerated_from_start = c.value("tolerated_from_start", false);
    co.program_origin = c.value("program_origin", std::string());
    // What the implementation showed: report.html draws the finding from it.
    co.finding->shown_by = c.value("shown_by", std::string());
    co.finding->observed_document = c.value("observed_document", std::string());
    co.finding->expected_line = c.value("expected_line", std::string());
    co.finding->observed_line = c.value("observed_line", std::string());
    std::string text;
    for (const auto& line : c.value("counterexample_commands", json::array())) text += line.get<std::string>() + "\n";
    TextError e;
    parse_commands(text, &co.program.commands, &e);
    if (c.contains("capability_check")) {
      const auto& q = c["capability_check"];
      CapabilityRequest r{q.value("capability", std::string()), q.value("variant", 1), std::nullopt};
      if (q.contains("draw")) r.draw = q["draw"].get<std::uint32_t>();
      co.program.request = r;
    }
  }
  return co;
}

// Per clause, as the runner combines properties.
void merge_clauses(const std::vector<json>& reports, RunResult* run) {
  for (const Clause& clause : clause_catalog()) {
    std::vector<ClauseOutcome> seen;
    for (const auto& r : reports)
      for (const auto& c : r["clauses"])
        if (c.value("id", std::string()) == clause.id) seen.push_back(clause_from(clause, c));
    if (seen.empty()) continue;
    ClauseOutcome out = seen[0];
    const ClauseOutcome* found = nullptr;
    const ClauseOutcome* unchecked = nullptr;
    const ClauseOutcome* judged = nullptr;
    std::set<std::string> props;
    out.exercised = 0;
    for (const auto& co : seen) {
      out.exercised += co.exercised;
      for (const auto& p : co.properties) props.insert(p);
      if (co.finding && (!found || property_index(co.found_by) < property_index(found->found_by))) found = &co;
      if (co.status == "unchecked" && !unchecked) unchecked = &co;
      if (co.status != "skipped" && !judged) judged = &co;
    }
    const long exercised = out.exercised;
    if (found) out = *found;
    else if (unchecked) out = *unchecked;
    else if (judged) out = *judged;
    out.exercised = exercised;
    out.properties.clear();
    for (const PropertySpec& spec : property_catalog())
      if (props.count(std::string(spec.id))) out.properties.push_back(std::string(spec.id));
    run->clauses.push_back(out);
  }
}

}  // namespace

bool merge_runs(const std::vector<std::string>& run_dirs, MergedRun* out, std::string* error) {
  std::vector<json> reports;
  if (run_dirs.empty()) {
    *error = "give the run directories of every shard";
    return false;
  }
  if (!read_reports(run_dirs, &reports, error) || !check_shards(reports, run_dirs, error)) return false;
  const json& first = reports[0];
  RunResult& run = out->run;
  run.implementation = first.value("implementation_name", std::string());
  run.options.seed = first.value("seed", std::uint64_t{1});
  run.options.cases = first.value("cases_per_property", 0);
  run.options.max_size = first.value("max_size", 0);
  run.options.budget_seconds = first.value("budget_seconds", 0.0);
  run.options.clause_glob = first.value("clauses_selected", std::string("*"));
  run.route = first.value("route_limits", std::string());
  out->strict = first.value("strict", false);
  std::string started = first.value("started", std::string());
  for (const auto& r : reports) {
    run.seconds = std::max(run.seconds, r.value("seconds", 0.0));  // shards run side by side
    run.unreported_verdicts += r.value("unreported_verdicts", 0L);
    started = std::min(started, r.value("started", started));
    if (r.contains("preflight") && !run.preflight) {
      const auto& p = r["preflight"];
      run.preflight = Finding(p.value("clause", std::string()), status_named(p.value("status", std::string())),
                              p.value("message", std::string()));
    }
    const json kinds = r.value("command_kinds", json::object());
    for (const auto& [kind, k] : kinds.items()) {
      CommandKindCount& c = run.command_kinds[kind];
      c.sent += k.value("sent", 0L);
      c.applied += k.value("applied", 0L);
      const json rejected = k.value("rejected", json::object());
      for (const auto& [reason, n] : rejected.items()) c.rejected[reason] += n.get<long>();
    }
    // Each property ran in one shard: the rules its steps used add up.
    const json rules = r.value("rule_uses", json::object());
    for (const auto& [rule, n] : rules.items()) run.rule_uses[rule] += n.get<long>();
    for (const auto& c : r["clauses"])
      if (c.contains("baseline_reason"))
        out->baseline.reasons[c["id"].get<std::string>()] = c["baseline_reason"].get<std::string>();
    for (const auto& id : r.value("stale_baseline", json::array()))
      out->baseline.reasons.emplace(id.get<std::string>(), "");
    out->has_baseline = out->has_baseline || r.contains("baseline");
    if (r.contains("baseline")) out->ctx.baseline_path = r["baseline"].get<std::string>();
  }
  merge_properties(reports, &run);
  merge_clauses(reports, &run);
  run.conformant = true;
  run.complete = true;
  for (const auto& co : run.clauses) {
    if (co.finding && co.clause->level == ClauseLevel::Must) run.conformant = false;
    if (co.finding && co.finding->status != FindingStatus::Fail && co.clause->level != ClauseLevel::Should)
      run.conformant = false;
    if (co.status == "unchecked") run.complete = false;
  }
  for (const auto& p : run.properties)
    if (p.status == "stopped") run.complete = false;

  out->ctx.implementation_spec = first.value("implementation", std::string());
  // The shards' VGC_* variables (VGC_FAULT, ...), not merge's own, start the
  // replay commands (a report.json of before version 4 has none: merge's).
  if (first.contains("environment_prefix")) out->ctx.environment_prefix = first["environment_prefix"].get<std::string>();
  out->ctx.started = started;
  // The shard's re-run command without its --shard: the unsharded run.
  out->ctx.command_line = std::regex_replace(first.value("rerun", std::string()), std::regex(" --shard [0-9]+/[0-9]+"), "");
  return true;
}

}  // namespace vgc
