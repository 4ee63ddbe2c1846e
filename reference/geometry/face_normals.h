// face_normals.h — the front-side normal of a polygon.
//
// Spec: 000 section 2.6 ("All polygons are two-sided, and the front side
// references its vertices in a clockwise manner"); 000 section 2.6.4 (the
// cube: "the four first vertices outline the top quadrilateral, in
// clock-wise order when seen from the outside"); 002 ("n = (C-B) x (A-B)
// ... In a right-handed co-ordinate system the three vertices must be
// specified anti-clockwise round the polygon as you look down the desired
// normal vector (i.e. as you look at the front side of the polygon)").
//
// Decision: "clockwise" is read as in the cube example: looking at the front
// side (from outside, against the normal, in the right-handed x/y/z of the
// vertex layer) the corners run clockwise. 002's formula assumes
// anti-clockwise fronts, so the Verse front normal is its negation:
//   n_front = -((C-B) x (A-B)) = (A-B) x (C-B)    for consecutive corners A, B, C.
// Check on the spec's cube: top face 0,1,2,3 = (-1,1,-1) (1,1,-1) (1,1,1)
// (-1,1,1): (A-B) x (C-B) = (-2,0,0) x (0,0,2) = (0,4,0), pointing up (+y),
// outwards. The bottom face 4,5,6,7 gives (0,-4,0), the front face 3,2,5,4
// gives (0,0,4) (+z; the cube is viewed along -z).
//
// Robustness: a quad (or any polygon) need not be planar and three of its
// corners may be collinear, so the normal is Newell's: the vector area
//   N = 1/2 sum_i (p_i x p_(i+1))   (right-handed, anti-clockwise-positive)
// computed with the equivalent differences form (Newell 1972)
//   N.x = 1/2 sum (y_i - y_j)(z_i + z_j), N.y = 1/2 sum (z_i - z_j)(x_i + x_j),
//   N.z = 1/2 sum (x_i - x_j)(y_i + y_j),  j = i + 1 mod n,
// and negated for the clockwise front. For a triangle it equals half the
// cross product above; for a planar polygon its length is the area; for a
// non-planar one it is the area vector of its projections (the best-fitting
// plane's normal). It does not depend on which corner comes first.
#pragma once

#include <array>
#include <vector>

#include "mesh_arrays.h"

namespace vgc {

using Vec3 = std::array<double, 3>;

// 002's formula as written: (C-B) x (A-B), the normal for anti-clockwise
// corners A, B, C. Precondition: none. Failure: collinear points give 0.
Vec3 triangle_normal_anticlockwise(const Vec3& a, const Vec3& b, const Vec3& c);

// Front-side (clockwise) vector area of the polygon with `corners` (any
// count; fewer than 3 gives 0). Precondition: none. Failure: a degenerate
// polygon gives a zero or tiny vector.
Vec3 polygon_area_vector(const std::vector<Vec3>& corners);

// Front-side vector area of face f of `mesh`. Preconditions:
// 0 <= f < mesh.face_count() and the face's corners index existing
// vertices (check_mesh(mesh) is Ok or not about this face).
Vec3 face_area_vector(const MeshArrays& mesh, int f);

// Unit front-side normal of face f, or (0,0,0) when the area vector's length
// is not above 1e-300 (degenerate face). Preconditions as face_area_vector.
Vec3 face_normal(const MeshArrays& mesh, int f);

// face_normal for every face. Precondition: check_mesh(mesh) == Ok.
std::vector<Vec3> face_normals(const MeshArrays& mesh);

// Small vector helpers shared by the normal code.
Vec3 add(const Vec3& a, const Vec3& b);
Vec3 sub(const Vec3& a, const Vec3& b);
Vec3 scale(const Vec3& a, double s);
double dot(const Vec3& a, const Vec3& b);
Vec3 cross(const Vec3& a, const Vec3& b);
double length(const Vec3& a);
// a / |a|, or (0,0,0) when |a| <= 1e-300.
Vec3 normalized(const Vec3& a);

}  // namespace vgc
