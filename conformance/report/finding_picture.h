// finding_picture.h — what report.html draws for a finding: the final mesh
// of its counterexample with the element the finding is about highlighted
// (svg_mesh.h), and the mesh itself for counterexamples/<CLAUSE>.obj.
//
// Spec: the documents of docs/commands.md section 6 (snapshot and derived
// lines name the vertex, polygon, slot or edge that differs) and the
// capability documents of docs/adapters.md section 5 (?classify,
// ?subdivide, ?subdivide-loop, ?subdivide-edit, ?normals).
//
// Rationale: the report layer sees documents, not oracles. The final state
// is the reference's, replayed from the counterexample's commands (the
// state the implementation should hold). What to highlight comes from what
// the implementation showed (Finding::shown_by, observed_document and the
// differing lines): a snapshot or derived line names its element; a
// ?classify key names a kind of edge (boundary, non-manifold, wrongly
// oriented: mesh_topology.h); a refinement is compared point by point with
// the reference's own answer (which the test suite checks against
// OpenSubdiv), and the points without a partner are the divergent ones.
// A finding with no differing document (a verdict, a crash) highlights
// the element its last command names.
#pragma once

#include <string>

#include "mesh_arrays.h"
#include "run_result.h"
#include "svg_mesh.h"

namespace vgc {

struct FindingPicture {
  // The final state holds a mesh: at least one live vertex. Nothing else
  // is filled when false.
  bool has_mesh = false;
  MeshArrays mesh;  // the reference's final state (the OBJ file)
  // The drawing. For a mesh of more than 600 polygons (a user's mesh,
  // certify --mesh) it is a patch of 64 polygons around the first thing
  // the finding is about, renumbered (its indices are its own, not mesh's),
  // and the caption says so; `mesh` is always whole.
  MeshPicture picture;
  // What is drawn and what is highlighted, for the reader (plain text).
  std::string caption;
  // Something is highlighted or marked (an element, divergent points).
  bool highlighted = false;
};

// The picture of `co`'s counterexample (co.program, co.finding). Never
// throws for any finding or document text.
FindingPicture picture_of_finding(const ClauseOutcome& co);

}  // namespace vgc
