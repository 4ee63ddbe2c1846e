// campaign_html.cpp — see campaign_html.h.
#include "campaign_html.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <system_error>

#include "html_page.h"

namespace vgc {
namespace {

constexpr int kPlotWidth = 640;
constexpr int kPlotHeight = 220;
constexpr std::size_t kMaxPoints = 1000;

pugi::xml_node add(pugi::xml_node parent, const char* name, const std::string& text = {}, const char* cls = nullptr) {
  auto e = parent.append_child(name);
  if (cls) e.append_attribute("class") = cls;
  if (!text.empty()) e.text().set(text.c_str());
  return e;
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// At most kMaxPoints samples, evenly spread, the first and last kept.
std::vector<CampaignSample> thinned(const std::vector<CampaignSample>& s) {
  if (s.size() <= kMaxPoints) return s;
  std::vector<CampaignSample> out;
  for (std::size_t i = 0; i < kMaxPoints - 1; ++i) out.push_back(s[i * (s.size() - 1) / (kMaxPoints - 1)]);
  out.push_back(s.back());
  return out;
}

// One value over time as an SVG polyline with its axes: y from 0 to the
// largest value, x from 0 to the last sample's time.
void plot(pugi::xml_node parent, const std::vector<CampaignSample>& samples, const char* cls, const std::string& label,
          const char* colour, const std::function<long long(const CampaignSample&)>& value) {
  const double left = 60, right = 16, top = 24, bottom = 34;
  const double w = kPlotWidth - left - right, h = kPlotHeight - top - bottom;
  double t_max = 0;
  long long v_max = 0;
  for (const auto& s : samples) t_max = std::max(t_max, s.seconds), v_max = std::max(v_max, value(s));
  if (t_max <= 0) t_max = 1;
  if (v_max <= 0) v_max = 1;
  auto svg = parent.append_child("svg");
  svg.append_attribute("class") = (std::string("plot ") + cls).c_str();
  svg.append_attribute("width") = kPlotWidth;
  svg.append_attribute("height") = kPlotHeight;
  svg.append_attribute("viewBox") = ("0 0 " + std::to_string(kPlotWidth) + " " + std::to_string(kPlotHeight)).c_str();
  svg.append_attribute("role") = "img";
  auto bg = svg.append_child("rect");
  bg.append_attribute("width") = kPlotWidth;
  bg.append_attribute("height") = kPlotHeight;
  bg.append_attribute("fill") = "#ffffff";
  auto text = [&](double x, double y, const std::string& s, const char* anchor) {
    auto t = add(svg, "text", s);
    t.append_attribute("x") = fixed(x, 1).c_str();
    t.append_attribute("y") = fixed(y, 1).c_str();
    t.append_attribute("font-family") = "sans-serif";
    t.append_attribute("font-size") = "11";
    t.append_attribute("fill") = "#333333";
    t.append_attribute("text-anchor") = anchor;
  };
  auto axis = svg.append_child("polyline");
  axis.append_attribute("points") = (fixed(left, 1) + "," + fixed(top, 1) + " " + fixed(left, 1) + "," +
                                     fixed(top + h, 1) + " " + fixed(left + w, 1) + "," + fixed(top + h, 1))
                                        .c_str();
  axis.append_attribute("fill") = "none";
  axis.append_attribute("stroke") = "#888888";
  text(left - 6, top + 4, std::to_string(v_max), "end");
  text(left - 6, top + h + 4, "0", "end");
  text(left, top + h + 16, "0 s", "middle");
  text(left + w, top + h + 16, fixed(t_max, 0) + " s", "end");
  text(left + w / 2, top + h + 30, "time since the start", "middle");
  text(left, top - 8, label, "start");
  std::string pts;
  for (const auto& s : samples) {
    const double x = left + w * s.seconds / t_max;
    const double y = top + h - h * static_cast<double>(value(s)) / static_cast<double>(v_max);
    pts += (pts.empty() ? "" : " ") + fixed(x, 1) + "," + fixed(y, 1);
  }
  auto line = svg.append_child("polyline");
  line.append_attribute("class") = "series";
  line.append_attribute("points") = pts.c_str();
  line.append_attribute("fill") = "none";
  line.append_attribute("stroke") = colour;
  line.append_attribute("stroke-width") = "2";
  line.append_attribute("stroke-linejoin") = "round";
}

}  // namespace

std::string render_campaign_html(const CampaignReport& r) {
  pugi::xml_document doc;
  const bool found = !r.findings.empty();
  auto title = doc.append_child("title");
  title.text().set(("vgc fuzz " + r.target + " — " + r.run).c_str());
  auto body = doc.append_child("body");
  auto h1 = add(body, "h1");
  h1.append_child(pugi::node_pcdata).set_value(("vgc fuzz " + r.target + " ").c_str());
  add(h1, "span", found ? std::to_string(r.findings.size()) + " FINDING" + (r.findings.size() == 1 ? "" : "S")
                        : "NOTHING FOUND",
      found ? "verdict not-conformant" : "verdict conformant");

  auto table = add(body, "table", {}, "campaign");
  auto row = [&](const std::string& k, const std::string& v) {
    auto tr = add(table, "tr");
    add(tr, "th", k);
    add(tr, "td", v);
  };
  row("run", r.run);
  row("implementation", r.implementation);
  row("seed, jobs, time", std::to_string(r.seed) + ", " + std::to_string(r.jobs) + ", " + fixed(r.time_s, 0) +
                              " s (wall " + fixed(r.wall_s, 0) + " s)");
  row("executions", std::to_string(r.executions));
  row("exec/s", fixed(r.exec_per_s_mean, 0) + " mean, " + std::to_string(r.exec_per_s_last) + " last reported");
  row("coverage", "cov " + std::to_string(r.coverage) + ", ft " + std::to_string(r.features));
  row("corpus", std::to_string(r.corpus_files) + " files, " + std::to_string(r.corpus_bytes) + " bytes (" +
                    std::to_string(r.seed_files) + " seeds)");
  row("crash inputs", std::to_string(r.crash_inputs) + " (" + std::to_string(r.findings.size()) + " unique)");
  if (!r.implementation_coverage.empty()) row("implementation coverage", r.implementation_coverage);
  auto cmd = add(body, "p");
  cmd.append_child(pugi::node_pcdata).set_value("Command: ");
  add(cmd, "code", r.command);
  auto files = add(body, "p", {}, "note");
  files.append_child(pugi::node_pcdata).set_value("Next to this page: ");
  for (const char* name : {"summary.md", "summary.json", "fuzzer.log"}) {
    add(files, "a", name).append_attribute("href") = name;
    files.append_child(pugi::node_pcdata).set_value(" ");
  }

  add(body, "h2", "Coverage and corpus over time");
  const std::vector<CampaignSample> samples = thinned(r.samples);
  if (samples.size() < 2) {
    add(body, "p", "libFuzzer reported fewer than two status lines: nothing to plot.", "note");
  } else {
    plot(body, samples, "coverage", "coverage (cov: edges reached)", "#1f4e9e",
         [](const CampaignSample& s) { return s.coverage; });
    plot(body, samples, "corpus", "corpus size (inputs)", "#2e7d32", [](const CampaignSample& s) { return s.corpus; });
    add(body, "p",
        std::to_string(r.samples.size()) + " status lines of libFuzzer, from " + fixed(r.samples.front().seconds, 1) +
            " s to " + fixed(r.samples.back().seconds, 1) + " s.",
        "note");
  }
  if (r.implementation_samples.size() >= 2) {
    plot(body, thinned(r.implementation_samples), "implementation", "the implementation's own counters reached",
         "#8e24aa", [](const CampaignSample& s) { return s.coverage; });
    add(body, "p",
        "The implementation's counters reached (its own coverage, shared memory): the most any of the run's "
        "processes had reached by then; the summary's figure is the union at the end.",
        "note");
  }

  if (!r.function_report.empty()) {
    add(body, "h2", "The implementation's functions no input entered");
    auto p = add(body, "p");
    p.append_child(pugi::node_pcdata)
        .set_value((std::to_string(r.functions_never_entered_count) + " never entered" +
                    (r.functions_never_entered_count > r.functions_never_entered.size()
                         ? " (the first " + std::to_string(r.functions_never_entered.size()) + " by place below)"
                         : "") +
                    "; every function, entered or not, in ")
                       .c_str());
    add(p, "code", r.function_report);
    auto ul = add(body, "ul", {}, "functions");
    for (const std::string& f : r.functions_never_entered) add(ul, "li", f);
  }

  add(body, "h2", found ? "Findings" : "No findings");
  for (const auto& f : r.findings) {
    auto sec = add(body, "section", {}, "finding");
    add(sec, "h3", f.signature);
    add(sec, "p", std::to_string(f.inputs) + " crash input" + (f.inputs == 1 ? "" : "s") + " with this signature.");
    if (!f.also.empty()) {
      auto ul = add(sec, "ul");
      for (const auto& a : f.also) add(ul, "li", "also: " + a);
    }
    auto p = add(sec, "p");
    p.append_child(pugi::node_pcdata).set_value("Counterexample: ");
    add(p, "code", f.counterexample);
    if (!f.counterexample_text.empty())
      add(sec, "pre", f.counterexample_text.size() <= 20000 ? f.counterexample_text
                                                            : f.counterexample_text.substr(0, 20000) + "\n[...]\n",
          "program");
    add(sec, "h4", "Replay");
    add(sec, "pre", f.replay, "replay");
    add(sec, "h4", "Replay the fuzzer input");
    add(sec, "pre", f.replay_fuzzer, "replay");
  }
  return html_page(title, body);
}

bool write_campaign_html(const std::string& dir, const CampaignReport& report, std::string* error) {
  namespace fs = std::filesystem;
  const fs::path final_path = fs::path(dir) / "report.html";
  const fs::path tmp = fs::path(dir) / ".report.html.partial";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << render_campaign_html(report);
    out.close();
    if (!out) {
      *error = "cannot write " + tmp.string();
      std::error_code ignored;
      fs::remove(tmp, ignored);
      return false;
    }
  }
  std::error_code ec;
  fs::rename(tmp, final_path, ec);
  if (ec) {
    *error = "cannot move " + tmp.string() + " to " + final_path.string() + ": " + ec.message();
    fs::remove(tmp, ec);
    return false;
  }
  return true;
}

}  // namespace vgc
