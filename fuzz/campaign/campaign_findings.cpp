// campaign_findings.cpp — a campaign's crash inputs signed and grouped, and
// one finding per group minimized and written as a counterexample that
// replays (campaign_run.h's sign_crash_inputs and write_findings).
//
// Spec: docs/fuzzing.md "Running a campaign" (one bug, one finding;
// counterexamples minimized: raw bytes by libFuzzer's crash-minimizing
// steps, minimize_input.h; command programs as certify shrinks them,
// minimize_finding.h).
#include "campaign_run.h"

#include <fmt/core.h>

#include <algorithm>
#include <fstream>
#include <regex>

#include "clause.h"
#include "crash_signature.h"
#include "display_text.h"
#include "exec_implementation.h"  // shell_quote
#include "finding.h"
#include "minimize_finding.h"
#include "minimize_input.h"
#include "program_command.h"
#include "restartable_host.h"

namespace vgc::fuzz::campaign_steps {

// Crashes: re-runs each saved input alone (smallest first, within a budget
// of its own: at most 200 inputs and max(10 s, --time / 10), replays and
// minimization of the counterexamples included), signs it, groups the
// inputs by signature (key: digits folded).
std::map<std::string, CrashGroup> sign_crash_inputs(CampaignRun* r) {
  CampaignSummary& s = r->s;
  std::map<std::string, CrashGroup> unique;
  std::vector<fs::path> saved;
  for (const auto& e : fs::directory_iterator(r->crashes))
    if (e.is_regular_file()) saved.push_back(e.path());
  std::sort(saved.begin(), saved.end(), [](const fs::path& a, const fs::path& b) {
    const auto sa = fs::file_size(a), sb = fs::file_size(b);
    return sa != sb ? sa < sb : a < b;
  });
  s.crash_inputs = saved.size();
  for (const fs::path& f : saved)
    if (auto t = seconds_since(f, r->sys0); t && (!s.time_to_first_finding_s || *t < *s.time_to_first_finding_s))
      s.time_to_first_finding_s = t;
  r->sign = SignBudget::starting_now(r->o.time_s);
  // A live implementation costs a process or a login per input re-run:
  // its inputs get half the budget, so that the unique findings are still
  // minimized and replayed on a fresh instance in the other half.
  const bool live = bool(r->impl.live);
  for (const fs::path& f : saved) {
    if (s.crash_inputs_signed >= 200) break;
    if (live ? r->sign.half_spent() : r->sign.spent()) {
      s.signing_stopped = r->sign.wall_guard_reached() ? "the wall guard" : "the CPU budget";
      break;
    }
    ++s.crash_inputs_signed;
    const std::string output = rerun_input(*r, f);
    CrashSignature sig = crash_signature(output);
    // A live implementation's finding that the input alone does not show
    // again (it depended on the instance's history or on timing; the
    // target's own confirmation says which in fuzzer.log): said so, not
    // "unknown".
    if (r->impl.live && sig.key == "unknown" && output.find("FINDING") == std::string::npos)
      sig = {"not reproduced", "not reproduced: the input alone, re-run on a fresh instance, showed nothing (the "
                               "finding depended on the implementation's history or timing; its FINDING line is in "
                               "fuzzer.log)"};
    CrashGroup& g = unique[sig.key];
    g.shown[f] = sig.shown;
    g.files.push_back(f);
    g.first_seen[f] = seconds_since(f, r->sys0);
    if (auto block = printed_block(*r, output)) g.printed[f] = *block;
  }
  return unique;
}

// The finding's summary fields from its group: signature, other forms,
// inputs, first seen, clause, level, baseline.
CampaignCrash describe_crash(const CampaignRun& r, const std::string& key, CrashGroup& g) {
  CampaignCrash c;
  const fs::path& rep = g.files.front();  // smallest (saved was sorted by size)
  c.dedup_key = key;
  c.signature = g.shown[rep];
  for (const auto& [file, text] : g.shown)
    if (text != c.signature && std::find(c.also.begin(), c.also.end(), text) == c.also.end()) c.also.push_back(text);
  c.inputs = g.files.size();
  c.input = rep.string();
  for (const fs::path& f : g.files)
    if (auto t = g.first_seen[f]; t && (!c.first_seen_s || *t < *c.first_seen_s)) c.first_seen_s = t;
  c.clause = clause_of_finding(c.signature);
  if (!c.clause.empty()) {
    if (const Clause* cl = find_clause(c.clause)) c.level = clause_level_name(cl->level);
    c.in_baseline = r.baseline.reasons.count(c.clause) > 0;
  }
  c.replay_fuzzer = env_prefix(r.target_env) + shell_quote(r.binary.string()) + " " + shell_quote(rep.string());
  return c;
}

// Whether the finding's counterexample is a command program that
// minimize_finding shrinks (a clause finding of a command-stream target);
// every other finding is raw bytes, minimized by libFuzzer.
bool shrinks_as_program(const CampaignRun& r, const CampaignCrash& c) {
  const bool command_stream = r.name != "text" && r.name != "verse_packet" && !r.mesh;
  return command_stream && !c.clause.empty();
}

// A raw-bytes finding's input minimized with libFuzzer's crash-minimizing
// steps (minimize_input.h) into minimized/, kept only when a fresh run signs
// it with the group's key. The minimization is bounded by steps, mutations
// and CPU seconds, seeded by the campaign's seed, so the same finding
// minimizes to the same bytes on an idle or a loaded machine; it is not cut
// by the signing budget (a wall-clock share of which used to leave it
// larger under load). Its wall guard (10 min) only stops a stuck step. On
// success the group's smallest input becomes the minimized one (with the
// target's printed block of it), and *bytes its contents.
void minimize_raw_input(CampaignRun* r, const std::string& key, CrashGroup& g, CampaignCrash* c,
                        std::string* bytes) {
  std::error_code ec;
  fs::create_directories(r->dir / "minimized", ec);
  const fs::path rep = c->input;
  const fs::path out = r->dir / "minimized" / rep.filename();
  std::string output;
  MinimizeLimits limits;
  limits.seed = r->o.seed;
  limits.cpu_seconds = 60;
  const MinimizedInput m = minimize_input(
      env_prefix(r->target_env) + shell_quote(r->binary.string()), rep.string(), out.string(),
      [&](const std::string& candidate) {
        output = rerun_input(*r, candidate);
        return crash_signature(output).key == key;
      },
      limits, clock::now() + std::chrono::minutes(10));
  c->minimize_note = m.note;
  if (!m.kept) return;
  c->minimized_input = m.file;
  c->input_bytes = m.before;
  c->minimized_bytes = m.after;
  read_file(m.file, bytes);
  if (auto block = printed_block(*r, output)) g.printed[m.file] = *block;
  g.files.front() = m.file;
  c->replay_fuzzer = env_prefix(r->target_env) + shell_quote(r->binary.string()) + " " + shell_quote(m.file);
}

// The counterexample of a finding of text, verse_packet or a mesh target:
// the input itself (text), its bytes in hex (a datagram) or the mesh the
// target printed; each replays through the target.
void write_input_counterexample(const CampaignRun& r, const CrashGroup& g, const std::string& bytes,
                                CampaignCrash* c) {
  const fs::path cex_file = c->counterexample;
  const std::string& target = r.s.target;
  auto printed = g.printed.find(g.files.front());
  c->replay = c->replay_fuzzer;
  if (r.name == "text") {
    write_file(cex_file, bytes);  // the input is text already
  } else if (r.name == "verse_packet") {  // one datagram: no command file; the input replays
    std::string text = "# vgc fuzz " + target + " counterexample: " + c->signature + "\n# from " +
                       g.files.front().string() + "\n# replay: " + c->replay_fuzzer + "\n# the datagram, " +
                       std::to_string(bytes.size()) + " bytes, in hex:\n";
    static const char* hex = "0123456789abcdef";
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      const auto b = static_cast<unsigned char>(bytes[i]);
      text += hex[b >> 4];
      text += hex[b & 15];
      text += (i % 16 == 15 || i + 1 == bytes.size()) ? '\n' : ' ';
    }
    if (printed != g.printed.end()) text += printed->second;
    write_file(cex_file, text);
  } else {  // a mesh: no command file (a mesh the node may not hold); the input replays
    std::string text = "# vgc fuzz " + target + " counterexample: " + c->signature + "\n# from " +
                       g.files.front().string() + "\n# replay: " + c->replay_fuzzer + "\n";
    text += printed != g.printed.end() ? printed->second : "# the target printed no mesh (a sanitizer finding)\n";
    write_file(cex_file, text);
  }
}

// The counterexample of a finding of a command-stream target (stream,
// differential, property_*): a command file. A finding named by clause
// replays as a certify counterexample, against the same implementation,
// with the same environment, minimized as certify shrinks. So does a crash
// of a plugin in fuzz_differential (in process it takes the fuzzer down
// unnamed): `vgc replay` runs the plugin isolated and names the clause, as
// certify would.
void write_program_counterexample(const CampaignRun& r, const CrashGroup& g, const std::string& bytes,
                                  CampaignCrash* c) {
  const fs::path cex_file = c->counterexample;
  const std::string vgc = r.o.vgc_binary.empty() ? self_exe().string() : r.o.vgc_binary;
  const std::string impl_spec = r.impl.spec();
  const CampaignOptions& o = r.o;
  const bool plugin_crash = c->clause.empty() && r.name == "differential" && !r.plugin.empty();
  const bool replayable = !c->clause.empty() || plugin_crash;
  const auto replay_line = [&] {
    return env_prefix(r.run_env) + program_command() + " replay " + shell_quote(cex_file.string()) + " --impl " +
           shell_quote(impl_spec) + replay_options(o);
  };
  const auto apply_line = [&] { return env_prefix(r.run_env) + program_command() + " apply " + shell_quote(cex_file.string()); };
  c->replay = replayable ? replay_line() : apply_line();
  std::string body;
  auto printed = g.printed.find(g.files.front());
  if (printed != g.printed.end()) body = printed->second;
  else if (r.property) body = "# the target printed no command file (a sanitizer finding): replay the input\n";
  else body = stream_to_text(bytes);
  const std::string status = status_of_finding(c->signature);
  const std::optional<FindingStatus> status_value = finding_status_named(status);
  const bool call_failure = status_value == FindingStatus::Crash || status_value == FindingStatus::Timeout;
  // A wire host that crashed or hung cannot be replayed on a fresh
  // instance without the user's restart command, unless vgc starts it
  // (--host-cmd: `vgc replay --host-cmd` starts a fresh one).
  const bool launched = !o.host_cmd.empty();
  const bool wire = r.impl.live && !r.impl.live->traits().restartable && !launched;
  const bool confirmable = !call_failure || !wire || !o.restart.empty();
  if (!c->clause.empty() && !r.sign.spent() && !(call_failure && wire)) {
    // Minimized as certify shrinks, before it is written (minimize_finding.h);
    // a crash stays a crash (an exec: program crashed is restarted by the replay).
    OpenOptions open;
    if (o.call_timeout_s > 0) open.timeout_seconds = o.call_timeout_s;
    if (!o.verse_bone_form.empty()) open.verse_bone_form = o.verse_bone_form;
    const Minimized min = minimize_finding(body, c->clause, impl_spec, r.sign.wall_guard, 200, status, open,
                                           o.host_cmd);
    if (min.reproduced && min.after < min.before)
      body = fmt::format("# minimized from {} to {} commands ({} replays); the input replays the original\n",
                         min.before, min.after, min.replays) + min.text;
  }
  if (call_failure && !confirmable)
    c->confirmation = "not confirmed: the host is not restarted without --restart CMD, so the counterexample "
                      "was not replayed on a fresh instance";
  auto write_cex = [&] {
    write_file(cex_file, "# vgc fuzz " + r.s.target + " counterexample: " + c->signature + "\n# from " +
                             g.files.front().string() + "\n# replay: " + c->replay + "\n" + body);
  };
  write_cex();
  if (replayable && confirmable && fs::exists(vgc) && !r.sign.spent()) {
    // Which clause does it replay to? (`vgc replay` exits 1 naming it.)
    // For a crash or hang of a live implementation this is the
    // confirmation on a fresh instance: `vgc replay` starts a new exec:
    // process; a wire host is restarted by the user's command first.
    std::string restarted;
    if (call_failure && wire && !run_restart_command(o.restart, 60, &restarted))
      c->confirmation = "not confirmed: " + restarted;
    const std::string out = run_capture("timeout 60 env " + env_prefix(r.run_env) + shell_quote(vgc) + " replay " +
                                        shell_quote(cex_file.string()) + " --impl " + shell_quote(impl_spec) +
                                        replay_options(o) + " 2>&1; echo \"vgc-replay-exit=$?\"");
    static const std::regex named(R"(\b([A-Z][A-Z0-9]*(?:-[A-Z0-9]+)*-[0-9]+)\b)");
    std::string found;
    if (out.find("vgc-replay-exit=1") != std::string::npos)
      for (std::sregex_iterator it(out.begin(), out.end(), named), end; it != end; ++it)
        if (find_clause((*it)[1].str())) {
          if (found.empty() || (*it)[1].str() == c->clause) found = (*it)[1].str();
          if (found == c->clause) break;
        }
    c->replayed_clause = found;
    if (call_failure && c->confirmation.empty())
      c->confirmation = found == c->clause && out.find(status + " ") != std::string::npos
                            ? "confirmed: `vgc replay` on a fresh instance (" +
                                  std::string(wire       ? "restarted by --restart"
                                              : launched ? "a host started by --host-cmd"
                                                         : "a new process") +
                                  ") shows the " +
                                  status + " again"
                            : "not confirmed: `vgc replay` on a fresh instance did not show the " + status +
                                  " (depends on the instance's history, or flaky)";
    if (plugin_crash) {
      if (!found.empty()) {
        c->clause = found;  // certify's name for the crash
        if (const Clause* cl = find_clause(c->clause)) c->level = clause_level_name(cl->level);
        c->in_baseline = r.baseline.reasons.count(c->clause) > 0;
      } else {
        c->replay = apply_line();
        write_cex();
      }
    }
  } else if (plugin_crash) {
    c->replay = apply_line();
    write_cex();
  }
}

// One finding per signature: described, its input minimized (raw bytes)
// or its program shrunk (clause findings), its counterexample written.
void write_findings(CampaignRun* r, std::map<std::string, CrashGroup>& unique) {
  std::size_t k = 0;
  for (auto& [key, g] : unique) {
    CampaignCrash c = describe_crash(*r, key, g);
    std::string bytes;
    read_file(c.input, &bytes);
    if (!shrinks_as_program(*r, c)) minimize_raw_input(r, key, g, &c, &bytes);
    ++k;
    const char* ext = r->name == "text" ? "txt" : r->mesh ? "mesh.txt" : r->name == "verse_packet" ? "packet.txt" : "vgc";
    c.counterexample = (r->cex / fmt::format("crash-{}{}.{}", k, c.clause.empty() ? "" : "-" + c.clause, ext)).string();
    if (r->name == "text" || r->name == "verse_packet" || r->mesh) write_input_counterexample(*r, g, bytes, &c);
    else write_program_counterexample(*r, g, bytes, &c);
    r->s.crashes.push_back(std::move(c));
  }
}

}  // namespace vgc::fuzz::campaign_steps
