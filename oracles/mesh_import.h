// mesh_import.h — a mesh file (OBJ, OFF, PLY, STL) as a command program:
// what `vgc import FILE` and `vgc certify --mesh FILE` read.
//
// Spec: 000 section 2.6 through mesh_program.h (what the program holds);
// the formats as CGAL 5.5 reads them (CGAL::IO::read_OBJ, read_OFF,
// read_PLY, read_STL polygon soups); issue 28 (a file vgc cannot read is
// never certified, numbers read correctly rounded).
//
// Rationale: CGAL is already a dependency and reads the four formats a
// modeller exports; its headers stay in this layer. The format is the file
// name's extension (case-insensitive); a name with none of the four is
// refused, never guessed. A text file (OBJ, OFF; PLY and STL are checked
// where their header says text) must be UTF-8 or ASCII, non-empty, and
// pass mesh_text_scan.h, which names the line and column of what it
// refuses; CGAL's reading must then be the scan's, point for point (bit for
// bit) and corner for corner, or the file is refused: an importer that
// reads numbers inexactly cannot certify exact storage. A mesh of no face
// is refused too. Nothing of the file's name or content reaches the
// program but numbers.
#pragma once

#include <string>

#include "mesh_program.h"

namespace vgc {

struct MeshImportOptions {
  bool triangulate = false;  // split faces of more than 4 corners (polygon_triangulation.h)
};

// Reads `path`. On failure returns false with *error (line and column when
// the error is a line's).
bool import_mesh(const std::string& path, const MeshImportOptions& options, MeshProgram* out, MeshFileError* error);

}  // namespace vgc
