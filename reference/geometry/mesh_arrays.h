// mesh_arrays.h — a node's polygon mesh as plain arrays, for derived geometry.
//
// Spec: 000 section 2.6 (polygons reference vertices; 3 or 4 corners; front
// side clockwise) and 2.6.2 (effective creases, crease.h).
//
// Rationale: connectivity, subdivision and normals, in the reference and in
// the oracles alike, work on dense 0-based indices, not on the node's sparse
// ids. This struct of arrays (in the manner of OpenSubdiv's
// Far::TopologyDescriptor) is the one boundary between the node and all of
// them. Tests may also fill it directly, for shapes the node cannot hold.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "node.h"

namespace vgc {

struct MeshArrays {
  // Vertices, in ascending node id order.
  std::vector<std::uint32_t> vertex_ids;              // dense index -> node vertex id
  std::vector<std::array<double, 3>> positions;       // per vertex
  std::vector<std::uint32_t> vertex_creases;          // per vertex: effective crease (0..0xFFFFFFFF)
  // Faces, in ascending node polygon id order.
  std::vector<std::uint32_t> polygon_ids;             // dense index -> node polygon id
  std::vector<int> face_sizes;                        // corners per face
  std::vector<int> face_offsets;                      // first corner of each face in face_vertices
  std::vector<int> face_vertices;                     // dense vertex index per corner, faces concatenated
  std::vector<std::uint32_t> corner_edge_creases;     // per corner: crease of the edge starting there

  int vertex_count() const { return static_cast<int>(positions.size()); }
  int face_count() const { return static_cast<int>(face_sizes.size()); }
};

// The live vertices and polygons of `node` with their effective creases.
// Every corner index is valid because live polygons name live vertices.
MeshArrays extract_mesh(const Node& node);

// The same mesh without the vertices no face uses (the rest keep their
// order and ids). Precondition: every face_vertices index is in range.
MeshArrays remove_unused_vertices(const MeshArrays& mesh);

// Recomputes face_offsets from face_sizes (for meshes built by hand).
void update_face_offsets(MeshArrays& mesh);

}  // namespace vgc
