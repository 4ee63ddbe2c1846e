// mesh_text_scan.h — the checks a mesh file's text passes before and after
// CGAL reads it (mesh_import.h): its encoding, and, for OBJ and OFF, each
// line's structure with every number read correctly rounded.
//
// Spec: none (file formats: Wavefront OBJ "v x y z" and "f a b c ..." with
// 1-based and negative indices; OFF's header, counts, vertex and face
// records); issue 28: a file vgc cannot read is never an empty mesh.
//
// Rationale: CGAL's readers return false without saying where, and accept
// some lines silently (an OBJ "f" with no corners becomes an empty polygon,
// a corner index one past the last vertex passes its range check). This
// scan names the line and column of what it refuses, and reads every
// coordinate with std::from_chars (correctly rounded, locale-free), so the
// importer can require CGAL's reading to be the same, bit for bit: the
// numbers are never parsed by hand. It accepts what CGAL's OBJ reader
// accepts line for line (the same statements known, the same ignored);
// PLY and STL (binary or text) are CGAL's alone, after the encoding check
// where they are text.
#pragma once

#include <string_view>

#include "mesh_program.h"

namespace vgc {

// Empty, UTF-16/UTF-32 (a byte-order mark or NUL bytes), bytes that are not
// UTF-8: false with *error (line and column of the first such byte).
bool check_text_encoding(std::string_view bytes, MeshFileError* error);

// OBJ text (a UTF-8 byte-order mark already removed): points, polygons
// (0-based) and where each polygon is. False with *error at the first line
// that is not what CGAL's reader reads the same way.
bool scan_obj_text(std::string_view text, PolygonSoup* out, MeshFileError* error);

// OFF text. *complete is false for the variants left to CGAL alone
// (binary, 4OFF homogeneous, nOFF of other dimensions): then *out is empty.
bool scan_off_text(std::string_view text, PolygonSoup* out, bool* complete, MeshFileError* error);

}  // namespace vgc
