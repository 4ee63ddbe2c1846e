// triangle_tree.cpp — see triangle_tree.h.
#include "triangle_tree.h"

namespace vgc {

int corner_child_of_vertex(int vertex) { return vertex >= 0 && vertex < 3 ? vertex + 1 : -1; }

int nearest_vertex_of_child(int child) { return child >= 1 && child <= 3 ? child - 1 : -1; }

std::array<int, 2> edge_vertices(int edge) {
  if (edge < 0 || edge >= 3) return {-1, -1};
  return {(edge + 1) % 3, (edge + 2) % 3};
}

std::array<TreeCorner, 3> child_corner_names(int child) {
  std::array<TreeCorner, 3> names{};
  if (child < 0 || child >= 4) return names;
  const int nearest = nearest_vertex_of_child(child);
  for (int k = 0; k < 3; ++k) names[static_cast<std::size_t>(k)] = TreeCorner{k != nearest, k};
  return names;
}

int child_triangle(const SubdivisionLevel& child_level, int parent_face, int child) {
  if (parent_face < 0 || parent_face >= static_cast<int>(child_level.first_child_of_parent_face.size())) return -1;
  if (child < 0 || child >= 4) return -1;
  return child_level.first_child_of_parent_face[static_cast<std::size_t>(parent_face)] + child;
}

int sub_vertex(const SubdivisionLevel& parent, const SubdivisionLevel& child_level, int parent_face, int k) {
  if (parent_face < 0 || parent_face >= parent.face_count() || parent.face_sizes[parent_face] != 3) return -1;
  if (k < 0 || k >= 3) return -1;
  // Corner i's edge runs from vertex i to i+1, so edge k (opposite vertex k) is corner k+1's.
  const int e = parent.face_edges[static_cast<std::size_t>(parent.face_offsets[parent_face] + (k + 1) % 3)];
  if (e < 0 || e >= static_cast<int>(child_level.child_of_parent_edge.size())) return -1;
  return child_level.child_of_parent_edge[static_cast<std::size_t>(e)];
}

std::array<int, 3> named_child_vertices(const SubdivisionLevel& parent, const SubdivisionLevel& child_level,
                                        int parent_face, int child) {
  std::array<int, 3> out{-1, -1, -1};
  if (child < 0 || child >= 4 || parent_face < 0 || parent_face >= parent.face_count() ||
      parent.face_sizes[parent_face] != 3)
    return out;
  const auto names = child_corner_names(child);
  for (int k = 0; k < 3; ++k) {
    const TreeCorner& n = names[static_cast<std::size_t>(k)];
    if (n.sub_vertex) {
      out[static_cast<std::size_t>(k)] = sub_vertex(parent, child_level, parent_face, n.index);
    } else {
      const int v = parent.face_vertices[static_cast<std::size_t>(parent.face_offsets[parent_face] + n.index)];
      out[static_cast<std::size_t>(k)] = child_level.child_of_parent_vertex[static_cast<std::size_t>(v)];
    }
  }
  return out;
}

}  // namespace vgc
