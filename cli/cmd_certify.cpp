// cmd_certify.cpp — `vgc certify`: certify an implementation against the
// clause catalog and write reports/<implementation>/<run>/.
//
// Exit codes (verdict.h): 0 conformant, 1 not conformant, 2 usage or
// infrastructure error or an incomplete run.
#include <fmt/core.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>

#include "baseline.h"
#include "clause.h"
#include "exec_implementation.h"  // shell_quote
#include "implementation.h"
#include "open_impl.h"
#include "program_command.h"
#include "progress_line.h"
#include "report.h"
#include "runner.h"
#include "subcommand.h"
#include "verdict.h"

namespace vgc::cli {
namespace {

struct Options {
  std::string impl = "reference";
  std::uint64_t seed = 1;
  int cases = 200;
  int max_size = 50;
  double budget = 300;
  double timeout = 5;
  std::string verse_bone_form = "auto";  // --verse-bone-form
  std::string clauses = "*";
  std::string baseline;
  std::string shard = "1/1";
  std::string reports = "reports";
  bool quiet = false;
  bool strict = false;
};

std::string utc_now() {
  std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

bool parse_shard(const std::string& s, int* index, int* count) {
  int i = 0, n = 0;
  char slash = 0, extra = 0;
  if (std::sscanf(s.c_str(), "%d%c%d%c", &i, &slash, &n, &extra) != 3 || slash != '/' || n < 1 || i < 1 || i > n)
    return false;
  *index = i - 1;
  *count = n;
  return true;
}

int usage(const std::string& message) {
  fmt::print(stderr, "vgc certify: {}\n", message);
  return 2;
}

// The first comma-separated pattern of `glob` that matches no clause id
// (a typo would silently leave clauses unchecked), or "" when all match.
std::string unmatched_pattern(const std::string& glob) {
  std::stringstream ss(glob);
  std::string pattern;
  bool any = false;
  while (std::getline(ss, pattern, ',')) {
    if (pattern.empty()) continue;
    any = true;
    bool matched = false;
    for (const Clause& c : clause_catalog()) matched = matched || clause_selected(pattern, c.id);
    if (!matched) return pattern;
  }
  return any ? "" : glob;
}

// Whether runs can be written under `dir` (it or its nearest existing
// parent is a directory we may write into), checked before a run that may
// take long; nothing is created.
bool reports_writable(const std::string& dir, std::string* why) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path p = fs::absolute(dir.empty() ? "." : dir, ec);
  while (!fs::exists(p, ec) && p.has_parent_path() && p != p.parent_path()) p = p.parent_path();
  if (!fs::is_directory(p, ec)) {
    *why = p.string() + " is not a directory";
    return false;
  }
  if (::access(p.c_str(), W_OK | X_OK) != 0) {
    *why = p.string() + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

std::string rerun_command(const Options& o) {
  std::string c = vgc_environment_prefix() + program_command() + " certify --impl " + shell_quote(o.impl) + " --seed " +
                  std::to_string(o.seed) + " --cases " + std::to_string(o.cases) + " --budget " +
                  fmt::format("{:g}", o.budget);
  if (o.max_size != 50) c += " --max-size " + std::to_string(o.max_size);
  if (o.clauses != "*") c += " --clauses " + shell_quote(o.clauses);
  if (o.shard != "1/1") c += " --shard " + o.shard;
  if (!o.baseline.empty()) c += " --baseline " + shell_quote(o.baseline);
  if (o.strict) c += " --strict";
  if (o.timeout != 5) c += " --timeout " + fmt::format("{:g}", o.timeout);
  if (o.verse_bone_form != "auto") c += " --verse-bone-form " + o.verse_bone_form;
  return c;
}

int run(const Options& o) {
  RunOptions ro;
  ro.seed = o.seed;
  ro.cases = o.cases;
  ro.max_size = o.max_size;
  ro.budget_seconds = o.budget;
  ro.clause_glob = o.clauses;
  if (!parse_shard(o.shard, &ro.shard_index, &ro.shard_count)) {
    fmt::print(stderr, "vgc certify: --shard takes I/N with 1 <= I <= N, got '{}': for example --shard 2/3 runs "
                       "the second of three shards\n", o.shard);
    return 2;
  }
  if (o.cases < 1)
    return usage(fmt::format("--cases is {}: give a positive number of cases per property (default 200)", o.cases));
  if (o.max_size < 1) return usage(fmt::format("--max-size is {}: give a positive size (default 50)", o.max_size));
  if (!(o.budget > 0))
    return usage(fmt::format("--budget is {:g}: give a positive number of seconds (default 300)", o.budget));
  if (!(o.timeout > 0))
    return usage(fmt::format("--timeout is {:g}: give a positive number of seconds (default 5)", o.timeout));
  if (const std::string bad = unmatched_pattern(o.clauses); !bad.empty())
    return usage("--clauses pattern '" + bad + "' matches no clause id: `vgc clauses` lists them; give comma-separated "
                 "ids or globs, e.g. --clauses 'LAYER-*,BONE-FOREST-1'");
  if (std::string why; !reports_writable(o.reports, &why))
    return usage("cannot write reports under '" + o.reports + "' (" + why +
                 "): give --reports a directory you can write (it is created if missing)");
  Baseline baseline;
  if (!o.baseline.empty()) {
    std::string error;
    if (!load_baseline(o.baseline, &baseline, &error)) {
      fmt::print(stderr, "vgc certify: {}\n", error);
      return 2;
    }
    for (const auto& [id, why] : baseline.reasons) ro.tolerated.insert(id);
  }
  auto sut = open_impl_or_report("certify", o.impl, o.timeout, o.verse_bone_form);
  if (!sut) return 2;

  ReportContext ctx;
  ctx.implementation_spec = o.impl;
  if (o.impl.rfind("verse:", 0) == 0) ctx.implementation_identity = sut->identity();  // host, release, bone form
  ctx.command_line = rerun_command(o);
  ctx.started = utc_now();
  if (!o.baseline.empty()) {
    ctx.baseline = &baseline;
    ctx.baseline_path = o.baseline;
  }
  fmt::print(stderr, "vgc certify: {} (seed {}, {} cases per property, budget {:g} s, shard {})\n", o.impl, o.seed,
             o.cases, o.budget, o.shard);
  if (!ctx.implementation_identity.empty()) fmt::print(stderr, "vgc certify: {}\n", ctx.implementation_identity);

  ProgressLine line(!o.quiet);
  ro.progress = [&line](const RunProgress& p) {
    // ProgressLine adds the elapsed time, and on a terminal redraws it
    // twice a second however long one case takes.
    line.update(fmt::format("[{}/{}] {:<18} {:>4}/{} cases, {} found{}{}", p.property_index + 1, p.property_count,
                            p.property, p.cases_done, p.cases_total, p.failures,
                            p.set_aside ? fmt::format(", {} set aside", p.set_aside) : "",
                            p.shrinking ? "  shrinking a failure" : ""));
  };
  // One permanent line per property as it finishes (in a CI log the only
  // sign of progress besides a status line every 10 s).
  ro.property_done = [&line, &o](const PropertyOutcome& p, const RunProgress& at) {
    if (o.quiet) return;
    line.finish();
    std::string found;
    for (const auto& f : p.findings) found += (found.empty() ? "" : ", ") + f.finding.clause;
    fmt::print(stderr, "[{}/{}] {:<20} {:<8} {}/{} cases ({} judged, {} set aside{}){}  {:.1f} s\n",
               at.property_index + 1, at.property_count, p.id, p.status, p.cases, p.cases_target, p.judged,
               p.set_aside, p.not_judged ? fmt::format(", {} not judged", p.not_judged) : "",
               found.empty() ? "" : "; found " + found, at.elapsed_seconds);
    if (!p.note.empty() && p.status != "pass") fmt::print(stderr, "      {}\n", p.note);
  };
  register_oracle_checks();  // the oracles judge the optional capabilities
  line.update("asking the implementation for a fresh node", true);
  const RunResult result = run_certification(*sut, ro);
  line.finish();
  const Verdict verdict = judge(result, ctx.baseline, o.strict);
  ctx.run_dir = default_run_dir(o.reports, result, ctx);
  std::string error;
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(ctx.run_dir).parent_path(), ec);
  if (!write_report(o.reports, result, verdict, ctx, &error)) {
    fmt::print(stderr, "vgc certify: {}: no report was written (verdict {}); free space or give --reports a "
                       "directory you can write, then run again: {}\n", error, verdict.name, ctx.command_line);
    return 2;
  }

  std::map<std::string, int> counts;
  for (const auto& c : result.clauses) ++counts[c.status];
  std::string tally;
  for (const char* st : {"fail", "crash", "timeout", "unchecked", "not-applicable", "not-claimed", "skipped"})
    if (counts[st]) tally += fmt::format(", {} {}", counts[st], st);
  fmt::print("{}: {} ({} of {} clauses pass{}; {:.1f} s)\n", o.impl, verdict.name, counts["pass"],
             result.clauses.size(), tally, result.seconds);
  if (result.preflight)
    fmt::print("  the implementation could not show a fresh node: {}: {}\n", result.preflight->clause,
               result.preflight->message);
  for (const auto& co : result.clauses) {
    if (!co.finding) continue;
    const std::string id(co.clause->id);
    const bool known = ctx.baseline && ctx.baseline->reasons.count(id);
    const char* tag = co.clause->level == ClauseLevel::Should ? "should"
                      : known                                  ? "known"
                      : !finding_gates(co, o.strict)           ? "profile"
                                                               : co.status.c_str();
    fmt::print("  {:<8} {:<24} {}\n", tag, co.clause->id, co.finding->message);
    fmt::print("           replay: {}\n",
               replay_command((std::filesystem::path(ctx.run_dir) / counterexample_path(co)).string(), o.impl));
  }
  for (const auto& id : verdict.stale_baseline)
    fmt::print("  stale    {:<24} in the baseline but no case diverged on it: remove it\n", id);
  for (const auto& p : result.properties)
    if (p.status == "stopped") fmt::print("  stopped  {}: {}\n", p.id, p.note);
  for (const auto& co : result.clauses)
    if (co.status == "unchecked") fmt::print("  unchecked {:<23} {}\n", co.clause->id, co.note);
  if (!verdict.profile_differences.empty() && !o.strict)
    fmt::print("  ({} profile difference(s) from the suite's reading of silent points: reported, not gating; "
               "--strict gates on them)\n",
               verdict.profile_differences.size());
  fmt::print("report: {}/summary.md\n", ctx.run_dir);
  fmt::print("re-run: {}\n", ctx.command_line);
  return verdict.exit_code;
}

void add(CLI::App& app, int* exit_code) {
  auto o = std::make_shared<Options>();
  auto* sub = app.add_subcommand("certify", "Certify an implementation of the geometry node against the spec");
  sub->add_option("--impl", o->impl, "reference | exec:CMD | plugin:PATH | verse:HOST[:PORT]")->capture_default_str();
  sub->add_option("--seed", o->seed, "Seed; the same seed gives the same cases and verdicts")
      ->capture_default_str()
      ->check(CLI::Validator(
          [](std::string& s) -> std::string {
            if (!s.empty() && s.size() <= 20 && s.find_first_not_of("0123456789") == std::string::npos) return "";
            return "takes a whole number from 0 to 18446744073709551615, got '" + s + "'";
          },
          "UINT64"));
  sub->add_option("--cases", o->cases, "Test cases per property")->capture_default_str();
  sub->add_option("--max-size", o->max_size, "RapidCheck size: longest command sequences")->capture_default_str();
  sub->add_option("--budget", o->budget, "Wall-time limit in seconds; a run cut short is 'incomplete' (exit 2)")
      ->capture_default_str();
  sub->add_option("--timeout", o->timeout, "Seconds an out-of-process implementation has per answer")
      ->capture_default_str();
  sub->add_option("--verse-bone-form", o->verse_bone_form,
                  "verse: the bone_create form to speak: auto (the form the host answers a probe in), spec "
                  "(Verse spec 2.6.3) or r6 (r6's last release; docs/verse_wire.md section 4)")
      ->check(CLI::IsMember({"auto", "spec", "r6"}))
      ->capture_default_str();
  sub->add_option("--clauses", o->clauses, "Clause ids to check: comma-separated glob patterns")->capture_default_str();
  sub->add_option("--baseline", o->baseline, "File of known deviations: CLAUSE-ID reason, one per line");
  sub->add_option("--shard", o->shard, "Run shard I of N (1-based); shards together give the full verdicts")
      ->capture_default_str();
  sub->add_option("--reports", o->reports, "Directory for reports")->capture_default_str();
  sub->add_flag("--quiet", o->quiet, "No progress line");
  sub->add_flag("--strict", o->strict,
                "Also gate on IMPLEMENTATION-DEFINED clauses (the suite's reading of points the spec leaves open)");
  sub->callback([o, exit_code] { *exit_code = run(*o); });
}

const Subcommand kCertify{add};

}  // namespace
}  // namespace vgc::cli
