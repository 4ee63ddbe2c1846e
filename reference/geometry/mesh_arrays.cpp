// mesh_arrays.cpp — see mesh_arrays.h.
#include "mesh_arrays.h"

#include <unordered_map>

#include "crease.h"

namespace vgc {

MeshArrays extract_mesh(const Node& node) {
  MeshArrays m;
  std::unordered_map<std::uint32_t, int> dense;
  for (const auto& [id, slot] : node.vertices()) {
    dense.emplace(id, static_cast<int>(m.positions.size()));
    m.vertex_ids.push_back(id);
    m.positions.push_back({slot.r[0], slot.r[1], slot.r[2]});
    m.vertex_creases.push_back(vertex_crease(node, id));
  }
  for (const auto& [id, slot] : node.polygons()) {
    const int n = corner_count(slot);
    m.polygon_ids.push_back(id);
    m.face_offsets.push_back(static_cast<int>(m.face_vertices.size()));
    m.face_sizes.push_back(n);
    for (int c = 0; c < n; ++c) {
      m.face_vertices.push_back(dense.at(slot.u[static_cast<std::size_t>(c)]));
      m.corner_edge_creases.push_back(edge_crease(node, id, c));
    }
  }
  return m;
}

MeshArrays remove_unused_vertices(const MeshArrays& in) {
  std::vector<int> remap(in.positions.size(), -1);
  for (int v : in.face_vertices) remap[static_cast<std::size_t>(v)] = 0;
  MeshArrays out;
  int next = 0;
  for (std::size_t v = 0; v < in.positions.size(); ++v) {
    if (remap[v] < 0) continue;
    remap[v] = next++;
    out.vertex_ids.push_back(in.vertex_ids[v]);
    out.positions.push_back(in.positions[v]);
    out.vertex_creases.push_back(in.vertex_creases[v]);
  }
  out.polygon_ids = in.polygon_ids;
  out.face_sizes = in.face_sizes;
  out.face_offsets = in.face_offsets;
  for (int v : in.face_vertices) out.face_vertices.push_back(remap[static_cast<std::size_t>(v)]);
  out.corner_edge_creases = in.corner_edge_creases;
  return out;
}

void update_face_offsets(MeshArrays& mesh) {
  mesh.face_offsets.clear();
  int offset = 0;
  for (int n : mesh.face_sizes) {
    mesh.face_offsets.push_back(offset);
    offset += n;
  }
}

}  // namespace vgc
