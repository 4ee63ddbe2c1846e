// hierarchical_edit.h — hierarchical edits on Catmull-Clark levels: paths
// naming any face, edge or vertex at any level, vertex set/add edits,
// vertex and edge sharpness edits, face holes.
//
// Spec: 001 "Hierarchical Edits":
//   paths: "a hierarchical path specification for faces"; "By appending a
//   vertex index to a face index, we can create a vertex path
//   specification. For example, (655 2 3 0) specifies the 1st. vertex of the
//   3 rd. child face of the 2 nd. child face of the of the 655 th. face";
//   "Faces also have incident edges, and these are labelled according to
//   the origin vertex of the edge"; child faces: "the sub-face labeled n has
//   one incident vertex that is the result of the subdivision of the parent
//   vertex also labeled n"; child vertices: "in the extraordinary case,
//   vertex to vertex subdivision always results in a vertex labeled 0,
//   while in the regular case, vertex to vertex subdivision assigns the same
//   index to the child vertex" (catmull_clark.h numbers children so);
//   vertex edits: "set" sets the value; "add adds a value to the normal
//   result computed via standard subdivision rules"; vertex edits may also
//   modify "the sharpness"; edge edits "can only modify the sharpness";
//   face "hole": "The faces will be deleted, and none of their children will
//   appear".
// The indices in the example read as 0-based in the text's own ordinals
// ("(655 2 3 0)" ... "the 1st. vertex"): every index here is 0-based.
//
// Rationale: OpenSubdiv 3 dropped hierarchical edits ("support for
// hierarchical features has been removed from the 3.0 release"), so this is
// the suite's own reading. Decisions:
//   - An edit on a component at level k applies after level k is computed
//     and before level k+1 is: it changes level k and, through subdivision,
//     every finer level; coarser levels are untouched. Edits at one level
//     apply in the order given.
//   - A hole changes no position (as OpenSubdiv's holes): the face and all
//     its descendants are flagged (SubdivisionLevel::face_hole).
//   - Sharpness "add" clamps to [0, 10]. A sharpness edit on a boundary
//     edge changes nothing: boundary edges stay infinitely sharp
//     (crease_sharpness.h).
//   - Only the Catmull-Clark scheme (the spec's primitive) takes edits.
#pragma once

#include <array>
#include <vector>

#include "catmull_clark.h"

namespace vgc {

// A face at level children.size(): a base face, then a child index per level.
struct FacePath {
  int base_face = 0;
  std::vector<int> children;
  int level() const { return static_cast<int>(children.size()); }
};

// The face's index in levels[path.level()], or -1 if the path names no face
// (base face out of range, a child index outside 0..n-1 for an n-gon, or
// not enough levels). Precondition: `levels` from subdivide_catmull_clark
// or subdivide_with_edits.
int resolve_face(const std::vector<SubdivisionLevel>& levels, const FacePath& path);
// The vertex `vertex` (0..n-1) of the face, as a vertex index of its level; -1 if none.
int resolve_vertex(const std::vector<SubdivisionLevel>& levels, const FacePath& path, int vertex);
// The edge whose origin is vertex `edge` of the face, as an edge index of its level; -1 if none.
int resolve_edge(const std::vector<SubdivisionLevel>& levels, const FacePath& path, int edge);

enum class EditKind { VertexValue, VertexSharpness, EdgeSharpness, FaceHole };
enum class EditOp { Set, Add };

struct HierarchicalEdit {
  EditKind kind = EditKind::VertexValue;
  EditOp op = EditOp::Set;
  FacePath face;
  int index = 0;                        // vertex or edge index in the face (unused for holes)
  std::array<double, 3> value{0, 0, 0};  // VertexValue
  float sharpness = 0.0f;               // VertexSharpness, EdgeSharpness
};

enum class EditStatus { Ok, BadMesh, BadLevels, BadPath, BadIndex };

// Levels 0..levels of `mesh` with `edits` applied (see the decisions above).
// Failure: a status other than Ok, naming the first problem, with *out
// cleared; an edit deeper than `levels` is BadPath. Precondition: `out` is
// not null; 0 <= levels <= 6.
EditStatus subdivide_with_edits(const MeshArrays& mesh, int levels, const std::vector<HierarchicalEdit>& edits,
                                std::vector<SubdivisionLevel>* out);

}  // namespace vgc
