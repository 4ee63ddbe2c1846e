// obj_import.h — a Wavefront OBJ mesh as a command program: what `vgc
// import FILE.obj` prints and what `vgc certify --mesh FILE.obj` builds the
// node from.
//
// Spec: 000 section 2.6 (vertices on layer 0, polygons of 3 or 4 corners on
// layer 1, the front side the one whose corners run clockwise; creases
// 2.6.2); docs/commands.md (the command file). OBJ: Wavefront's text
// format, read with tinyobjloader (Debian libtinyobjloader-dev, double
// precision), not a parser of our own.
//
// Rationale: a team's own mesh shows what no generated case does. Vertex k
// of the file (1-based in OBJ) becomes vertex id k-1 (vertex_set_xyz_real64
// on layer 0), face j (in file order, across objects and groups) polygon id
// j-1 (polygon_set_corner_uint32 on layer 1) with its corners reversed:
// OBJ's front is counter-clockwise, the node's clockwise, and
// report/obj_writer.h writes faces reversed, so a node exported and
// imported again is the same node (positions as tinyobjloader reads them:
// its number reading is not always correctly rounded, one unit in the last
// place off, e.g. 0.7071067811865476 read as 0.7071067811865475; the
// program carries what it read, so implementation and reference get the
// same values). Normals, texture coordinates, materials,
// groups and smoothing groups are not geometry the node holds and are
// dropped. OBJ has no creases: the program sets none, so the node keeps its
// default settings ("" and 0: smooth everywhere, docs/commands.md 4.7);
// smoothing groups (`s`) are about shading normals, not creases, and are
// not turned into sharp edges. A face of more than 4 corners is an error
// (the node holds 3 or 4), as is a face whose corner names a vertex the file
// does not have: each names the file's line and the corner's column.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "runner.h"

namespace vgc {

struct ObjMesh {
  Program program;  // the commands, from a fresh node; no capability request
  std::size_t vertices = 0, triangles = 0, quads = 0;
  std::vector<std::string> warnings;  // tinyobjloader's (a missing material library, ...)
};

struct ObjError {
  std::size_t line = 0, column = 0;  // 0 when the error is the file's as a whole
  std::string message;
};

// Reads `path`. On failure returns false with *error (line and column when
// the error is a line's).
bool import_obj(const std::string& path, ObjMesh* out, ObjError* error);

// The command file of an import: comments saying where it comes from and
// what became of sharpness, then the commands (program_text.h).
std::string print_obj_import(const ObjMesh& mesh, const std::string& path);

}  // namespace vgc
