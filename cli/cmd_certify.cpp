// cmd_certify.cpp — `vgc certify`: certify an implementation against the
// clause catalog and write reports/<implementation>/<run>/.
//
// Exit codes (verdict.h): 0 conformant, 1 not conformant, 2 usage or
// infrastructure error or an incomplete run; 128 + the signal (130 SIGINT,
// 143 SIGTERM) for a cancelled run, after its report (verdict
// "incomplete", every finding so far) is written. A second SIGINT or
// SIGTERM exits at once with that code, writing nothing more (the same
// signal from the same sender within a second is the first one delivered
// again, cancel.h: `timeout` sends it to vgc and to its process group).
#include <fmt/core.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <chrono>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

#include "mesh_certification.h"
#include "mesh_import.h"
#include "baseline.h"
#include "cancel.h"
#include "clause.h"
#include "exec_implementation.h"  // shell_quote
#include "implementation.h"
#include "open_impl.h"
#include "option_values.h"
#include "program_command.h"
#include "progress_line.h"
#include "report.h"
#include "runner.h"
#include "subcommand.h"
#include "terminal_text.h"
#include "unstarted_implementation.h"
#include "verdict.h"

namespace vgc::cli {
namespace {

// The largest --max-size: sequences of up to about this many commands
// (more only exhausts memory before any verdict).
constexpr std::uint64_t kMaxSize = 100000;

struct Options {
  ImplOptions impl;  // --impl and its family (open_impl.h)
  std::uint64_t seed = 1;
  int cases = 200;
  int max_size = 50;
  double budget = 300;
  std::string clauses = "*";
  std::string baseline;
  std::string shard = "1/1";
  std::string reports = "reports";
  bool quiet = false;
  bool strict = false;
  std::string mesh;  // --mesh FILE: the derived-geometry checks on that mesh instead
  int levels = 2;    // --levels: subdivision levels judged on --mesh
  bool triangulate = false;  // --triangulate: with --mesh, split faces of 5+ corners
};

std::string utc_now() {
  std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

// "I/N" with 1 <= I <= N, each a whole decimal number (option_values.h).
bool parse_shard(const std::string& s, int* index, int* count) {
  const std::size_t slash = s.find('/');
  std::uint64_t i = 0, n = 0;
  if (slash == std::string::npos || !parse_whole_number(std::string_view(s).substr(0, slash), &i) ||
      !parse_whole_number(std::string_view(s).substr(slash + 1), &n) || n < 1 || n > INT_MAX || i < 1 || i > n)
    return false;
  *index = static_cast<int>(i) - 1;
  *count = static_cast<int>(n);
  return true;
}

int usage(const std::string& message) {
  say(stderr, "vgc certify: {}\n", message);
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

// Whether runs can really be written under `dir`, checked before a run that
// may take long: a file is created there and removed (access() says yes to
// root under /proc, and on a read-only mount). Directories it had to create
// for that are removed again (the run creates them when it writes), so a
// usage error found later leaves nothing behind.
bool reports_writable(const std::string& dir, std::string* why) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p = fs::absolute(dir.empty() ? fs::path(".") : fs::path(dir), ec);
  std::vector<fs::path> created;  // deepest last
  for (fs::path q = p; !q.empty() && !fs::exists(q, ec) && q != q.parent_path(); q = q.parent_path())
    created.insert(created.begin(), q);
  auto undo = [&] {
    std::error_code ignored;  // only empty directories go: another run may be using one already
    for (auto it = created.rbegin(); it != created.rend(); ++it) fs::remove(*it, ignored);
  };
  for (int attempt = 0;; ++attempt) {
    fs::create_directories(p, ec);
    // Another run checking the same --reports at once may remove a parent
    // it created between our creating and our looking (its undo): again.
    const bool vanished = ec ? ec == std::errc::no_such_file_or_directory : !fs::is_directory(p);
    if (vanished && attempt < 10) continue;
    if (ec || !fs::is_directory(p)) {
      *why = ec ? ec.message() : "not a directory";
      undo();
      return false;
    }
    const fs::path probe = p / (".vgc-write-probe." + std::to_string(::getpid()));
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0 && errno == ENOENT && attempt < 10) continue;  // another run's undo removed it meanwhile
    if (fd < 0) {
      *why = std::string("cannot create a file there: ") + std::strerror(errno);
      undo();
      return false;
    }
    const bool wrote = ::write(fd, "x", 1) == 1;
    const int saved = errno;
    ::close(fd);
    fs::remove(probe, ec);
    undo();
    if (!wrote) *why = std::string("cannot write a file there: ") + std::strerror(saved);
    return wrote;
  }
}

// SIGINT / SIGTERM (a cancelled CI job, Ctrl-C): the first asks the run to
// stop (cancel.h) so that the report of what was found is written; a second
// one exits at once. Only async-signal-safe calls here.
extern "C" void on_cancel_signal(int sig, siginfo_t* info, void*) {
  const long sender = info && info->si_code <= 0 ? static_cast<long>(info->si_pid) : 0;  // SI_USER, SI_QUEUE...
  if (cancel_signal() && repeated_cancel(sig, sender)) return;  // the same cancel, delivered again (cancel.h)
  if (cancel_signal()) {
    const char msg[] = "\nvgc certify: second signal: exiting at once, no report\n";
    [[maybe_unused]] const ssize_t n = ::write(2, msg, sizeof msg - 1);
    _exit(128 + sig);
  }
  request_cancel(sig, sender);
  const char msg[] = "\nvgc certify: cancelled: stopping the implementation and writing an incomplete report "
                     "(a second signal exits at once)\n";
  [[maybe_unused]] const ssize_t n = ::write(2, msg, sizeof msg - 1);
}

void install_cancel_handlers() {
  prepare_cancel();
  struct sigaction sa {};
  sa.sa_sigaction = on_cancel_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_SIGINFO;  // no SA_RESTART: a blocking wait returns EINTR and sees the request
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

std::string rerun_command(const Options& o) {
  std::string c = vgc_environment_prefix() + program_command() + " certify --impl " +
                  shell_quote(o.impl.route.spec) + " --seed " + std::to_string(o.seed) + " --cases " +
                  std::to_string(o.cases) + " --budget " + fmt::format("{:g}", o.budget);
  if (o.max_size != 50) c += " --max-size " + std::to_string(o.max_size);
  if (o.clauses != "*") c += " --clauses " + shell_quote(o.clauses);
  if (o.shard != "1/1") c += " --shard " + o.shard;
  if (!o.baseline.empty()) c += " --baseline " + shell_quote(o.baseline);
  if (o.strict) c += " --strict";
  if (o.impl.timeout != 5) c += " --timeout " + fmt::format("{:g}", o.impl.timeout);
  if (o.impl.start_timeout != 60) c += " --start-timeout " + fmt::format("{:g}", o.impl.start_timeout);
  if (o.impl.verse_bone_form != "auto") c += " --verse-bone-form " + o.impl.verse_bone_form;
  if (!o.impl.restart.empty()) c += " --restart " + shell_quote(o.impl.restart);
  if (!o.impl.host_cmd.empty()) c += " --host-cmd " + shell_quote(o.impl.host_cmd);
  return c;
}

// `vgc certify --mesh FILE.obj`: the mesh (obj_import.h) built on a fresh
// instance and on the reference, then each claimed derived-geometry
// capability judged per level (mesh_certification.h). Prints one line per
// check; exit 0 the mesh was stored as the reference stores it and every
// judged check passes, 1 a failure (or the mesh could not be built as the
// reference builds it), 2 the file is bad or nothing could be judged. The
// run directory under --reports has the usual files (one "property" per
// check and level).
int run_mesh(const Options& o) {
  if (o.levels < 1 || o.levels > 4)
    return usage(fmt::format("--levels is {}: give 1 to 4 subdivision levels (default 2)", o.levels));
  if (!(o.budget > 0))
    return usage(fmt::format("--budget is {:g}: give a positive number of seconds (default 300)", o.budget));
  if (!(o.impl.timeout > 0))
    return usage(fmt::format("--timeout is {:g}: give a positive number of seconds (default 5)", o.impl.timeout));
  if (const std::string bad = unmatched_pattern(o.clauses); !bad.empty())
    return usage("--clauses pattern '" + bad + "' matches no clause id: `vgc clauses` lists them; with --mesh the "
                 "checks are MESH-CLASSIFY-1, NORMALS-SPLIT-1, SUBD-CATMARK-1 and LOOP-TRIANGLE-1");
  if (std::string why; !reports_writable(o.reports, &why))
    return usage("cannot write reports under '" + o.reports + "' (" + why +
                 "): give --reports a directory you can write (it is created if missing)");
  MeshProgram mesh;
  MeshFileError error;
  if (!import_mesh(o.mesh, MeshImportOptions{o.triangulate}, &mesh, &error)) {
    if (error.line)
      say(stderr, "{}:{}:{}: error: {}\n", one_line_text(o.mesh), error.line, error.column, error.message);
    else
      say(stderr, "vgc certify: --mesh {}: {}\n", one_line_text(o.mesh), error.message);
    return 2;
  }
  if (mesh.split_faces)
    say(stderr, "vgc certify: --triangulate split {} faces of more than 4 corners into triangles\n",
        mesh.split_faces);
  install_cancel_handlers();
  auto sut = open_impl_or_report("certify", o.impl);
  if (!sut) return 2;
  register_oracle_checks();
  say(stderr, "vgc certify: {} on {} ({} vertices, {} triangles, {} quads; up to level {})\n", o.impl.route.spec,
      one_line_text(o.mesh),
      mesh.vertices, mesh.triangles, mesh.quads, o.levels);
  const auto t0 = std::chrono::steady_clock::now();
  const std::string started = utc_now();
  MeshCertifyOptions mo;
  mo.levels = o.levels;
  mo.clauses = o.clauses;
  mo.budget_seconds = o.budget;
  const MeshCertification r = certify_mesh(mesh, *sut, mo);
  const RunResult run = mesh_run_result(r, mesh, sut->name(),
                                        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  ReportContext ctx;
  ctx.implementation_spec = o.impl.route.spec;
  ctx.started = started;
  ctx.command_line = vgc_environment_prefix() + program_command() + " certify --mesh " + shell_quote(o.mesh) +
                     " --impl " + shell_quote(o.impl.route.spec) + " --levels " + std::to_string(o.levels) +
                     (o.triangulate ? " --triangulate" : "") + (o.clauses != "*" ? " --clauses " + shell_quote(o.clauses) : "") +
                     " --budget " + fmt::format("{:g}", o.budget) +
                     (o.impl.timeout != 5 ? " --timeout " + fmt::format("{:g}", o.impl.timeout) : "");
  const Verdict verdict = judge(run, nullptr, o.strict);
  std::string werror;
  if (!claim_run_dir(o.reports, run, &ctx, &werror) || !write_report(o.reports, run, verdict, ctx, &werror)) {
    say(stderr, "vgc certify: {}: no report was written\n", werror);
    return 2;
  }
  if (r.build_failure) {
    say("  fail        {:<18} building the mesh ({} commands, {:.1f} s): {}\n", r.build_failure->clause, r.commands,
        r.build_seconds, r.build_failure->message);
  } else {
    say("  built       the mesh: {} commands, the same snapshot as the reference ({:.1f} s)\n", r.commands,
        r.build_seconds);
  }
  std::map<std::string, int> tally;  // by name: printed in that order
  bool checks_judged = false;        // a check passed or failed
  for (const MeshCheckOutcome& c : r.checks) {
    ++tally[mesh_check_status_name(c.status)];
    checks_judged = checks_judged || c.status == MeshCheckStatus::Pass || c.status == MeshCheckStatus::Fail;
    const std::string what = c.capability + (c.level ? fmt::format(" level {}", c.level) : "");
    const std::string detail = c.finding ? c.finding->message : c.note;
    say("  {:<11} {:<18} {:<20} {:>6.2f} s  {}\n", mesh_check_status_name(c.status), c.clause, what, c.seconds,
        detail.size() > 300 ? detail.substr(0, 300) + "..." : detail);
  }
  // Each finding's replay line, as certify prints it for the catalog (the
  // file by its absolute path: it works from any directory).
  for (const auto& co : run.clauses)
    if (co.finding)
      say("           replay {}: {}\n", co.clause->id,
          replay_command((std::filesystem::path(ctx.run_dir) / counterexample_path(co)).string(), ctx));
  std::string counts;
  for (const auto& [status, n] : tally) counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", n, status);
  if (!r.build_failure) counts += std::string(counts.empty() ? "" : "; ") + "stored as the reference stores it";
  // The verdict is the report's (verdict.h, from the clauses' statuses).
  const char* verdict_name = "conformant";
  switch (verdict.kind) {
    case VerdictKind::Conformant: break;
    case VerdictKind::NotConformant: verdict_name = "not conformant"; break;
    case VerdictKind::Incomplete: verdict_name = "incomplete"; break;
  }
  say("{}: {} on {} ({})\n", o.impl.route.spec, verdict_name, one_line_text(o.mesh),
      counts.empty() ? "no check run" : counts);
  if (verdict.new_failures.empty() && !checks_judged)
    say("  only the storage of the mesh was judged: the implementation claims none of manifold, subdivision, "
        "normals, loop (docs/adapters.md section 5)\n");
  say("report: {}/summary.md\n", ctx.run_dir);
  if (!r.stopped_why.empty()) say("  stopped: {}; the verdict is incomplete\n", r.stopped_why);
  else if (verdict.kind == VerdictKind::Incomplete)
    say("  a check stopped at a limit of vgc's (time or answer size), not at anything the implementation did: "
        "give --timeout more seconds (it scales with the mesh already) and run again\n");
  const int code = cancel_signal() ? 128 + cancel_signal() : verdict.exit_code;
  if (r.abandoned) {  // a check is still running on another thread: leave without unwinding through it
    std::fflush(nullptr);
    _exit(code);
  }
  return code;
}

// One line per finding, with its replay command (CI annotations read them).
void print_findings(const RunResult& result, const ReportContext& ctx, const Options& o) {
  for (const auto& co : result.clauses) {
    if (!co.finding) continue;
    const std::string id(co.clause->id);
    const bool known = ctx.baseline && ctx.baseline->reasons.count(id);
    const char* tag = co.clause->level == ClauseLevel::Should ? "should"
                      : known                                  ? "known"
                      : !finding_gates(co, o.strict)           ? "profile"
                                                               : clause_status_name(co.status);
    say("  {:<8} {:<24} {}\n", tag, co.clause->id, co.finding->message);
    say("           replay: {}\n",
        replay_command((std::filesystem::path(ctx.run_dir) / counterexample_path(co)).string(), o.impl.route.spec));
  }
}

int run(const Options& o) {
  if (!o.mesh.empty()) return run_mesh(o);
  RunOptions ro;
  ro.seed = o.seed;
  ro.cases = o.cases;
  ro.max_size = o.max_size;
  ro.budget_seconds = o.budget;
  ro.clause_glob = o.clauses;
  if (!parse_shard(o.shard, &ro.shard_index, &ro.shard_count)) {
    say(stderr, "vgc certify: --shard takes I/N with 1 <= I <= N, got '{}': for example --shard 2/3 runs "
                       "the second of three shards\n", o.shard);
    return 2;
  }
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
      say(stderr, "vgc certify: {}\n", error);
      return 2;
    }
    for (const auto& [id, why] : baseline.reasons) ro.tolerated.insert(id);
  }
  install_cancel_handlers();
  std::unique_ptr<Implementation> sut =
      open_impl_or_report("certify", o.impl);
  if (!sut && !cancel_signal()) {
    // Shards run side by side on one machine would start their hosts on
    // one port: the second finds it in use (said above).
    if (ro.shard_count > 1 && !o.impl.host_cmd.empty())
      say(stderr, "vgc certify: with --shard {} and --host-cmd every shard starts its own host on the port of --impl: "
                  "shards run side by side on one machine each need a port of their own (in --impl and in "
                  "--host-cmd)\n", o.shard);
    return 2;
  }
  if (!sut)  // cancelled while it started: the report says that nothing was judged
    sut = std::make_unique<UnstartedImplementation>(
        o.impl.route.spec,
        std::string("not started: the run was cancelled by ") + cancel_signal_name() + " while it started");

  ReportContext ctx;
  ctx.implementation_spec = o.impl.route.spec;
  // A route whose implementation declares a profile at its start says what
  // it found (a Verse host: its release and the bone form it speaks).
  if (o.impl.route.traits().declares_bone_form) ctx.implementation_identity = sut->identity();
  ctx.merge_identity = sut->merge_identity();
  ctx.command_line = rerun_command(o);
  ctx.started = utc_now();
  if (!o.baseline.empty()) {
    ctx.baseline = &baseline;
    ctx.baseline_path = o.baseline;
  }
  say(stderr, "vgc certify: {} (seed {}, {} cases per property, budget {:g} s, shard {})\n", o.impl.route.spec,
      o.seed, o.cases, o.budget, o.shard);
  if (!ctx.implementation_identity.empty()) say(stderr, "vgc certify: {}\n", ctx.implementation_identity);

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
    say(stderr, "[{}/{}] {:<20} {:<8} {}/{} cases ({} judged, {} set aside{}){}  {:.1f} s\n",
               at.property_index + 1, at.property_count, p.id, property_status_name(p.status), p.cases, p.cases_target, p.judged,
               p.set_aside, p.not_judged ? fmt::format(", {} not judged", p.not_judged) : "",
               found.empty() ? "" : "; found " + found, at.elapsed_seconds);
    if (!p.note.empty() && p.status != PropertyStatus::Pass) say(stderr, "      {}\n", p.note);
  };
  register_oracle_checks();  // the oracles judge the optional capabilities
  line.update("asking the implementation for a fresh node", true);
  const RunResult result = run_certification(*sut, ro);
  line.finish();
  const Verdict verdict = judge(result, ctx.baseline, o.strict);
  std::string error;
  if (!claim_run_dir(o.reports, result, &ctx, &error) || !write_report(o.reports, result, verdict, ctx, &error)) {
    say(stderr, "vgc certify: {}: no report was written (verdict {}); free space or give --reports a "
                       "directory you can write, then run again: {}\n", error, verdict.name, ctx.command_line);
    return 2;
  }

  // The counts per shown status (verdict.h), as summary.md, report.html and
  // report.json give them: "N of M clauses pass, 1 fail, 2 fail (SHOULD), ...".
  int passed = 0;
  std::string tally;
  for (const auto& [shown, n] : shown_counts(result, verdict)) {
    if (shown == ClauseShown{ClauseStatus::Pass, ShownQualifier::None}) passed = n;
    else tally += fmt::format(", {} {}", n, shown_status_name(shown));
  }
  say("{}: {} ({} of {} clauses pass{}; {:.1f} s)\n", o.impl.route.spec, verdict.name, passed, result.clauses.size(),
             tally, result.seconds);
  if (result.preflight)
    say("  the implementation could not show a fresh node: {}: {}\n", result.preflight->clause,
               result.preflight->message);
  print_findings(result, ctx, o);
  for (const auto& id : verdict.stale_baseline)
    say("  stale    {:<24} in the baseline but no case diverged on it: remove it\n", id);
  for (const auto& p : result.properties)
    if (p.status == PropertyStatus::Stopped) say("  stopped  {}: {}\n", p.id, p.note);
  for (const auto& co : result.clauses)
    if (co.status == ClauseStatus::Unchecked) say("  unchecked {:<23} {}\n", co.clause->id, co.note);
  if (!verdict.profile_differences.empty() && !o.strict)
    say("  ({} profile difference(s) from the suite's reading of silent points: reported, not gating; "
               "--strict gates on them)\n",
               verdict.profile_differences.size());
  say("report: {}/summary.md\n", ctx.run_dir);
  say("re-run: {}\n", ctx.command_line);
  // The exit code is the report's (verdict.h): 128 + the signal when the
  // signal cut the run short; a signal that came after the last case found
  // a whole run, whose report and exit code say so.
  if (!result.cancelled_by.empty())
    say("cancelled by {}: the verdict is incomplete; the findings above are those found before\n",
        result.cancelled_by);
  return verdict.exit_code;
}

void add(CLI::App& app, int* exit_code) {
  auto o = std::make_shared<Options>();
  auto* sub = app.add_subcommand("certify", "Certify an implementation of the geometry node against the spec");
  add_impl_options(sub, &o->impl, kTimeout | kStartTimeout | kBoneForm | kRestart | kHostCmd,
                   "reference | exec:CMD | plugin:PATH | verse:HOST[:PORT]");
  auto* seed = sub->add_option("--seed", o->seed, "Seed; the same seed gives the same cases and verdicts")
                   ->capture_default_str()
                   ->transform(whole_number(0, UINT64_MAX, "the run's seed"));
  auto* cases = sub->add_option("--cases", o->cases, "Test cases per property")
                    ->capture_default_str()
                    ->transform(whole_number(1, INT_MAX, "cases per property"));
  auto* max_size = sub->add_option("--max-size", o->max_size, "RapidCheck size: longest command sequences")
                       ->capture_default_str()
                       ->transform(whole_number(1, kMaxSize, "commands (the RapidCheck size)"));
  sub->add_option("--budget", o->budget,
                  "CPU seconds of vgc and the implementation it started (a wall-clock guard stops at 10x); a run cut "
                  "short is 'incomplete' (exit 2)")
      ->capture_default_str()
      ->transform(seconds("for the whole run"));
  sub->add_option("--clauses", o->clauses, "Clause ids to check: comma-separated glob patterns")->capture_default_str();
  auto* baseline = sub->add_option("--baseline", o->baseline, "File of known deviations: CLAUSE-ID reason, one per line");
  sub->add_option("--shard", o->shard, "Run shard I of N (1-based); shards together give the full verdicts")
      ->capture_default_str();
  sub->add_option("--reports", o->reports, "Directory for reports")->capture_default_str();
  sub->add_flag("--quiet", o->quiet, "No progress line");
  auto* mesh = sub->add_option("--mesh", o->mesh,
                               "A mesh file (.obj, .off, .ply, .stl): build it on the implementation and run the "
                               "derived-geometry checks (manifold, subdivision per level, normals, loop) on it "
                               "instead of the catalog");
  sub->add_flag("--triangulate", o->triangulate,
                "With --mesh: split faces of more than 4 corners into triangles (CGAL; concave faces included)")
      ->needs(mesh);
  sub->add_option("--levels", o->levels, "With --mesh: subdivision levels to judge (1 to 4)")
      ->capture_default_str()
      ->transform(whole_number(1, 4, "subdivision levels"))
      ->needs(mesh);
  // What --mesh does not use: the mesh is the one case, judged whole (its
  // --budget, --clauses, --timeout and --levels apply).
  for (CLI::Option* generated : {seed, cases, max_size, baseline}) generated->excludes(mesh);
  sub->add_flag("--strict", o->strict,
                "Also gate on IMPLEMENTATION-DEFINED clauses (the suite's reading of points the spec leaves open)");
  sub->callback([o, exit_code] {
    if (const std::string misuse = impl_options_misuse(o->impl); !misuse.empty()) {
      *exit_code = usage(misuse);
      return;
    }
    // Each per-check and verdict line reaches a pipe or a CI log as it is
    // printed, whatever ends the run afterwards (a second signal's _exit).
    std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
    *exit_code = run(*o);
  });
}

const Subcommand kCertify{add};

}  // namespace
}  // namespace vgc::cli
