// polygon_triangulation.h — faces of more than 4 corners split into
// triangles for `vgc import --triangulate` / `certify --mesh --triangulate`.
//
// Spec: 000 section 2.6 (a node's polygon has 3 or 4 corners); CGAL Polygon
// Mesh Processing triangulate_faces (a constrained Delaunay triangulation of
// the face in the plane of its normal: concave faces are split inside
// their outline).
//
// Rationale: production meshes hold n-gons (CGAL's own corpus has faces of
// up to hundreds of corners); a node cannot, and a hand-rolled fan split is
// wrong for a concave face. Each such face becomes triangles in its place
// (same orientation, same corners, no new vertex), in file order, each
// keeping its face's line; faces of 3 or 4 corners are left as they are.
#pragma once

#include <cstddef>

#include "mesh_program.h"

namespace vgc {

// Splits every polygon of more than 4 corners of *soup; returns how many
// it split. False with *error (the face's line) for a face CGAL cannot
// triangulate (all its corners on one line, a corner repeated).
bool triangulate_large_faces(PolygonSoup* soup, std::size_t* split, MeshFileError* error);

}  // namespace vgc
