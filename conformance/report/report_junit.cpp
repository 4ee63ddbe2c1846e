// report_junit.cpp — junit.xml: one test suite per clause group, one test
// case per clause; failures carry the finding and the replay command.
// A test case is named by the clause id alone (stable: a CI's per-test
// history survives a change of level), the level is a property, and its
// time is its share of the time of the properties that judged it (each
// property's seconds split evenly over the clauses it declares).
#include <pugixml.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>

#include "html_page.h"
#include "report.h"

namespace vgc {

namespace {

// The clause's other findings (ClauseOutcome::other_findings), each with
// its replay line; "" when it has none.
std::string other_findings_text(const ClauseOutcome& co, const ReportContext& ctx) {
  std::string out;
  for (const ClauseOutcome& other : co.other_findings)
    out += "\n" + std::string(co.clause->id) + ", another finding (another difference): " + other.finding->message +
           "\nFound by " + other.found_by + " (seed " + std::to_string(other.seed) + ").\nReplay: " +
           replay_command((std::filesystem::path(ctx.run_dir) / counterexample_path(other)).string(), ctx) + "\n";
  return out;
}

}  // namespace

std::string render_junit(const RunResult& run, const Verdict& v, const ReportContext& ctx) {
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  auto suites = doc.append_child("testsuites");
  suites.append_attribute("name") = ("vgc certify " + ctx.implementation_spec).c_str();
  suites.append_attribute("time") = run.seconds;

  std::map<std::string, double> property_seconds;
  std::map<std::string, int> property_clauses;
  for (const auto& p : run.properties) property_seconds[p.id] = p.seconds;
  for (const ClauseOutcome& co : run.clauses)
    for (const auto& p : co.properties) ++property_clauses[p];
  auto clause_seconds = [&](const ClauseOutcome& co) {
    double t = 0;
    for (const auto& p : co.properties) t += property_seconds[p] / std::max(1, property_clauses[p]);
    return t;
  };

  std::map<std::string, pugi::xml_node> by_group;
  std::map<std::string, std::map<std::string, int>> counts;
  int tests = 0, failures = 0, errors = 0, skipped = 0;
  for (const ClauseOutcome& co : run.clauses) {
    const std::string group(co.clause->group);
    auto it = by_group.find(group);
    if (it == by_group.end()) {
      auto s = suites.append_child("testsuite");
      s.append_attribute("name") = ("vgc." + group).c_str();
      it = by_group.emplace(group, s).first;
    }
    auto tc = it->second.append_child("testcase");
    tc.append_attribute("classname") = ("vgc." + group).c_str();
    tc.append_attribute("name") = std::string(co.clause->id).c_str();
    tc.append_attribute("time") = clause_seconds(co);
    ++tests;
    ++counts[group]["tests"];
    const bool known = ctx.baseline && ctx.baseline->reasons.count(std::string(co.clause->id));
    auto props = tc.append_child("properties");
    auto level = props.append_child("property");
    level.append_attribute("name") = "level";
    level.append_attribute("value") = std::string(clause_level_name(co.clause->level)).c_str();
    auto exercised = props.append_child("property");
    exercised.append_attribute("name") = "exercised";
    exercised.append_attribute("value") = static_cast<long long>(co.exercised);
    auto status = props.append_child("property");
    status.append_attribute("name") = "status";
    status.append_attribute("value") = clause_status_name(co.status);
    if (co.finding && !known && finding_gates(co, v.strict)) {
      const bool is_error = co.status != ClauseStatus::Fail;  // crash / timeout
      auto f = tc.append_child(is_error ? "error" : "failure");
      f.append_attribute("type") = clause_status_name(co.status);
      f.append_attribute("message") = co.finding->message.c_str();
      std::ostringstream body;
      body << co.clause->text << "\n\nFound by " << co.found_by << " (seed " << co.seed << ").\nReplay: "
           << replay_command((std::filesystem::path(ctx.run_dir) / counterexample_path(co)).string(), ctx)
           << "\n" << other_findings_text(co, ctx);
      f.text().set(body.str().c_str());
      ++(is_error ? errors : failures);
      ++counts[group][is_error ? "errors" : "failures"];
    } else if (co.status == ClauseStatus::Skipped || co.status == ClauseStatus::NotClaimed ||
               co.status == ClauseStatus::Unchecked || co.status == ClauseStatus::NotApplicable ||
               (co.finding && known)) {
      auto s = tc.append_child("skipped");
      s.append_attribute("message") =
          (co.finding ? "known deviation (baseline): " + ctx.baseline->reasons.at(std::string(co.clause->id))
                      : co.status == ClauseStatus::Unchecked || co.status == ClauseStatus::NotApplicable
                          ? std::string(clause_status_name(co.status)) + ": " + co.note
                                                                                   : co.note)
              .c_str();
      ++skipped;
      ++counts[group]["skipped"];
    } else if (co.finding) {  // SHOULD, or a profile difference: reported, not failing
      tc.append_child("system-out").text().set(
          ((co.clause->level == ClauseLevel::Should ? "SHOULD not met: " : "profile difference (the spec is silent): ") +
           co.finding->message + "\n" + other_findings_text(co, ctx))
              .c_str());
    }
  }
  for (auto& [group, node] : by_group) {
    node.append_attribute("tests") = counts[group]["tests"];
    node.append_attribute("failures") = counts[group]["failures"];
    node.append_attribute("errors") = counts[group]["errors"];
    node.append_attribute("skipped") = counts[group]["skipped"];
  }
  suites.append_attribute("tests") = tests;
  suites.append_attribute("failures") = failures;
  suites.append_attribute("errors") = errors;
  suites.append_attribute("skipped") = skipped;
  escape_unprintable_tree(doc);  // XML 1.0 has no way to write a control byte
  std::ostringstream out;
  doc.save(out, "  ");
  return out.str();
}

}  // namespace vgc
