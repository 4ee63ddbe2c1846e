// soak.cpp — see soak.h.
#include "soak.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "campaign.h"
#include "exec_implementation.h"  // shell_quote
#include "reaped_command.h"

namespace vgc::fuzz {
namespace {

namespace fs = std::filesystem;

std::size_t count_files(const fs::path& dir) {
  std::error_code ec;
  std::size_t n = 0;
  if (!fs::is_directory(dir, ec)) return 0;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.is_regular_file()) ++n;
  return n;
}

bool write_whole(const fs::path& file, const std::string& text) {
  fs::path tmp = file;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out) return false;
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  return !ec;
}

std::string with_commas(long long v) {
  std::string digits = std::to_string(v < 0 ? -v : v), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return v < 0 ? "-" + out : out;
}

std::size_t max_len_of(const std::string& name) {
  // As .clusterfuzzlite/build.sh's options: a mesh is at most 209 bytes.
  return name.rfind("mesh_", 0) == 0 ? 256 : 1024;
}

double time_of(const SoakOptions& o, const std::string& name) {
  auto it = o.target_time_s.find(name);
  return it != o.target_time_s.end() ? it->second : o.time_s;
}

// Merges the campaign's corpus into the work corpus: libFuzzer -merge=1
// adds to WORK only the inputs that bring coverage WORK does not have yet.
// Bounded by `timeout` (coreutils); its output goes to merge.log in the
// campaign's run directory.
bool merge_into_work(const fs::path& binary, const std::string& name, const fs::path& work, const fs::path& run_dir,
                     double limit_s) {
  const std::string cmd = fmt::format(
      "timeout -k 5 {} {} -merge=1 -timeout=10 -max_len={} {} {} >{} 2>&1", static_cast<long long>(limit_s),
      shell_quote(binary.string()), max_len_of(name), shell_quote(work.string()),
      shell_quote((run_dir / "corpus").string()), shell_quote((run_dir / "merge.log").string()));
  return run_reaped_shell(cmd, nullptr) == 0;
}

SoakRow run_one(const SoakOptions& o, const std::string& name, const fs::path& src, const fs::path& work_root,
                const fs::path& fbuild) {
  SoakRow row;
  row.target = "fuzz_" + name;
  row.time_s = time_of(o, name);
  const fs::path work = work_root / row.target;
  std::error_code ec;
  fs::create_directories(work, ec);
  CampaignOptions c;
  c.target = name;
  c.time_s = row.time_s;
  c.jobs = 1;
  c.seed = o.seed;
  c.max_len = max_len_of(name);
  c.fuzz_build = fbuild.string();
  c.source_dir = src.string();
  c.vgc_binary = o.vgc_binary;
  c.quiet = true;
  // Let the last fork-mode job end by itself (its inputs merged, its CPU
  // time counted): libFuzzer's job k runs min(300, k) s, and after T s of
  // jobs of 1, 2, 3, ... s the running one is about sqrt(2 T) s long.
  c.grace_s = std::min(300.0, std::ceil(std::sqrt(2 * row.time_s))) + 10;
  if (o.cpu_time) {
    // Stopped at its CPU budget; the wall clock only caps a starved run.
    c.cpu_time_s = row.time_s;
    c.time_s = row.time_s * o.wall_cap_factor;
  }
  c.progress = [](const std::string&) {};
  c.extra_corpora = {(src / "corpora" / "fuzz" / (row.target + "-crashes")).string(), work.string()};
  row.work_files_before = count_files(work);
  row.start_files = count_files(src / "corpora" / "fuzz" / row.target) + count_files(c.extra_corpora[0]) +
                    row.work_files_before;
  CampaignSummary s;
  row.campaign_exit = run_campaign(c, &s);
  if (s.run_dir.empty()) return row;  // the campaign did not run (its error is on stderr)
  row.run_dir = s.run_dir;
  row.wall_s = s.wall_s;
  row.cpu_s = s.cpu_s;
  row.executions = s.executions;
  row.cov = s.cov;
  row.ft = s.ft;
  row.crash_inputs = s.crash_inputs;
  row.killed = s.killed_at_deadline;
  row.cpu_budget_spent = s.cpu_budget_spent;
  row.findings = s.crashes.size();
  for (const CampaignCrash& k : s.crashes) row.signatures.push_back(k.signature);
  const auto merge_start = std::chrono::steady_clock::now();
  row.merged = merge_into_work(fbuild / "fuzz" / row.target, name, work, s.run_dir, std::max(120.0, row.time_s));
  row.merge_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - merge_start).count();
  row.work_files = count_files(work);
  return row;
}

}  // namespace

std::vector<std::string> soak_targets() {
  return {"verse_packet",       "text",           "stream",          "differential",     "mesh_manifold",
          "mesh_subdivision",   "property_layers", "property_polygons", "property_creases", "property_bones",
          "property_values",    "property_ids",   "property_commands"};
}

int run_soak(const SoakOptions& o, const std::string& command, SoakSummary* out) {
  using clock = std::chrono::steady_clock;
  const std::vector<std::string> all = soak_targets();
  std::vector<std::string> names = o.targets.empty() ? all : o.targets;
  for (std::string& n : names)
    if (n.rfind("fuzz_", 0) == 0) n = n.substr(5);
  for (const std::string& n : names)
    if (std::find(all.begin(), all.end(), n) == all.end()) {
      fmt::print(stderr, "vgc fuzz --all: unknown target '{}'\n", n);
      return 2;
    }
  for (const auto& [n, t] : o.target_time_s) {
    if (std::find(names.begin(), names.end(), n) == names.end()) {
      fmt::print(stderr, "vgc fuzz --all: --target-time names '{}', which this soak does not run\n", n);
      return 2;
    }
    if (!(t > 0)) {
      fmt::print(stderr, "vgc fuzz --all: --target-time {}: the time must be a positive number of seconds\n", n);
      return 2;
    }
  }
  if (!(o.time_s > 0) || o.jobs < 1) {
    fmt::print(stderr, "vgc fuzz --all: --time must be positive seconds and --jobs at least 1\n");
    return 2;
  }
  // Where the campaigns run: the same source and fuzz build `vgc fuzz` uses.
  CampaignOptions probe;
  probe.source_dir = o.source_dir;
  probe.fuzz_build = o.fuzz_build;
  const fs::path src = fs::absolute(campaign_source_dir(probe));
  const fs::path fbuild = fs::absolute(campaign_fuzz_build_dir(probe));
  const fs::path work_root = o.work_corpus.empty() ? src / "reports" / "fuzz" / "work-corpus" : fs::path(o.work_corpus);

  SoakSummary s;
  s.seed = o.seed;
  s.jobs = o.jobs;
  s.cpu_time = o.cpu_time;
  s.command = command;
  s.work_corpus = fs::absolute(work_root).string();
  const fs::path runs = src / "reports" / "fuzz" / "soak";
  std::error_code ec;
  fs::create_directories(runs, ec);
  const std::string stamp = utc_stamp() + "-seed" + std::to_string(o.seed);
  s.run = stamp;
  for (int k = 2; !ec && !fs::create_directory(runs / s.run, ec) && !ec; ++k) s.run = stamp + "-" + std::to_string(k);
  if (ec) {
    fmt::print(stderr, "vgc fuzz --all: cannot create a run directory under {}: {}\n", runs.string(), ec.message());
    return 2;
  }
  s.run_dir = (runs / s.run).string();

  // Longest first, so that the jobs end close together; the table keeps
  // soak_targets() order.
  std::vector<std::size_t> order(names.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return time_of(o, names[a]) > time_of(o, names[b]); });
  double total = 0;
  for (const std::string& n : names) total += time_of(o, n);
  fmt::print(stderr, "vgc fuzz --all: {} targets, {:.0f} {}s of fuzzing, {} at a time (about {:.0f} s{}), seed {}\n  run: {}\n",
             names.size(), total, o.cpu_time ? "CPU " : "", o.jobs, total / o.jobs,
             o.cpu_time ? " on an idle machine" : "", o.seed, s.run_dir);
  std::vector<SoakRow> rows(names.size());
  std::atomic<std::size_t> next{0};
  std::mutex print;
  const auto t0 = clock::now();
  auto worker = [&] {
    for (std::size_t k; (k = next++) < order.size();) {
      const std::size_t i = order[k];
      {
        std::lock_guard<std::mutex> lock(print);
        fmt::print(stderr, "vgc fuzz --all: [{}/{}] fuzz_{} for {:.0f} {}s\n", k + 1, order.size(), names[i],
                   time_of(o, names[i]), o.cpu_time ? "CPU " : "");
      }
      rows[i] = run_one(o, names[i], src, work_root, fbuild);
      const SoakRow& r = rows[i];
      std::lock_guard<std::mutex> lock(print);
      fmt::print(stderr, "vgc fuzz --all: {} done: {} executions, {:.0f} CPU s, cov {}, work corpus {}, {} finding(s){}\n",
                 r.target, r.executions, r.cpu_s, r.cov, r.work_files, r.findings,
                 r.campaign_exit == 2 ? " — the campaign failed, see above" : "");
    }
  };
  std::vector<std::thread> threads;
  for (int j = 0; j < std::min<int>(o.jobs, static_cast<int>(order.size())); ++j) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  s.wall_s = std::chrono::duration<double>(clock::now() - t0).count();
  s.rows = std::move(rows);

  const std::string md = soak_markdown(s);
  if (!write_whole(fs::path(s.run_dir) / "soak.json", soak_json(s)) ||
      !write_whole(fs::path(s.run_dir) / "soak.md", md)) {
    fmt::print(stderr, "vgc fuzz --all: cannot write the table into {}\n", s.run_dir);
    return 2;
  }
  fmt::print("{}", md);
  fmt::print("table: {}\n", (fs::path(s.run_dir) / "soak.md").string());
  if (out) *out = s;
  bool failed = false;
  std::size_t findings = 0;
  for (const SoakRow& r : s.rows) {
    failed = failed || r.campaign_exit == 2;
    findings += r.findings + (r.findings == 0 && r.crash_inputs > 0 ? 1 : 0);
  }
  if (failed) return 2;
  return findings == 0 ? 0 : 1;
}

std::string soak_markdown(const SoakSummary& s) {
  std::string md = fmt::format("# vgc fuzz --all — {}\n\n`{}`\n\n{} targets, {} at a time, seed {}, {:.0f} s wall; "
                               "work corpus {}\n\n",
                               s.run, s.command, s.rows.size(), s.jobs, s.seed, s.wall_s, s.work_corpus);
  md += fmt::format("| target | {} | wall s | CPU s | executions | exec per CPU s | cov | ft | corpus: start → work corpus | merge s | findings |\n"
                    "|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---|\n",
                    s.cpu_time ? "CPU budget s" : "time s");
  double cpu = 0;
  long long execs = 0;
  std::size_t findings = 0;
  for (const SoakRow& r : s.rows) {
    cpu += r.cpu_s;
    execs += r.executions;
    findings += r.findings;
    std::string found = std::to_string(r.findings);
    if (r.crash_inputs > 0) found += fmt::format(" ({} crash inputs)", r.crash_inputs);
    if (r.campaign_exit == 2) found += " — did not run to its end (error)";
    const std::string corpus =
        r.merged ? fmt::format("{} → {} (was {})", r.start_files, r.work_files, r.work_files_before)
                 : fmt::format("{} → not merged (see merge.log)", r.start_files);
    md += fmt::format("| {} | {:.0f}{} | {:.0f} | {:.0f} | {} | {} | {} | {} | {} | {:.0f} | {} |\n", r.target, r.time_s,
                      r.killed ? "*" : "", r.wall_s, r.cpu_s,
                      with_commas(r.executions),
                      r.cpu_s > 0 ? with_commas(static_cast<long long>(r.executions / r.cpu_s)) : std::string("-"),
                      r.cov, r.ft, corpus, r.merge_s, found);
  }
  md += fmt::format("| **total** | | | {:.0f} | {} | | | | | | {} |\n\n", cpu, with_commas(execs), findings);
  if (s.cpu_time)
    md += "CPU budget s: each target ran until libFuzzer and its jobs had used that many CPU seconds (read from /proc "
          "once a second; the job running then was stopped, its new inputs lost), whatever else the machine ran; wall s "
          "is how long that took. ";
  md += "CPU s: user + system time of libFuzzer and its fork-mode job (kernel rusage). cov, ft: the last status "
        "line. Corpus: the inputs the target started from (committed corpus, fixed crashes, work corpus), and the "
        "work corpus after the run's corpus was merged into it (libFuzzer -merge=1; before the merge in brackets); merge s: "
        "the merge's wall time. *: libFuzzer was still waiting for its last fork-mode job at the end of its grace and was killed "
        "(that job's CPU time and new inputs are lost; the figures are those of its last status line).\n";
  bool any = false;
  for (const SoakRow& r : s.rows) {
    if (r.findings == 0 && r.crash_inputs == 0) continue;
    if (!any) md += "\n## Findings\n\n";
    any = true;
    for (const std::string& sig : r.signatures) md += fmt::format("- {}: {}\n", r.target, sig);
    if (r.signatures.empty()) md += fmt::format("- {}: {} crash inputs, none signed\n", r.target, r.crash_inputs);
    md += fmt::format("  - counterexamples and replay commands: {}/summary.md\n", r.run_dir);
  }
  return md;
}

std::string soak_json(const SoakSummary& s) {
  using nlohmann::json;
  json rows = json::array();
  for (const SoakRow& r : s.rows)
    rows.push_back({{"target", r.target},
                    {"time_s", r.time_s},
                    {"wall_s", r.wall_s},
                    {"cpu_s", r.cpu_s},
                    {"executions", r.executions},
                    {"cov", r.cov},
                    {"ft", r.ft},
                    {"start_files", r.start_files},
                    {"work_files_before", r.work_files_before},
                    {"work_files", r.work_files},
                    {"merged", r.merged},
                    {"merge_s", r.merge_s},
                    {"killed_at_deadline", r.killed},
                    {"cpu_budget_spent", r.cpu_budget_spent},
                    {"findings", r.findings},
                    {"crash_inputs", r.crash_inputs},
                    {"signatures", r.signatures},
                    {"run_dir", r.run_dir},
                    {"campaign_exit", r.campaign_exit}});
  json j = {{"run", s.run},         {"run_dir", s.run_dir}, {"command", s.command},
            {"seed", s.seed},       {"jobs", s.jobs},       {"wall_s", s.wall_s},
            {"cpu_time", s.cpu_time},
            {"work_corpus", s.work_corpus}, {"rows", rows}};
  return j.dump(2) + "\n";
}

}  // namespace vgc::fuzz
