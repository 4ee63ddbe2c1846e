// obj_writer.h — a node's polygon mesh as a Wavefront OBJ file, to open a
// counterexample's final mesh in Blender or MeshLab (report.html,
// counterexamples/<CLAUSE>.obj).
//
// Spec: 000 section 2.6 (vertices and 3- or 4-corner polygons; the front
// side is the one whose corners run clockwise). OBJ: Wavefront's text
// format, "v x y z" lines and 1-based "f a b c" lines, whose front side is
// the one whose corners run counter-clockwise.
//
// Rationale: OBJ is the format every mesh tool opens. Each face is written
// with its corners reversed, so the side the node calls the front is the
// side Blender and MeshLab call the front (their normals point the same
// way as the node's, face_normals.h). Every live vertex is written, used
// or not, and a comment maps each OBJ index back to the node's vertex id
// (and each face to its polygon id), so what is seen can be found in the
// counterexample. Numbers use the snapshot's exact f64 text
// (number_text.h), so no position is rounded.
#pragma once

#include <string>

#include "mesh_arrays.h"

namespace vgc {

// The OBJ text of `mesh`; `title` goes into the first comment line and the
// object name ("o" line; characters other than letters, digits, '-', '_'
// and '.' become '_').
std::string render_obj(const MeshArrays& mesh, const std::string& title);

}  // namespace vgc
