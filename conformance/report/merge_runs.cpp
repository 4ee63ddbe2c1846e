// merge_runs.cpp — see merge_runs.h.
#include "merge_runs.h"

#include <charconv>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "clause.h"
#include "clause_selection.h"
#include "clause_status.h"
#include "command_text.h"
#include "property.h"

namespace vgc {
namespace {

// "K/N" with 1 <= K <= N, read exactly (std::from_chars): a shard's place.
bool read_shard(const std::string& text, int* k, int* n) {
  const char* const last = text.data() + text.size();
  const auto [slash, ec1] = std::from_chars(text.data(), last, *k);
  if (ec1 != std::errc() || slash == last || *slash != '/') return false;
  const auto [end, ec2] = std::from_chars(slash + 1, last, *n);
  return ec2 == std::errc() && end == last && *k >= 1 && *k <= *n;
}

using nlohmann::json;

// A finding's status as report.json names it; a finding is at least a
// failure (not-judged, or a word this vgc does not know, reads as fail).
FindingStatus status_named(const std::string& s) {
  const std::optional<FindingStatus> status = finding_status_named(s);
  return status && *status != FindingStatus::NotJudged ? *status : FindingStatus::Fail;
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
  // The implementation is compared by its merge identity (report.json
  // format 5): shards of one Verse host release on different ports merge.
  const bool keyed = std::all_of(reports.begin(), reports.end(),
                                 [](const json& r) { return r.contains("merge_identity"); });
  for (const char* key : {"seed", "cases_per_property", "max_size", "budget_seconds", "clauses_selected",
                          keyed ? "merge_identity" : "implementation", "strict", "environment_prefix"}) {
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
    if (!read_shard(reports[i]["shard"].get<std::string>(), &k, &n)) {
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
  // An unknown status (a damaged report) counts as stopped: never a pass.
  o.status = property_status_named(p.value("status", std::string())).value_or(PropertyStatus::Stopped);
  o.note = p.value("note", std::string());
  o.skip = property_skip_named(p.value("skip", std::string()));
  if (o.status == PropertyStatus::Skipped && o.skip == PropertySkip::None && o.note.rfind("in shard", 0) == 0)
    o.skip = PropertySkip::OtherShard;  // a report.json of before format 5
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

// A property's cases are split over the shards (runner.cpp owns_case): its
// merged outcome adds up every shard's part. A shard that had none of its
// cases lists it as skipped (PropertySkip::OtherShard).
void merge_properties(const std::vector<json>& reports, RunResult* run) {
  for (const PropertySpec& spec : property_catalog()) {
    std::vector<PropertyOutcome> parts;
    std::optional<PropertyOutcome> skipped;
    for (const auto& r : reports)
      for (const auto& p : r["properties"])
        if (p.value("id", std::string()) == spec.id) {
          PropertyOutcome o = property_from(p);
          if (o.status != PropertyStatus::Skipped) parts.push_back(std::move(o));
          else if (!skipped || skipped->skip == PropertySkip::OtherShard) skipped = std::move(o);
        }
    if (parts.empty()) {
      if (!skipped) continue;
      if (skipped->skip == PropertySkip::OtherShard) skipped->note = "no selected clause", skipped->skip = PropertySkip::NotSelected;
      run->properties.push_back(*skipped);
      continue;
    }
    PropertyOutcome m = parts[0];
    for (std::size_t i = 1; i < parts.size(); ++i) {
      const PropertyOutcome& o = parts[i];
      m.cases += o.cases;
      m.cases_target += o.cases_target;
      m.judged += o.judged;
      m.set_aside += o.set_aside;
      m.not_judged += o.not_judged;
      m.rounds += o.rounds;
      m.steps_taken_out += o.steps_taken_out;
      m.seconds += o.seconds;
      m.findings.insert(m.findings.end(), o.findings.begin(), o.findings.end());
      if (o.status == PropertyStatus::Stopped && m.status != PropertyStatus::Stopped)
        m.status = PropertyStatus::Stopped, m.note = o.note;
    }
    if (m.status != PropertyStatus::Stopped) m.status = m.findings.empty() ? PropertyStatus::Pass : PropertyStatus::Fail;
    run->properties.push_back(std::move(m));
  }
}

ClauseOutcome clause_from(const Clause& clause, const json& c) {
  ClauseOutcome co;
  co.clause = &clause;
  // An unknown status (a damaged report) counts as unchecked: never a pass.
  co.status = clause_status_named(c.value("status", std::string())).value_or(ClauseStatus::Unchecked);
  co.note = c.value("note", std::string());
  co.exercised = c.value("exercised", 0L);
  co.derived_only = c.value("derived_only", 0L);
  co.route_limit = c.value("route_limit", std::string());
  for (const auto& p : c.value("properties", json::array())) co.properties.push_back(p.get<std::string>());
  if (c.contains("message")) {
    co.finding = Finding(std::string(clause.id), status_named(clause_status_name(co.status)), c["message"].get<std::string>());
    co.found_by = c.value("found_by", std::string());
    co.seed = c.value("seed", std::uint64_t{0});
    co.tolerated_from_start = c.value("tolerated_from_start", false);
    co.program_origin = c.value("program_origin", std::string());
    // What the implementation showed: report.html draws the finding from it.
    co.finding->shown_by = c.value("shown_by", std::string());
    co.finding->observed_document = c.value("observed_document", std::string());
    co.finding->expected_line = c.value("expected_line", std::string());
    co.finding->observed_line = c.value("observed_line", std::string());
    if (c.contains("host_sent")) {
      co.finding->host_sent_seen = true;
      for (const auto& line : c["host_sent"]) co.finding->host_sent.push_back(line.get<std::string>());
      co.finding->host_sent_count = c.value("host_sent_count", co.finding->host_sent.size());
    }
    co.finding->difference = c.value("difference", std::string());
    std::string text;
    for (const auto& line : c.value("counterexample_commands", json::array())) text += line.get<std::string>() + "\n";
    TextError e;
    parse_commands(text, &co.program.commands, &e);
    co.program.history_kind = finding_kind_named(c.value("history_kind", std::string()));
    co.finding->history_kind = co.program.history_kind;
    const std::optional<FindingKind> kind = finding_kind_named(c.value("kind", std::string()));
    co.finding->late_view = !co.program.history_kind && kind == FindingKind::HiddenState;
    co.finding->protocol_error = !co.program.history_kind && kind == FindingKind::ProtocolError;
    if (c.contains("capability_check")) {
      const auto& q = c["capability_check"];
      CapabilityRequest r{q.value("capability", std::string()), q.value("variant", 1), std::nullopt};
      if (q.contains("draw")) r.draw = q["draw"].get<std::uint32_t>();
      co.program.request = r;
    }
  }
  for (const auto& o : c.value("other_findings", json::array())) {
    ClauseOutcome other = clause_from(clause, o);
    other.part = static_cast<int>(co.other_findings.size()) + 1;
    co.other_findings.push_back(std::move(other));
  }
  return co;
}

// Per clause, as the runner decides one run (clause_status.h): the
// evidence of every shard added up, the merged properties, one ladder.
void merge_clauses(const std::vector<json>& reports, RunResult* run) {
  for (const Clause& clause : clause_catalog()) {
    std::vector<ClauseOutcome> seen;
    for (const auto& r : reports)
      for (const auto& c : r["clauses"])
        if (c.value("id", std::string()) == clause.id) seen.push_back(clause_from(clause, c));
    ClauseEvidence e;
    e.selected = clause_selected(run->options.clause_glob, clause.id);
    e.preflight = run->preflight;
    e.route = run->route;
    e.unreported_verdicts = run->unreported_verdicts;
    ClauseOutcome out;
    out.clause = &clause;
    int chosen_index = 0;
    for (const auto& co : seen) {
      e.exercised += co.exercised;
      e.derived_only += co.derived_only;
      if (!co.route_limit.empty()) e.route_limit = co.route_limit;
      if (co.finding &&
          prefer_finding(*co.finding, co.program, property_index(co.found_by), out.finding, out.program, chosen_index)) {
        chosen_index = property_index(co.found_by);
        out = co;
      }
    }
    if (run->preflight && run->preflight->clause == clause.id && !out.finding) {
      out.finding = run->preflight;
      out.found_by = "fresh-node check";
    }
    e.finding = out.finding;
    out.properties.clear();
    gather_clause_evidence(clause, run->properties, &e, &out.properties);
    out.exercised = e.exercised;
    out.derived_only = e.derived_only;
    out.route_limit = e.route_limit;
    const ClauseDecision d = decide_clause_status(clause, e);
    if (!d.status) continue;
    out.status = *d.status;
    out.note = d.note;
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
    for (const auto& note : r.value("avoided_classes", json::array())) run.avoided_classes.push_back(note.get<std::string>());
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
  summarize_run(&run);

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
