// mesh_program.h — a mesh file's polygons as a command program: what `vgc
// import FILE` prints and what `vgc certify --mesh FILE` builds the node
// from. The file itself is read in the oracle layer (oracles/mesh_import.h:
// CGAL's OBJ, OFF, PLY and STL readers); this is the format-neutral half.
//
// Spec: 000 section 2.6 (vertices on layer 0, polygons of 3 or 4 corners on
// layer 1, the front side the one whose corners run clockwise; creases
// 2.6.2); docs/commands.md (the command file).
//
// Rationale: a team's own mesh shows what no generated case does. Vertex k
// of the file (0-based, in file order) becomes vertex id k
// (vertex_set_xyz_real64 on layer 0), face j (in file order) polygon id j
// (polygon_set_corner_uint32 on layer 1) with its corners reversed: the
// front of OBJ, OFF, PLY and STL is counter-clockwise, the node's
// clockwise, and report/obj_writer.h writes faces reversed, so a node
// exported and imported again is the same node, bit for bit (positions are
// read correctly rounded and written in the shortest text that reads back
// the same). Normals, texture coordinates, colours, materials and groups
// are not geometry the node holds and are dropped. No format here has
// creases: the program sets none, so the node keeps its default settings
// ("" and 0: smooth everywhere, docs/commands.md 4.7). A face of more than
// 4 corners is an error naming the option that splits it (--triangulate),
// as is a face of fewer than 3 or a corner naming a vertex the file does
// not have: each names the file's line and the corner's column where the
// format has lines.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "program.h"

namespace vgc {

// A file's polygons as read, before they become commands.
struct PolygonSoup {
  std::string format;  // "OBJ", "OFF", "PLY", "STL"
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> polygons;
  // Where each polygon is in the file (1-based line, column of its first
  // corner); 0 where the format has no lines (binary PLY and STL).
  std::vector<std::size_t> polygon_lines, polygon_columns;
};

struct MeshProgram {
  std::string format;
  Program program;  // the commands, from a fresh node; no capability request
  std::size_t vertices = 0, triangles = 0, quads = 0;
  std::size_t split_faces = 0;  // faces of 5+ corners --triangulate split
  std::vector<std::string> warnings;
};

struct MeshFileError {
  std::size_t line = 0, column = 0;  // 0 when the error is the file's as a whole
  std::string message;
};

// The program of `soup`: every polygon must have 3 or 4 corners naming
// points of the soup (else false with *error at the polygon's line).
bool program_from_soup(const PolygonSoup& soup, MeshProgram* out, MeshFileError* error);

// The command file of an import: comments saying where it comes from and
// what became of sharpness, then the commands (program_text.h). Nothing of
// `path` can end a comment line: every byte outside printable text, the
// newline included, is written \xHH.
std::string print_mesh_import(const MeshProgram& mesh, const std::string& path);

// `text` on one line: escape_unprintable, and newlines as \x0a too (a file
// name in an error message or a comment).
std::string one_line_text(const std::string& text);

}  // namespace vgc
