// mesh_certification.h — the derived-geometry checks on a team's own mesh:
// what `vgc certify --mesh FILE.obj` runs (cli/cmd_certify.cpp).
//
// Spec: clauses MESH-CLASSIFY-1 (capability "manifold", against CGAL),
// SUBD-CATMARK-1 ("subdivision", against OpenSubdiv, per level),
// NORMALS-SPLIT-1 ("normals") and LOOP-TRIANGLE-1 ("loop", per level, on an
// all-triangle mesh), through the checks the oracle layer registers
// (capability.h); the mesh as mesh_program.h builds it.
//
// Rationale: generated cases hold a handful of polygons; a production mesh
// holds 10^4 to 10^6 and may show what they never do. The mesh is built on
// a fresh instance of the implementation and on the reference, command by
// command, each verdict compared (a rejected polygon is a finding before
// any geometry is judged), then the two snapshots compared once at the end
// (not after every command: that would cost the square of the mesh). Then
// each capability the implementation claims is judged by the same check
// certify uses, at each level up to `levels` for the leveled ones, and
// reported per level like any capability check: pass, fail (with the
// finding), not judged (the oracle refuses the mesh, says why), or
// not-claimed. Nothing here throws for anything the implementation does.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "check_step.h"
#include "implementation.h"
#include "mesh_program.h"
#include "runner.h"

namespace vgc {

struct MeshCheckOutcome {
  std::string capability;  // "manifold", "subdivision", "normals", "loop"
  std::string clause;      // MESH-CLASSIFY-1, ...
  int level = 0;           // the subdivision level (0 for manifold and normals)
  std::string status;      // "pass", "fail", "not-judged", "not-claimed", "no-oracle", "timeout", "stopped"
  std::optional<Finding> finding;  // for "fail"
  std::string note;        // for "not-judged", "not-claimed", "no-oracle"
  double seconds = 0;
};

struct MeshCertification {
  // Building the mesh on the implementation: the first disagreement with
  // the reference (a verdict, a crash, the final snapshot), if any; the
  // checks are not run then.
  std::optional<Finding> build_failure;
  std::size_t commands = 0;
  double build_seconds = 0;
  std::vector<MeshCheckOutcome> checks;
  // The build is itself judged (the storage of the whole mesh): true when it
  // ran and matched the reference, or when any check passed or failed.
  bool any_judged() const;
  bool any_failed() const;
  // A check (or the build's snapshot) stopped at a limit of vgc's (time,
  // answer size): no verdict on it, the run is incomplete (exit 2).
  bool any_incomplete() const;
  bool built = false;      // the mesh was built and its snapshot compared
  bool abandoned = false;  // a check was left running (see MeshCertifyOptions)
  std::string stopped_why;  // "cancelled by SIGTERM", "the budget of 10 s ran out"
};

// What certify's options select (cli/cmd_certify.cpp --levels, --clauses,
// --budget). A check whose clause the glob does not select is left out; a
// check not started within the budget, or when the run is cancelled
// (cancel.h), is "stopped" and the run incomplete. A check in progress is
// waited for in steps of 50 ms: on cancellation or at the budget it is
// abandoned (`abandoned`: a thread still runs it, so the caller writes its
// report and exits without returning through the implementation).
struct MeshCertifyOptions {
  int levels = 2;
  std::string clauses = "*";
  double budget_seconds = 0;  // 0: none
};

MeshCertification certify_mesh(const MeshProgram& mesh, Implementation& sut, const MeshCertifyOptions& options);

// The certification as a run the report writers take (report.h): one
// "property" per check and level (mesh.<capability>[.level<N>], one case
// each), one clause outcome per clause judged (fail when any level
// failed: the finding of the first, its program the mesh's commands and
// the capability check; pass when every judged level passed; not-claimed,
// or unchecked when no level could be judged). A mesh the implementation
// did not build as the reference is the build finding's clause, failed;
// one it built is "mesh.build", passed, with VERTEX-SET-1 and
// POLY-CORNERS-1 (the storage a difference would be blamed on) passed. A
// route that reports no verdicts (the Verse wire) is judged by the snapshot
// at the end alone.
RunResult mesh_run_result(const MeshCertification& m, const MeshProgram& mesh, const std::string& implementation,
                          double seconds);

// `vgc replay` of a program marked "#! mesh" (Program::mesh): judged as
// certify_mesh judged it, with the same requests, blame and wording: built
// on a fresh instance with a verdict per command and the snapshot once at
// the end (no ?digest), then the directive's capability check, if any,
// with the answer limit scaled with the mesh. Never stopped by a budget.
ReplayResult replay_mesh_program(const Program& program, Implementation& sut);

}  // namespace vgc
