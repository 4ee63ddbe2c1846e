// mesh_certification.cpp — see mesh_certification.h.
#include "mesh_certification.h"

#include <algorithm>
#include <chrono>

#include "capability.h"
#include "command_text.h"
#include "document_diff.h"
#include "node.h"
#include "snapshot.h"

namespace vgc {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The mesh on a fresh instance and on the reference: verdicts per command,
// the snapshots once at the end.
std::optional<Finding> build(const ObjMesh& mesh, Implementation& sut, Node* model) {
  const Answer fresh = sut.reset();
  if (fresh.status != CallStatus::Ok) return call_failure("STABLE-1", fresh.status, "resetting to a fresh node", fresh.detail);
  for (const Command& c : mesh.program.commands) {
    const Reason want = model->apply(c);
    const Answer got = sut.apply(c);
    if (got.status != CallStatus::Ok)
      return call_failure("STABLE-1", got.status, "applying `" + print_command(c) + "`", got.detail);
    if (got.applied != (want == Reason::Ok))
      return Finding("ACCEPT-1", FindingStatus::Fail,
                     "`" + print_command(c) + "` of the mesh: expected " +
                         (want == Reason::Ok ? std::string("applied") : std::string("rejected ") + std::string(reason_name(want))) +
                         ", observed " + (got.applied ? "applied" : "rejected " + got.reason));
  }
  const Document snap = sut.snapshot();
  if (snap.status != CallStatus::Ok) return call_failure("STABLE-1", snap.status, "showing the snapshot", snap.detail);
  if (auto d = diff_documents(print_snapshot(*model), snap.text)) {
    // Blamed by the kind of the first differing line (a generated case
    // localizes the rule; a mesh of 10^5 commands is compared once).
    Finding f(d->kind == "polygon" ? "POLY-CORNERS-1" : "VERTEX-SET-1", FindingStatus::Fail,
              "after the mesh's " + std::to_string(mesh.program.commands.size()) +
                  " commands, the snapshot differs: " + d->describe());
    f.shown_by = "snapshot";
    f.observed_document = snap.text;
    f.expected_line = d->expected_line;
    f.observed_line = d->observed_line;
    return f;
  }
  return std::nullopt;
}

bool all_triangles(const ObjMesh& mesh) { return mesh.quads == 0 && mesh.triangles > 0; }

}  // namespace

bool MeshCertification::any_judged() const {
  for (const auto& c : checks)
    if (c.status == "pass" || c.status == "fail") return true;
  return false;
}

bool MeshCertification::any_failed() const {
  if (build_failure) return true;
  for (const auto& c : checks)
    if (c.status == "fail") return true;
  return false;
}

MeshCertification certify_mesh(const ObjMesh& mesh, Implementation& sut, int levels) {
  MeshCertification out;
  out.commands = mesh.program.commands.size();
  Node model;
  const auto t0 = Clock::now();
  out.build_failure = build(mesh, sut, &model);
  out.build_seconds = since(t0);
  if (out.build_failure) return out;
  const std::vector<std::string> claimed = query_capabilities(sut);
  struct Planned {
    const char* capability;
    const char* clause;
    int level;
  };
  std::vector<Planned> plan = {{"manifold", "MESH-CLASSIFY-1", 0}, {"normals", "NORMALS-SPLIT-1", 0}};
  for (int l = 1; l <= levels; ++l) plan.push_back({"subdivision", "SUBD-CATMARK-1", l});
  if (all_triangles(mesh))
    for (int l = 1; l <= levels; ++l) plan.push_back({"loop", "LOOP-TRIANGLE-1", l});
  for (const Planned& p : plan) {
    MeshCheckOutcome o;
    o.capability = p.capability;
    o.clause = p.clause;
    o.level = p.level;
    const bool is_claimed = std::find(claimed.begin(), claimed.end(), p.capability) != claimed.end();
    const CapabilityCheck* check = find_capability_check(p.capability);
    if (!is_claimed) {
      o.status = "not-claimed";
      o.note = sut.name() + " does not claim \"" + p.capability + "\"";
    } else if (!check || !check->check) {
      o.status = "no-oracle";
      o.note = "this vgc has no oracle linked for \"" + std::string(p.capability) + "\"";
    } else {
      const auto t = Clock::now();
      std::optional<Finding> f = check->check(model, sut, p.level == 0 ? 1 : p.level);
      o.seconds = since(t);
      if (!f) {
        o.status = "pass";
      } else if (f->status == FindingStatus::NotJudged) {
        o.status = "not-judged";
        o.note = f->message;
      } else {
        o.status = "fail";
        o.finding = std::move(f);
      }
    }
    out.checks.push_back(std::move(o));
  }
  return out;
}

}  // namespace vgc
