// split_normals.h — per-corner ("split", "loop") normals from sharp edges and
// smooth fans, and custom normals kept in a per-fan normal space.
//
// Spec: 003 (Blender split normals): "A sharp edge is either tagged as such,
// non-manifold (i.e. used by more or less than exactly two faces), and/or
// manifold but used by two faces having opposed normals (i.e. opposed
// winding)"; "Smooth fan: a set of loops sharing the same vertex, and
// belonging to faces joined by smooth edges only"; "Each smooth fan has only
// one automatically-computed loop normal, one custom loop normal, and one
// loop normal space"; the loop normal space: first axis the automatic
// normal, reference axis "the normalized projection of the first edge of the
// loop onto the lnor plane", a third axis orthogonal to both. 000 section
// 2.6.2 and the README's corner-to-edge rule give the tag: edge crease
// 0xFFFFFFFF (maximum). Face normals: face_normals.h (clockwise front).
//
// Decisions:
//  - Tag: an edge is tagged sharp when ANY corner using it (on either face)
//    holds the crease 0xFFFFFFFF: the two faces' creases combine by maximum,
//    so one side asking for a hard edge is enough. Smaller creases are
//    smooth here (they only soften subdivision). An empty
//    corner_edge_creases means all 0.
//  - Opposed winding = the edge's two uses run in the same direction
//    (MeshEdge::forward_count != 1).
//  - Fan normal: the sum of the unit front normals of the fan's faces, each
//    weighted by the fan corner's angle (angle-weighted, Thurmer & Wuthrich
//    1998: independent of how faces are split into triangles), normalized.
//    If that sum vanishes, the first corner's face normal; if that also
//    vanishes, (0,0,0).
//  - Normal space of a fan: N = fan normal; R = the normalized projection
//    onto the plane orthogonal to N of the fan's first corner's outgoing
//    edge (corner vertex to the next corner's vertex; first = smallest corner
//    index), falling back to its incoming edge, then to the other corners'
//    edges in ascending order, when a projection is shorter than 1e-9 times
//    the edge; B = N x R. All choices are combinatorial, so the space turns
//    with the mesh under a rigid motion. Unlike Blender, a custom normal is
//    stored as two absolute angles in that frame, not as factors of the
//    fan's angle: theta = angle from N in [0, pi], phi = azimuth from R
//    towards B in (-pi, pi]. Simpler, exact under rigid motions, but it does
//    not follow a fan that is sheared or opened (Blender's reason for
//    relative factors).
#pragma once

#include <optional>
#include <vector>

#include "face_normals.h"
#include "mesh_arrays.h"
#include "mesh_topology.h"

namespace vgc {

struct SplitNormals {
  MeshStatus status = MeshStatus::Ok;
  int bad_face = -1;
  // Filled only when status == Ok.
  std::vector<bool> edge_sharp;            // per MeshTopology edge
  std::vector<int> corner_face;            // per corner (MeshTopology::corner_face)
  std::vector<int> corner_fan;             // per corner
  int fan_count = 0;
  std::vector<int> fan_vertex;             // per fan
  std::vector<int> fan_corner_offsets;     // fan_count + 1 entries
  std::vector<int> fan_corners;            // corners of each fan, ascending
  std::vector<Vec3> face_normals;          // per face, unit front normals
  std::vector<Vec3> fan_normals;           // per fan, unit (or 0 if degenerate)
  std::vector<Vec3> corner_normals;        // per corner: its fan's normal
};

// Whether topology edge e is sharp (decisions above). Preconditions:
// topology is classify_mesh(mesh) with status Ok, 0 <= e < edges.size().
bool is_edge_sharp(const MeshArrays& mesh, const MeshTopology& topology, int e);

// Split normals of `mesh`. Precondition: none (topology is computed; the
// second form takes a precomputed classify_mesh(mesh)). Failure: invalid
// input gives status != Ok (as check_mesh) and nothing else filled.
SplitNormals compute_split_normals(const MeshArrays& mesh);
SplitNormals compute_split_normals(const MeshArrays& mesh, const MeshTopology& topology);

struct FanNormalSpace {
  Vec3 normal{0, 0, 0};     // N, unit
  Vec3 reference{0, 0, 0};  // R, unit, orthogonal to N
  Vec3 bitangent{0, 0, 0};  // B = N x R
  bool valid = false;       // false when N vanished or no edge gave an R
};

// The normal space of fan `fan`. Preconditions: split computed from `mesh`
// with status Ok, 0 <= fan < split.fan_count. Failure: valid == false.
FanNormalSpace fan_normal_space(const MeshArrays& mesh, const SplitNormals& split, int fan);

struct CustomNormal {
  double theta = 0;  // angle from N, [0, pi]
  double phi = 0;    // azimuth from R towards B, (-pi, pi]
};

// Encodes direction `n` (need not be unit; a zero vector encodes as theta 0)
// in `space`. Precondition: space.valid. Failure: none.
CustomNormal encode_custom_normal(const FanNormalSpace& space, const Vec3& n);
// The unit direction `c` stands for in `space`. Precondition: space.valid.
Vec3 decode_custom_normal(const FanNormalSpace& space, const CustomNormal& c);

// Per-corner normals with custom normals: custom[fan] (when present and the
// fan's space is valid) replaces the fan's automatic normal. Preconditions:
// split from `mesh` with status Ok; custom is empty or has fan_count
// entries. Failure: none (invalid spaces keep the automatic normal).
std::vector<Vec3> corner_normals_with_custom(const MeshArrays& mesh, const SplitNormals& split,
                                             const std::vector<std::optional<CustomNormal>>& custom);

}  // namespace vgc
