// report_html.cpp — report.html: the report to look at. One self-contained
// file (no script, no network, no external style or font; a
// Content-Security-Policy that forbids loading anything), readable from
// disk: the verdict and counts first, then each failure with its spec
// sentence, the suite's reading, expected and observed, a picture of the
// counterexample's final mesh (finding_picture.h, svg_mesh.h), its commands
// and the replay command; then the clause table with statuses in colour.
//
// Spec: none (reporting); the content is summary.md's (report_summary.cpp),
// docs/certify.md describes the page.
#include <pugixml.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>

#include "finding_cause.h"
#include "finding_picture.h"
#include "html_page.h"
#include "program_text.h"
#include "report.h"
#include "report_sections.h"
#include "svg_mesh.h"

namespace vgc {
namespace {

constexpr int kPictureWidth = 640;
constexpr int kPictureHeight = 440;


pugi::xml_node add(pugi::xml_node parent, const char* name, const std::string& text = {}, const char* cls = nullptr) {
  auto e = parent.append_child(name);
  if (cls) e.append_attribute("class") = cls;
  if (!text.empty()) e.text().set(text.c_str());
  return e;
}

void add_text(pugi::xml_node parent, const std::string& text) {
  parent.append_child(pugi::node_pcdata).set_value(text.c_str());
}

// The status a person should see for a clause: profile differences, known
// (baseline) and SHOULD failures named as such.
struct ShownStatus {
  std::string text, css;
};

bool in(const std::vector<std::string>& ids, const std::string& id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// The words are verdict.h's shown_status, the same in every report; the
// colour follows its qualifier.
ShownStatus shown_status_of(const ClauseShown& shown) {
  const std::string text = shown_status_name(shown);
  switch (shown.qualifier) {
    case ShownQualifier::ProfileDifference: return {text, "st-profile-difference"};
    case ShownQualifier::Baseline: return {text, "st-known"};
    case ShownQualifier::Should: return {text, "st-should"};
    case ShownQualifier::None: break;
  }
  return {text, "st-" + text};
}

ShownStatus shown_status_html(const ClauseOutcome& co, const Verdict& v) { return shown_status_of(clause_shown(co, v)); }

void status_badge(pugi::xml_node parent, const ShownStatus& s) {
  add(parent, "span", s.text, ("st " + s.css).c_str());
}

void legend(pugi::xml_node parent, const FindingPicture& fp) {
  auto ul = add(parent, "ul", {}, "legend");
  auto item = [&](const char* colour, const std::string& mark, const std::string& what) {
    auto li = add(ul, "li");
    auto sw = add(li, "span", mark, "sw");
    sw.append_attribute("style") = (std::string("color: ") + colour).c_str();
    add_text(li, " " + what);
  };
  const MeshPicture& p = fp.picture;
  item(kEdgeColour, "\xE2\x96\xA1", "the polygons of the final state (ids p…), vertices labelled with their ids");
  if (!p.highlight_vertices.empty() || !p.highlight_faces.empty() || !p.highlight_edges.empty())
    item(kHighlightColour, "\xE2\x96\xA0", "what the finding is about");
  if (!p.observed_marks.empty() || !p.observed_outlines.empty())
    item(kObservedColour, "\xE2\x9C\x95", "what the implementation has instead");
  if (!p.expected_points.empty()) item(kExpectedColour, "\xE2\x97\x8B", "expected refined points");
  if (!p.observed_points.empty()) item(kObservedColour, "\xE2\x97\x8F", "the implementation's refined points");
  if (!p.divergent_expected.empty())
    item(kHighlightColour, "\xE2\x97\x8B", "expected points the implementation has no point near");
  if (!p.divergent_observed.empty())
    item(kObservedColour, "\xE2\x9C\x95", "the implementation's points that match no expected one");
  if (!p.expected_segments.empty())
    item(kExpectedColour, "\xE2\x80\x94", "expected normals, and the implementation's (dashed, orange)");
}

// What the implementation did: the finding's message and the first
// differing lines.
void what_it_did(pugi::xml_node sec, const Finding& f) {
  auto did = add(sec, "p");
  add(did, "strong", "What the implementation did: ");
  add_text(did, f.message);
  if (!f.expected_line.empty() || !f.observed_line.empty()) {
    auto t = add(sec, "table", {}, "expected-observed");
    auto r1 = add(t, "tr");
    add(r1, "th", "expected (" + f.shown_by + ")");
    add(add(r1, "td"), "code", f.expected_line.empty() ? "(no such line)" : f.expected_line);
    auto r2 = add(t, "tr");
    add(r2, "th", "observed");
    add(add(r2, "td"), "code", f.observed_line.empty() ? "(no such line)" : f.observed_line);
  }
  if (f.host_sent_seen) {  // the Verse wire: what the host sent back after the last command
    auto p = add(sec, "p");
    add(p, "strong", "What the host sent back after the last command: ");
    if (f.host_sent.empty()) {
      add_text(p, "nothing (no message for the node).");
    } else {
      add_text(p, "as vgc's mirror applied it, in order" +
                      (f.host_sent_count > f.host_sent.size()
                           ? ", the first " + std::to_string(f.host_sent.size()) + " of " +
                                 std::to_string(f.host_sent_count)
                           : std::string()) +
                      ":");
      auto list = add(sec, "ol", {}, "host-sent");
      for (const std::string& line : f.host_sent) add(add(list, "li"), "code", line);
    }
  }
}

// A finding's counterexample, linked to its file, and its replay line.
void counterexample_block(pugi::xml_node sec, const ClauseOutcome& co, const ReportContext& ctx) {
  const std::string file = (std::filesystem::path(ctx.run_dir) / counterexample_path(co)).string();
  auto h4 = add(sec, "h4");
  add_text(h4, counterexample_heading(co) + " — " + commands_counted(co.program.commands.size()) +
                   " from a fresh node; found by " + co.found_by +
                   (co.program_origin.empty() ? ", seed " + std::to_string(co.seed) : std::string()) + " (");
  auto link = add(h4, "a", counterexample_path(co));
  link.append_attribute("href") = counterexample_path(co).c_str();
  add_text(h4, ")");
  add(sec, "pre", inline_program(co), "program");
  add(sec, "h4", "Replay");
  add(sec, "pre", replay_command(file, ctx), "replay");
}

void finding_section(pugi::xml_node parent, const ClauseOutcome& co, const Verdict& v, const ReportContext& ctx,
                     const std::vector<CauseGroup>& groups) {
  const std::string id(co.clause->id);
  auto sec = add(parent, "section", {}, "finding");
  sec.append_attribute("id") = ("finding-" + id).c_str();
  auto h = add(sec, "h3");
  add_text(h, id + " (" + std::string(clause_level_name(co.clause->level)) + ") ");
  status_badge(h, shown_status_html(co, v));
  // A grouped finding names the others of its cause (as summary.md does),
  // each linked to its own section.
  if (const CauseGroup* g = cause_group_of(groups, id)) {
    auto p = add(sec, "p", {}, "one-cause");
    add_text(p, "One cause with ");
    bool first = true;
    for (const auto& c : g->clauses) {
      if (c == id) continue;
      if (!first) add_text(p, ", ");
      first = false;
      auto a = add(p, "a", c);
      a.append_attribute("href") = ("#finding-" + c).c_str();
    }
    add_text(p, " (");
    auto a = add(p, "a", "Findings with one cause");
    a.append_attribute("href") = "#cause-groups";
    add_text(p, " above).");
  }

  auto quote = add(sec, "blockquote");
  add_text(quote, std::string(co.clause->text) + " ");
  add(quote, "span", "(" + std::string(co.clause->source) + ")", "note");
  auto reading = add(sec, "p");
  add(reading, "strong", "Suite's reading: ");
  add_text(reading, std::string(co.clause->reading));
  what_it_did(sec, *co.finding);
  if (ctx.baseline && ctx.baseline->reasons.count(id)) {
    auto p = add(sec, "p");
    add(p, "strong", "Baseline says: ");
    add_text(p, ctx.baseline->reasons.at(id));
  }

  const FindingPicture fp = picture_of_finding(co);
  if (fp.has_mesh) {
    auto fig = add(sec, "figure");
    append_mesh_svg(fig, fp.picture, kPictureWidth, kPictureHeight);
    auto cap = add(fig, "figcaption");
    add_text(cap, fp.caption + " ");
    auto a = add(cap, "a", "Open the mesh: " + counterexample_obj_path(co));
    a.append_attribute("href") = counterexample_obj_path(co).c_str();
    add_text(cap, " (Wavefront OBJ, for Blender or MeshLab).");
    legend(fig, fp);
  } else {
    add(sec, "p", "The final state holds no vertex: nothing to draw.", "note");
  }

  counterexample_block(sec, co, ctx);
  // The clause's other findings (another difference of the same kind),
  // each with its own counterexample.
  for (const ClauseOutcome& other : co.other_findings) {
    auto oh = add(sec, "h4", id + ", another finding (" + clause_status_name(clause_status_of(other.finding->status)) +
                                 ": another difference)");
    oh.append_attribute("id") = ("finding-" + id + "." + std::to_string(other.part + 1)).c_str();
    what_it_did(sec, *other.finding);
    counterexample_block(sec, other, ctx);
  }
}

// render_report_html's parts, top to bottom.

// The headline, the counts as the reader will see the statuses in the
// table (the same counts as every other report: verdict.h), the run line,
// how to re-run, and the files next to the page.
void add_summary(pugi::xml_node body, const RunResult& run, const Verdict& v, const ReportContext& ctx,
                 const char* headline) {
  auto h1 = add(body, "h1");
  add_text(h1, "vgc certify: " + ctx.implementation_spec + " ");
  add(h1, "span", headline, ("verdict " + v.name).c_str());

  auto counts_p = add(body, "p", {}, "counts");
  add_text(counts_p, std::to_string(run.clauses.size()) + " clauses: ");
  for (const auto& [shown, n] : shown_counts(run, v)) {
    const ShownStatus s = shown_status_of(shown);
    add(counts_p, "span", std::to_string(n) + " " + s.text, ("st " + s.css).c_str());
  }
  std::ostringstream run_line;
  run_line.precision(1);
  run_line << std::fixed << "Seed " << run.options.seed << ", " << run.options.cases << " cases per property, "
           << run.seconds << " s" << (v.strict ? ", --strict (IMPLEMENTATION-DEFINED readings gate)" : "")
           << ". Started " << ctx.started << ". New failures: " << v.new_failures.size()
           << ". Known (baseline): " << v.known_failures.size()
           << ". Profile differences: " << v.profile_differences.size()
           << ". SHOULD not met: " << v.should_failures.size() << ". Unchecked: " << v.unchecked.size() << ".";
  add(body, "p", run_line.str());
  auto rerun = add(body, "p");
  add_text(rerun, "Re-run exactly: ");
  add(rerun, "code", ctx.command_line);
  auto files = add(body, "p", {}, "note");
  add_text(files, "Next to this page: ");
  for (const char* name : {"summary.md", "report.json", "junit.xml"}) {
    auto a = add(files, "a", name);
    a.append_attribute("href") = name;
    add_text(files, " ");
  }
}

// What could not be judged: a fresh node the implementation could not
// show, stopped properties, unchecked clauses.
void add_unjudged(pugi::xml_node body, const RunResult& run, const Verdict& v) {
  if (run.preflight)
    add(body, "p",
        "The implementation could not show a fresh node (" + run.preflight->clause + ": " + run.preflight->message +
            "); nothing else was judged.",
        "st st-fail");
  const bool incomplete = v.kind == VerdictKind::Incomplete;
  if (incomplete || !v.unchecked.empty()) {
    add(body, "p",
        incomplete ? "The run is incomplete: the verdict is neither a pass nor a failure."
                   : "Not everything could be judged:");
    auto ul = add(body, "ul");
    for (const auto& p : run.properties)
      if (p.status == PropertyStatus::Stopped) add(ul, "li", "property " + p.id + " stopped: " + p.note);
    for (const auto& co : run.clauses)
      if (co.status == ClauseStatus::Unchecked) add(ul, "li", "clause " + std::string(co.clause->id) + " is unchecked: " + co.note);
  }
}

// The findings, a section per kind of failure, then the stale baseline.
void add_findings(pugi::xml_node body, const RunResult& run, const Verdict& v, const ReportContext& ctx) {
  // Findings with one cause (finding_cause.h): the cause once, each
  // clause linked to its own finding below, its status unchanged.
  const std::vector<CauseGroup> groups = group_findings_by_cause(run);
  if (!groups.empty()) {
    add(body, "h2", report_section_title(ReportSection::CauseGroups)).append_attribute("id") = "cause-groups";
    auto ul = add(body, "ul", {}, "cause-groups");
    for (const auto& g : groups) {
      auto li = add(ul, "li");
      for (std::size_t i = 0; i < g.clauses.size(); ++i) {
        if (i) add_text(li, ", ");
        auto a = add(li, "a", g.clauses[i]);
        a.append_attribute("href") = ("#finding-" + g.clauses[i]).c_str();
      }
      std::string cause = g.cause;  // the markdown's code quotes, unquoted
      cause.erase(std::remove(cause.begin(), cause.end(), '`'), cause.end());
      add_text(li, ": " + cause + ".");
    }
  }
  auto section = [&](const std::vector<std::string>& ids, const std::string& heading, const std::string& intro) {
    if (ids.empty()) return;
    add(body, "h2", heading);
    if (!intro.empty()) add(body, "p", intro);
    for (const auto& co : run.clauses)
      if (co.finding && in(ids, std::string(co.clause->id))) finding_section(body, co, v, ctx, groups);
  };
  for (const FindingSection& s : finding_sections(v)) {
    std::string intro = report_section_intro(s.section);  // the markdown's code quotes, unquoted
    intro.erase(std::remove(intro.begin(), intro.end(), '`'), intro.end());
    section(*s.ids, report_section_title(s.section), intro);
  }
  if (!v.stale_baseline.empty()) {
    add(body, "h2", report_section_title(ReportSection::StaleBaseline));
    auto ul = add(body, "ul");
    for (const auto& id : v.stale_baseline) add(ul, "li", id);
  }
}

// The clause table, statuses in colour, a finding's clause linked to it.
void add_clause_table(pugi::xml_node body, const RunResult& run, const Verdict& v) {
  add(body, "h2", report_section_title(ReportSection::Clauses));
  auto table = add(body, "table", {}, "clauses");
  auto head = add(table, "tr");
  for (const char* c : {"clause", "group", "level", "status", "exercised", "note"}) add(head, "th", c);
  for (const auto& co : run.clauses) {
    auto tr = add(table, "tr");
    const std::string id(co.clause->id);
    auto td = add(tr, "td");
    if (co.finding) {
      auto a = add(td, "a", id);
      a.append_attribute("href") = ("#finding-" + id).c_str();
    } else {
      add_text(td, id);
    }
    add(tr, "td", std::string(co.clause->group));
    add(tr, "td", std::string(clause_level_name(co.clause->level)));
    status_badge(add(tr, "td"), shown_status_html(co, v));
    add(tr, "td", std::to_string(co.exercised));
    add(tr, "td", co.note);
  }
}

void add_property_table(pugi::xml_node body, const RunResult& run) {
  add(body, "h2", report_section_title(ReportSection::Properties));
  auto props = add(body, "table", {}, "properties");
  auto ph = add(props, "tr");
  for (const char* c : {"property", "status", "cases", "judged", "set aside", "not judged", "findings", "seed", "seconds"})
    add(ph, "th", c);
  for (const auto& p : run.properties) {
    auto tr = add(props, "tr");
    add(tr, "td", p.id);
    auto st = add(tr, "td");
    status_badge(st, {property_status_name(p.status), std::string("st-") + property_status_name(p.status)});
    if (!p.note.empty()) add_text(st, " " + p.note);
    add(tr, "td", std::to_string(p.cases) + "/" + std::to_string(p.cases_target));
    add(tr, "td", std::to_string(p.judged));
    add(tr, "td", std::to_string(p.set_aside));
    add(tr, "td", std::to_string(p.not_judged));
    std::string found;
    for (const auto& f : p.findings) found += (found.empty() ? "" : ", ") + f.finding.clause;
    add(tr, "td", found.empty() ? "-" : found);
    add(tr, "td", std::to_string(p.seed));
    std::ostringstream secs;
    secs.precision(2);
    secs << std::fixed << p.seconds;
    add(tr, "td", secs.str());
  }
}

}  // namespace

std::string counterexample_obj_path(const ClauseOutcome& co) {
  return "counterexamples/" + std::string(co.clause->id) + (co.part > 0 ? "." + std::to_string(co.part + 1) : "") +
         ".obj";
}

std::string render_report_html(const RunResult& run, const Verdict& v, const ReportContext& ctx) {
  const char* headline = verdict_kind_headline(v.kind);
  pugi::xml_document doc;
  auto title = doc.append_child("title");
  title.text().set(("vgc certify: " + ctx.implementation_spec + " — " + headline).c_str());
  auto body = doc.append_child("body");
  add_summary(body, run, v, ctx, headline);
  add_unjudged(body, run, v);
  add_findings(body, run, v, ctx);
  add_clause_table(body, run, v);
  add_property_table(body, run);
  return html_page(title, body);
}

}  // namespace vgc
