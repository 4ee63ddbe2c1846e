// mesh_certification.cpp — see mesh_certification.h.
#include "mesh_certification.h"
#include "run_budget.h"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <functional>
#include <future>
#include <memory>
#include <thread>
#include <cmath>

#include "cancel.h"
#include "capability.h"
#include "clause.h"
#include "clause_status.h"
#include "command_text.h"
#include "document_diff.h"
#include "node.h"
#include "snapshot.h"

namespace vgc {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The implementation's snapshot against the reference's node: a storage
// finding blamed by the kind of the first differing line (a generated case
// localizes the rule; a mesh of 10^5 commands is compared once), `when`
// saying at which point of the mesh.
std::optional<Finding> snapshot_difference(const Node& model, Implementation& sut, const std::string& when) {
  const std::string want = print_snapshot(model);
  sut.expect_answer_bytes(want.size());
  const Document snap = sut.snapshot();
  if (snap.status != CallStatus::Ok) {
    Finding f = call_failure("STABLE-1", snap.status, "showing the snapshot", snap.detail);
    if (!snap.limit.empty()) {
      f.status = FindingStatus::Timeout;  // vgc's limit, not a verdict
      f.message += " (a limit of vgc's, not a verdict: raise " + snap.limit + ")";
    }
    return f;
  }
  const auto d = diff_documents(want, snap.text);
  if (!d) return std::nullopt;
  Finding f(d->kind == "polygon" ? "POLY-CORNERS-1" : "VERTEX-SET-1", FindingStatus::Fail,
            when + ", the snapshot differs: " + d->describe());
  f.shown_by = "snapshot";
  f.observed_document = snap.text;
  f.expected_line = d->expected_line;
  f.observed_line = d->observed_line;
  return f;
}

// A command the implementation answered otherwise than the reference. If
// its node already differed before the command (a vertex it dropped while
// answering ok, so that a polygon naming it is now refused), the rule
// broken is the one that made it differ, not ACCEPT-1: the reference
// replays the mesh up to the command, once, and the snapshots are compared.
Finding verdict_difference(const MeshProgram& mesh, std::size_t index, Reason want, const Answer& got,
                           Implementation& sut) {
  const Command& c = mesh.program.commands[index];
  const std::string which = "`" + print_command(c) + "` (command " + std::to_string(index + 1) + " of " +
                            std::to_string(mesh.program.commands.size()) + ")";
  if (!got.applied) {
    Node before;
    for (std::size_t k = 0; k < index; ++k) before.apply(mesh.program.commands[k]);
    if (auto f = snapshot_difference(before, sut, "before " + which + ", which it refused (" + got.reason + ")"))
      return *f;
  }
  return Finding("ACCEPT-1", FindingStatus::Fail,
                 which + " of the mesh: expected " +
                     (want == Reason::Ok ? std::string("applied") : std::string("rejected ") + std::string(reason_name(want))) +
                     ", observed " + (got.applied ? "applied" : "rejected " + got.reason));
}

// The mesh on a fresh instance and on the reference: verdicts per command,
// the snapshots once at the end.
// *at: the index of the command a verdict finding came on (the command
// count when the finding is the final snapshot's or a call's).
std::optional<Finding> build(const MeshProgram& mesh, Implementation& sut, Node* model,
                             const std::function<std::string()>& should_stop, std::string* stopped,
                             std::size_t* at = nullptr) {
  const Answer fresh = sut.reset();
  if (fresh.status != CallStatus::Ok) return call_failure("STABLE-1", fresh.status, "resetting to a fresh node", fresh.detail);
  const auto& commands = mesh.program.commands;
  if (at) *at = commands.size();
  for (std::size_t i = 0; i < commands.size(); ++i) {
    if (i % 1024 == 0 && !(*stopped = should_stop()).empty()) {
      *stopped += " while building the mesh (command " + std::to_string(i + 1) + ")";
      return std::nullopt;
    }
    const Reason want = model->apply(commands[i]);
    const Answer got = sut.apply(commands[i]);
    if (got.status != CallStatus::Ok)
      return call_failure("STABLE-1", got.status, "applying `" + print_command(commands[i]) + "`", got.detail);
    // A route that reports no verdict (a host on the Verse wire answers
    // `done`): the snapshot at the end judges what it did with the command.
    if (!got.verdict_reported) continue;
    if (got.applied != (want == Reason::Ok)) {
      if (at) *at = i;
      return verdict_difference(mesh, i, want, got, sut);
    }
  }
  return snapshot_difference(*model, sut, "after the mesh's " + std::to_string(commands.size()) + " commands");
}

bool all_triangles(const MeshProgram& mesh) { return mesh.quads == 0 && mesh.triangles > 0; }

// About how long the answer to a check's request is on `mesh` (bytes), so
// that an out-of-process route's limits scale with it: a vertex line is
// about 60 bytes, a face line 30; level L of Catmull-Clark has 4^(L-1)
// faces per corner, of Loop 4^L per triangle, with about as many vertices
// as faces (half for Loop); ?normals a line per corner.
std::size_t expected_answer_bytes(const std::string& capability, int level, const MeshProgram& mesh) {
  const double corners = 3.0 * static_cast<double>(mesh.triangles) + 4.0 * static_cast<double>(mesh.quads);
  double bytes = 0;
  if (capability == "subdivision") bytes = corners * std::pow(4.0, level - 1) * (30 + 60);
  else if (capability == "loop") bytes = static_cast<double>(mesh.triangles) * std::pow(4.0, level) * (30 + 30);
  else if (capability == "normals") bytes = corners * 80;
  return static_cast<std::size_t>(bytes);
}

}  // namespace

const char* mesh_check_status_name(MeshCheckStatus s) {
  switch (s) {
    case MeshCheckStatus::Pass: return "pass";
    case MeshCheckStatus::Fail: return "fail";
    case MeshCheckStatus::NotJudged: return "not-judged";
    case MeshCheckStatus::NotClaimed: return "not-claimed";
    case MeshCheckStatus::NoOracle: return "no-oracle";
    case MeshCheckStatus::Timeout: return "timeout";
    case MeshCheckStatus::Stopped: return "stopped";
  }
  return "stopped";
}

bool MeshCertification::any_judged() const {
  if (!build_failure && built) return true;  // the storage of the mesh was judged
  for (const auto& c : checks)
    if (c.status == MeshCheckStatus::Pass || c.status == MeshCheckStatus::Fail) return true;
  return false;
}

bool MeshCertification::any_incomplete() const {
  if (!stopped_why.empty()) return true;
  if (build_failure && build_failure->status == FindingStatus::Timeout) return true;
  for (const auto& c : checks)
    if (c.status == MeshCheckStatus::Timeout) return true;
  return false;
}

bool MeshCertification::any_failed() const {
  if (build_failure && build_failure->status == FindingStatus::Timeout) return false;
  if (build_failure) return true;
  for (const auto& c : checks)
    if (c.status == MeshCheckStatus::Fail) return true;
  return false;
}

namespace {

struct Planned {
  const char* capability;
  const char* clause;
  int level;
};

// The checks --levels and --clauses select, in report order.
std::vector<Planned> plan_checks(const MeshProgram& mesh, const MeshCertifyOptions& options) {
  std::vector<Planned> all = {{"manifold", "MESH-CLASSIFY-1", 0}, {"normals", "NORMALS-SPLIT-1", 0}};
  for (int l = 1; l <= options.levels; ++l) all.push_back({"subdivision", "SUBD-CATMARK-1", l});
  if (all_triangles(mesh))
    for (int l = 1; l <= options.levels; ++l) all.push_back({"loop", "LOOP-TRIANGLE-1", l});
  std::vector<Planned> out;
  for (const Planned& p : all)
    if (clause_selected(options.clauses, p.clause)) out.push_back(p);
  return out;
}

// Why the run must stop now ("" to go on): a cancel signal, or the budget
// (run_budget.h: CPU seconds, with a wall-clock guard).
std::string stop_reason(RunBudget& budget) {
  if (cancel_signal()) return std::string("cancelled by ") + cancel_signal_name();
  if (budget.spent()) return budget.why();
  return "";
}

// One claimed check, run on a thread of its own and waited for in steps of
// 50 ms, so that a cancel signal or the budget stops the wait at once. On
// a stop the thread is left running with its own copy of the model
// (*abandoned): the caller must not return through `sut`.
void run_one_check(const Planned& p, const CapabilityCheck& check, const std::shared_ptr<const Node>& model,
                   Implementation& sut, const MeshProgram& mesh, RunBudget& budget, MeshCheckOutcome* o, MeshCertification* out) {
  const auto t = Clock::now();
  const CapabilityRequest request{p.capability, p.level == 0 ? 1 : p.level, std::nullopt};
  sut.expect_answer_bytes(expected_answer_bytes(p.capability, p.level, mesh));
  auto result = std::make_shared<std::promise<std::optional<Finding>>>();
  std::future<std::optional<Finding>> done = result->get_future();
  std::thread([result, &check, model, &sut, request] {
    result->set_value(run_capability_check(check, *model, sut, request));
  }).detach();
  while (done.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
    const std::string why = stop_reason(budget);
    if (why.empty()) continue;
    o->status = MeshCheckStatus::Stopped;
    o->note = why + " during this check";
    o->seconds = since(t);
    out->abandoned = true;
    out->stopped_why = why;
    return;
  }
  std::optional<Finding> f = done.get();
  o->seconds = since(t);
  if (!f) {
    o->status = MeshCheckStatus::Pass;
  } else if (f->status == FindingStatus::NotJudged) {
    o->status = MeshCheckStatus::NotJudged;
    o->note = f->message;
  } else if (f->status == FindingStatus::Timeout) {
    // No answer within vgc's limits: no verdict (the run is incomplete).
    o->status = MeshCheckStatus::Timeout;
    o->note = f->message;
  } else {
    o->status = MeshCheckStatus::Fail;
    o->finding = std::move(f);
  }
}

}  // namespace

MeshCertification certify_mesh(const MeshProgram& mesh, Implementation& sut, const MeshCertifyOptions& options) {
  MeshCertification out;
  out.commands = mesh.program.commands.size();
  auto model = std::make_shared<Node>();
  const auto t0 = Clock::now();
  RunBudget budget(options.budget_seconds);
  out.build_failure = build(mesh, sut, model.get(), [&] { return stop_reason(budget); }, &out.stopped_why);
  out.build_seconds = since(t0);
  if (out.build_failure || !out.stopped_why.empty()) return out;
  out.built = true;
  const std::vector<std::string> claimed = query_capabilities(sut);
  for (const Planned& p : plan_checks(mesh, options)) {
    MeshCheckOutcome o;
    o.capability = p.capability;
    o.clause = p.clause;
    o.level = p.level;
    const bool is_claimed = std::find(claimed.begin(), claimed.end(), p.capability) != claimed.end();
    const CapabilityCheck* check = find_capability_check(p.capability);
    if (!is_claimed) {
      o.status = MeshCheckStatus::NotClaimed;
      o.note = sut.name() + " does not claim \"" + p.capability + "\"";
    } else if (!check || (!check->check && !check->check_drawn)) {
      o.status = MeshCheckStatus::NoOracle;
      o.note = "this vgc has no oracle linked for \"" + std::string(p.capability) + "\"";
    } else if (!out.stopped_why.empty() || !(o.note = stop_reason(budget)).empty()) {
      o.status = MeshCheckStatus::Stopped;
      if (out.stopped_why.empty()) out.stopped_why = o.note;
      o.note = out.stopped_why + " before this check";
    } else {
      run_one_check(p, *check, model, sut, mesh, budget, &o, &out);
    }
    out.checks.push_back(std::move(o));
  }
  return out;
}

namespace {

const char* const kMeshOrigin =
    "The mesh's program, as vgc import writes it (a user's mesh is judged whole, not shrunk)";

std::string check_property_id(const MeshCheckOutcome& c) {
  return "mesh." + c.capability + (c.level ? ".level" + std::to_string(c.level) : "");
}

// A check as a "property" of the run (one case).
PropertyOutcome property_of_check(const MeshCheckOutcome& c) {
  PropertyOutcome p;
  p.id = check_property_id(c);
  p.cases_target = 1;
  p.cases = 1;
  p.seconds = c.seconds;
  switch (c.status) {
    case MeshCheckStatus::Pass: p.status = PropertyStatus::Pass, p.judged = 1; break;
    case MeshCheckStatus::Fail: p.status = PropertyStatus::Fail, p.judged = 1; break;
    case MeshCheckStatus::Stopped: p.status = PropertyStatus::Stopped; break;
    case MeshCheckStatus::NotJudged: p.status = PropertyStatus::Skipped, p.not_judged = 1; break;
    case MeshCheckStatus::Timeout: p.status = PropertyStatus::Skipped; break;
    case MeshCheckStatus::NotClaimed: p.status = PropertyStatus::Skipped, p.skip = PropertySkip::NotClaimed, p.cases = 0; break;
    case MeshCheckStatus::NoOracle: p.status = PropertyStatus::Skipped, p.skip = PropertySkip::NoOracle, p.cases = 0; break;
  }
  if (p.status == PropertyStatus::Skipped || p.status == PropertyStatus::Stopped) p.note = c.note;
  if (c.finding) {
    PropertyFinding pf;
    pf.finding = *c.finding;
    p.findings.push_back(pf);
  }
  return p;
}

// A clause's outcome, its status decided as for any run (clause_status.h).
ClauseOutcome decided(const Clause& clause, const ClauseEvidence& e, ClauseOutcome co) {
  co.clause = &clause;
  co.exercised = e.exercised;
  const ClauseDecision d = decide_clause_status(clause, e);
  co.status = d.status.value_or(ClauseStatus::Unchecked);
  if (co.note.empty()) co.note = d.note;
  return co;
}

// The mesh's storage: the build's finding on its clause, or the clauses a
// difference would have been blamed on, judged once by the snapshot.
void add_build_clauses(const MeshCertification& m, const MeshProgram& mesh, const std::string& built_id,
                       RunResult* run) {
  if (m.build_failure) {
    const Clause* clause = find_clause(m.build_failure->clause);
    if (!clause) return;
    ClauseEvidence e;
    e.declared_and_ran = true;
    ClauseOutcome co;
    co.properties = {built_id};
    if (m.build_failure->status == FindingStatus::Timeout) {  // vgc's limit: no verdict
      e.stopped_note = m.build_failure->message;
    } else {
      e.finding = m.build_failure;
      e.exercised = 1;
      co.finding = m.build_failure;
      co.found_by = built_id;
      co.program = mesh.program;
      co.program.mesh = true;  // replayed as certify --mesh judged it
      co.program_origin = kMeshOrigin;
    }
    run->clauses.push_back(decided(*clause, e, std::move(co)));
    return;
  }
  for (const char* id : {"VERTEX-SET-1", "POLY-CORNERS-1"}) {
    const Clause* clause = find_clause(id);
    if (!clause) continue;
    ClauseEvidence e;
    e.declared_and_ran = true;
    e.exercised = 1;
    ClauseOutcome co;
    co.properties = {built_id};
    run->clauses.push_back(decided(*clause, e, std::move(co)));
  }
}

// One capability clause from its checks (all levels): the first failure's
// finding, with the mesh and the check as its program; not-claimed when the
// implementation claims none; unchecked when no level could be judged, or a
// level stopped or timed out.
ClauseOutcome check_clause(const Clause& clause, const MeshCertification& m, const MeshProgram& mesh) {
  ClauseEvidence e;
  ClauseOutcome co;
  bool any_pass = false, timed_out = false;
  std::string unjudged;
  for (const auto& c : m.checks) {
    if (c.clause != clause.id) continue;
    const std::string prop = check_property_id(c);
    if (c.status != MeshCheckStatus::NotClaimed) e.declared_and_ran = true;
    if (c.status == MeshCheckStatus::Pass || c.status == MeshCheckStatus::Fail) {
      co.properties.push_back(prop);
      ++e.exercised;
    }
    if (c.status == MeshCheckStatus::Pass) any_pass = true;
    const bool no_verdict = c.status == MeshCheckStatus::Timeout || c.status == MeshCheckStatus::Stopped;
    const bool not_judged = c.status == MeshCheckStatus::NotJudged || c.status == MeshCheckStatus::NoOracle;
    if ((not_judged || no_verdict) && unjudged.empty()) unjudged = prop + ": " + c.note;
    if (no_verdict) timed_out = true;
    if (c.status == MeshCheckStatus::Fail && !e.finding) {
      e.finding = c.finding;
      co.finding = c.finding;
      co.found_by = prop;
      co.program.commands = mesh.program.commands;
      co.program.mesh = true;  // replayed as certify --mesh judged it
      co.program_origin = kMeshOrigin;
      co.program.request = CapabilityRequest{c.capability, c.level == 0 ? 1 : c.level, std::nullopt};
    }
  }
  if (!e.declared_and_ran) e.skip = PropertySkip::NotClaimed, e.skip_note = "the implementation does not claim it";
  if (!unjudged.empty() && (!any_pass || timed_out)) e.stopped_note = unjudged;
  return decided(clause, e, std::move(co));
}

}  // namespace

RunResult mesh_run_result(const MeshCertification& m, const MeshProgram& mesh, const std::string& implementation,
                          double seconds) {
  RunResult run;
  run.implementation = implementation;
  run.options.cases = 1;
  run.options.seed = 0;
  run.seconds = seconds;
  if (cancel_signal()) run.cancelled_by = cancel_signal_name();
  // The build judges the node's storage of the whole mesh: its snapshot is
  // the reference's, or its finding is the build's.
  PropertyOutcome built;
  built.id = "mesh.build";
  built.cases = built.cases_target = built.judged = 1;
  built.seconds = m.build_seconds;
  if (m.build_failure && m.build_failure->status == FindingStatus::Timeout) {
    built.status = PropertyStatus::Stopped;
    built.note = m.build_failure->message;
  } else if (m.build_failure) {
    built.status = PropertyStatus::Fail;
  } else if (!m.built) {  // stopped (cancelled, the budget) before the mesh was built
    built.status = PropertyStatus::Stopped;
    built.note = m.stopped_why;
    built.judged = 0;
  } else {
    built.status = PropertyStatus::Pass;
  }
  run.properties.push_back(built);
  if (m.build_failure || m.built) add_build_clauses(m, mesh, built.id, &run);
  if (!m.build_failure && m.built) {
    for (const auto& c : m.checks) run.properties.push_back(property_of_check(c));
    // Clauses in the order of the checks (catalog order for these four).
    std::vector<std::string> order;
    for (const auto& c : m.checks)
      if (std::find(order.begin(), order.end(), c.clause) == order.end()) order.push_back(c.clause);
    for (const std::string& id : order)
      if (const Clause* clause = find_clause(id)) run.clauses.push_back(check_clause(*clause, m, mesh));
  }
  summarize_run(&run);  // the one place a run's completeness and conformance are decided
  return run;
}

namespace {

// The counts expected_answer_bytes scales the limits with, read back from
// the commands mesh_program.cpp writes: a base-layer polygon whose fourth
// corner is unused is a triangle (a first corner unused is a delete).
MeshProgram mesh_of_program(const Program& program) {
  MeshProgram mesh;
  mesh.program.commands = program.commands;
  for (const Command& c : program.commands) {
    const auto* p = std::get_if<cmd::PolygonSetCornerUint32>(&c);
    if (!p || p->layer_id != 1 || p->v[0] == kNone32) continue;
    (p->v[3] == kNone32 ? mesh.triangles : mesh.quads) += 1;
  }
  return mesh;
}

}  // namespace

ReplayResult replay_mesh_program(const Program& program, Implementation& sut) {
  ReplayResult r;
  const MeshProgram mesh = mesh_of_program(program);
  Node model;
  std::string stopped;
  std::size_t at = 0;
  if (auto f = build(mesh, sut, &model, [] { return std::string(); }, &stopped, &at)) {
    r.failure = std::move(f);
    if (at < program.commands.size()) r.failed_at = static_cast<int>(at);
    return r;
  }
  if (!program.request) return r;
  const CapabilityRequest& q = *program.request;
  const std::vector<std::string> claimed = query_capabilities(sut);
  std::string clauses = capability_clauses(q.capability);
  if (clauses.empty()) clauses = "no clause of this vgc";
  if (std::find(claimed.begin(), claimed.end(), q.capability) == claimed.end()) {
    r.not_judged = sut.name() + " does not claim the capability \"" + q.capability + "\" (certify --mesh reports " +
                   clauses + " as not-claimed)";
    return r;
  }
  const CapabilityCheck* check = find_capability_check(q.capability);
  if (!check || (!check->check && !check->check_drawn)) {
    r.not_judged = "this vgc has no oracle linked for the capability \"" + q.capability + "\" (" + clauses +
                   " cannot be judged)";
    return r;
  }
  sut.expect_answer_bytes(expected_answer_bytes(q.capability, q.variant, mesh));
  if (auto f = run_capability_check(*check, model, sut, q)) {
    if (f->status == FindingStatus::NotJudged) {
      r.not_judged = "not judged (" + f->clause + "): " + f->message;
      return r;
    }
    r.failure = std::move(f);
    r.failed_at = static_cast<int>(program.commands.size());
  }
  return r;
}

}  // namespace vgc
