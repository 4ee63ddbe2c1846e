// hierarchical_edit.cpp — see hierarchical_edit.h.
#include "hierarchical_edit.h"

#include <algorithm>

#include "crease_sharpness.h"

namespace vgc {

int resolve_face(const std::vector<SubdivisionLevel>& levels, const FacePath& path) {
  if (levels.empty() || path.level() >= static_cast<int>(levels.size())) return -1;
  int f = path.base_face;
  if (f < 0 || f >= levels[0].face_count()) return -1;
  for (int d = 0; d < path.level(); ++d) {
    const int c = path.children[static_cast<std::size_t>(d)];
    if (c < 0 || c >= levels[static_cast<std::size_t>(d)].face_sizes[static_cast<std::size_t>(f)]) return -1;
    f = levels[static_cast<std::size_t>(d + 1)].first_child_of_parent_face[static_cast<std::size_t>(f)] + c;
  }
  return f;
}

int resolve_vertex(const std::vector<SubdivisionLevel>& levels, const FacePath& path, int vertex) {
  const int f = resolve_face(levels, path);
  if (f < 0) return -1;
  const SubdivisionLevel& l = levels[static_cast<std::size_t>(path.level())];
  if (vertex < 0 || vertex >= l.face_sizes[static_cast<std::size_t>(f)]) return -1;
  return l.face_vertices[static_cast<std::size_t>(l.face_offsets[static_cast<std::size_t>(f)] + vertex)];
}

int resolve_edge(const std::vector<SubdivisionLevel>& levels, const FacePath& path, int edge) {
  const int f = resolve_face(levels, path);
  if (f < 0) return -1;
  const SubdivisionLevel& l = levels[static_cast<std::size_t>(path.level())];
  if (edge < 0 || edge >= l.face_sizes[static_cast<std::size_t>(f)]) return -1;
  return l.face_edges[static_cast<std::size_t>(l.face_offsets[static_cast<std::size_t>(f)] + edge)];
}

namespace {

float edited_sharpness(EditOp op, float old, float value) {
  const float s = op == EditOp::Set ? value : old + value;
  return std::clamp(s, kSharpnessSmooth, kSharpnessInfinite);
}

EditStatus apply_edit(std::vector<SubdivisionLevel>& levels, const HierarchicalEdit& e) {
  SubdivisionLevel& l = levels.back();
  const int f = resolve_face(levels, e.face);
  if (f < 0) return EditStatus::BadPath;
  switch (e.kind) {
    case EditKind::VertexValue:
    case EditKind::VertexSharpness: {
      const int v = resolve_vertex(levels, e.face, e.index);
      if (v < 0) return EditStatus::BadIndex;
      if (e.kind == EditKind::VertexSharpness) {
        float& s = l.vertex_sharpness[static_cast<std::size_t>(v)];
        s = edited_sharpness(e.op, s, e.sharpness);
      } else {
        auto& p = l.positions[static_cast<std::size_t>(v)];
        for (std::size_t k = 0; k < 3; ++k) p[k] = e.op == EditOp::Set ? e.value[k] : p[k] + e.value[k];
      }
      return EditStatus::Ok;
    }
    case EditKind::EdgeSharpness: {
      const int edge = resolve_edge(levels, e.face, e.index);
      if (edge < 0) return EditStatus::BadIndex;
      if (l.edge_face_count[static_cast<std::size_t>(edge)] != 2) return EditStatus::Ok;  // boundary stays infinite
      float& s = l.edge_sharpness[static_cast<std::size_t>(edge)];
      s = edited_sharpness(e.op, s, e.sharpness);
      return EditStatus::Ok;
    }
    case EditKind::FaceHole:
      l.face_hole[static_cast<std::size_t>(f)] = 1;
      return EditStatus::Ok;
  }
  return EditStatus::BadIndex;
}

}  // namespace

EditStatus subdivide_with_edits(const MeshArrays& mesh, int levels, const std::vector<HierarchicalEdit>& edits,
                                std::vector<SubdivisionLevel>* out) {
  out->clear();
  if (levels < 0 || levels > 6) return EditStatus::BadLevels;
  for (const auto& e : edits)
    if (e.face.level() > levels) return EditStatus::BadPath;
  SubdivisionLevel base;
  if (!build_base_level(mesh, &base)) return EditStatus::BadMesh;
  out->push_back(std::move(base));
  for (int k = 0; k <= levels; ++k) {
    if (k > 0) out->push_back(refine_catmull_clark(out->back()));
    for (const auto& e : edits) {
      if (e.face.level() != k) continue;
      const EditStatus s = apply_edit(*out, e);
      if (s != EditStatus::Ok) {
        out->clear();
        return s;
      }
    }
  }
  return EditStatus::Ok;
}

}  // namespace vgc
