// check_edits.cpp — ?subdivide-edit against OpenSubdiv and the reference's hierarchical edits (capability_checks.h).
//
// Spec: clause EDIT-HIERARCHY-1; the document of docs/adapters.md "Optional
// capabilities".
#include "capability_checks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "capability_answer.h"
#include "hierarchical_edit.h"
#include "mesh_arrays.h"
#include "number_text.h"
#include "osd_subdivision.h"

namespace vgc {

using namespace capability_answer;

namespace {

constexpr const char* kEditClause = "EDIT-HIERARCHY-1";

// The four kinds of edit check_edits draws, one each per case.
enum DrawnEditKind { kHole, kSet, kAddZero, kAdd };

// An edit drawn for check_one_edit: the edit, its level, and how the
// ?subdivide-edit request spells it.
struct DrawnEdit {
  HierarchicalEdit edit;
  int level = 0;
  std::string text;
};

// The edit of `kind` from the drawn value (splitmix64, so every bit
// counts): a level up to `level`, a face path from a base polygon of
// `mesh`, a corner, and for set and add a value.
DrawnEdit draw_edit(const MeshArrays& mesh, int level, std::uint32_t draw, int kind) {
  std::uint64_t r = draw + 0x9E3779B97F4A7C15ull;
  r = (r ^ (r >> 30)) * 0xBF58476D1CE4E5B9ull;
  r = (r ^ (r >> 27)) * 0x94D049BB133111EBull;
  r ^= r >> 31;
  auto take = [&r](std::uint64_t n) {
    const std::uint64_t v = r % n;
    r /= n;
    return static_cast<int>(v);
  };
  DrawnEdit d;
  HierarchicalEdit& e = d.edit;
  d.level = take(static_cast<std::uint64_t>(level) + 1);
  e.face.base_face = take(static_cast<std::uint64_t>(mesh.face_count()));
  const int base_size = mesh.face_sizes[static_cast<std::size_t>(e.face.base_face)];
  for (int l = 0; l < d.level; ++l) e.face.children.push_back(take(l == 0 ? static_cast<std::uint64_t>(base_size) : 4));
  e.index = take(d.level == 0 ? static_cast<std::uint64_t>(base_size) : 4);
  e.kind = kind == kHole ? EditKind::FaceHole : EditKind::VertexValue;
  e.op = kind == kSet ? EditOp::Set : EditOp::Add;
  if (kind == kSet) e.value = {take(41) * 0.25 - 5, take(41) * 0.25 - 5, take(41) * 0.25 + 3};
  if (kind == kAdd) e.value = {0.5, -0.25, 1 + take(8) * 0.125};
  std::string path = "(" + std::to_string(mesh.polygon_ids[static_cast<std::size_t>(e.face.base_face)]);
  for (int c : e.face.children) path += " " + std::to_string(c);
  if (kind == kHole) {
    d.text = "hole " + path + ")";
  } else {
    d.text = std::string(kind == kSet ? "set " : "add ") + path + " " + std::to_string(e.index) + ") " +
             format_f64(e.value[0]) + " " + format_f64(e.value[1]) + " " + format_f64(e.value[2]);
  }
  return d;
}

// Asks ?subdivide-edit AT EDIT and reads the answer into *got: a finding
// when the call fails, the document is unreadable, of another level, or its
// face lines disagree with its face count.
std::optional<Finding> ask_edit(Implementation& sut, int at, const std::string& edit, SubdivisionAnswer* got,
                                std::string* request) {
  *request = "?subdivide-edit " + std::to_string(at) + " " + edit;
  const Document d = sut.request(*request);
  if (auto f = check_answer(kEditClause, *request, d, "vgc-subdivision")) return f;
  if (auto problem = read_subdivision(d.text, got)) return finding(kEditClause, *request + ": " + *problem);
  if (got->level != at) return finding(kEditClause, *request + ": the document says level " + std::to_string(got->level));
  if (static_cast<long>(got->face_lines.size()) != got->faces)
    return finding(kEditClause, *request + ": " + std::to_string(got->face_lines.size()) + " face lines but faces " +
                                    std::to_string(got->faces));
  return std::nullopt;
}

// Each face line must be a face of the level (`positions`, `sizes`,
// `corners`) whose flag in `allowed` is set, compared by the positions of
// its corners (same cycle, any starting corner, within the tolerance:
// coinciding vertices make a pairing by index arbitrary), each face used
// once.
std::optional<Finding> faces_among(const SubdivisionAnswer& got, const std::vector<std::array<double, 3>>& positions,
                                   const std::vector<int>& sizes, const std::vector<int>& corners,
                                   const std::vector<char>& allowed, const std::string& request,
                                   const std::string& source) {
  const double tol = tolerance_of(positions);
  std::vector<std::size_t> offset(sizes.size() + 1, 0);
  for (std::size_t f = 0; f < sizes.size(); ++f) offset[f + 1] = offset[f] + static_cast<std::size_t>(sizes[f]);
  auto same_cycle = [&](const std::vector<int>& line, std::size_t f) {
    const std::size_t n = line.size();
    if (n != static_cast<std::size_t>(sizes[f])) return false;
    for (std::size_t r = 0; r < n; ++r) {
      bool same = true;
      for (std::size_t k = 0; same && k < n; ++k)
        same = near(got.vertices[static_cast<std::size_t>(line[k])],
                    positions[static_cast<std::size_t>(corners[offset[f] + (k + r) % n])], tol);
      if (same) return true;
    }
    return false;
  };
  std::vector<char> used(sizes.size(), 0);
  for (std::size_t i = 0; i < got.face_lines.size(); ++i) {
    std::size_t hit = used.size();
    bool removed = false;
    for (std::size_t f = 0; f < used.size() && hit == used.size(); ++f) {
      if (used[f] || !same_cycle(got.face_lines[i], f)) continue;
      if (allowed[f]) hit = f;
      else removed = true;
    }
    if (hit == used.size())
      return finding(kEditClause, request + ": face line " + std::to_string(i) + " is " +
                                      (removed ? "a face the hole removes (it or an ancestor is the hole) in " + source
                                               : "no face of " + source + " (or one given twice)"));
    used[hit] = 1;
  }
  return std::nullopt;
}

// An edit changes its own level and the finer ones: the level just above
// it is OpenSubdiv's plain refinement.
std::optional<Finding> check_level_above_edit(const OsdResult& osd, Implementation& sut, const DrawnEdit& d) {
  SubdivisionAnswer got;
  std::string request;
  if (auto f = ask_edit(sut, d.level - 1, d.text, &got, &request)) return f;
  const OsdLevel& plain = osd.levels[static_cast<std::size_t>(d.level - 1)];
  std::vector<int> g2w;
  if (auto problem = compare_with_level(got, plain.positions, static_cast<long>(plain.face_sizes.size()),
                                        "OpenSubdiv (the edit is at level " + std::to_string(d.level) +
                                            ", so this level is untouched)",
                                        &g2w))
    return finding(kEditClause, request + ": " + *problem);
  return std::nullopt;
}

// Holes at level 0: OpenSubdiv's own holes (TopologyDescriptor holeIndices).
std::optional<Finding> check_base_hole(const MeshArrays& mesh, int level, const DrawnEdit& d,
                                       const SubdivisionAnswer& got, const std::string& request) {
  OsdInput in = osd_input_from_mesh(mesh, OsdScheme::CatmullClark, level);
  in.hole_faces.push_back(d.edit.face.base_face);
  const OsdResult holed = osd_refine_uniform(in);
  if (!holed.ok || holed.levels.size() != static_cast<std::size_t>(level) + 1) return std::nullopt;
  const OsdLevel& want = holed.levels.back();
  std::vector<char> allowed(want.face_sizes.size(), 1);
  long kept = 0;
  for (std::size_t f = 0; f < allowed.size(); ++f) {
    allowed[f] = f < want.face_hole.size() && want.face_hole[f] ? 0 : 1;
    kept += allowed[f];
  }
  std::vector<int> g2w;
  if (auto problem = compare_with_level(got, want.positions, kept, "OpenSubdiv with the hole", &g2w))
    return finding(kEditClause, request + ": " + *problem);
  return faces_among(got, want.positions, want.face_sizes, want.face_vertices, allowed, request,
                     "OpenSubdiv's refinement with the hole");
}

// A hole deeper down removes exactly its descendants at this level (4 per
// level below it: they are quads) and moves nothing; add 0 changes nothing.
std::optional<Finding> check_nothing_moved(const OsdLevel& plain, int level, int kind, const DrawnEdit& d,
                                           const SubdivisionAnswer& got, const std::string& request) {
  long removed = 0;
  if (kind == kHole) {
    removed = 1;
    for (int l = d.level; l < level; ++l) removed *= 4;
  }
  std::vector<int> g2w;
  if (auto problem = compare_with_level(got, plain.positions, static_cast<long>(plain.face_sizes.size()) - removed,
                                        kind == kHole ? "OpenSubdiv (a hole at level " + std::to_string(d.level) +
                                                            " moves nothing and removes " + std::to_string(removed) +
                                                            " faces here)"
                                                      : std::string("OpenSubdiv (add 0 changes nothing)"),
                                        &g2w))
    return finding(kEditClause, request + ": " + *problem);
  return faces_among(got, plain.positions, plain.face_sizes, plain.face_vertices,
                     std::vector<char>(plain.face_sizes.size(), 1), request, "OpenSubdiv's refinement");
}

// At the edit's own level only the edited vertex moved (OpenSubdiv's plain
// vertices for all the others), and "set" puts it at the value.
std::optional<Finding> check_one_vertex_moved(const OsdLevel& plain, int kind, const DrawnEdit& d,
                                              const SubdivisionAnswer& got, const std::string& request) {
  std::vector<int> w2g;
  std::vector<std::size_t> unmatched;
  match_vertices(plain.positions, got.vertices, tolerance_of(plain.positions), &w2g, &unmatched);
  if (got.vertices.size() != plain.positions.size() || unmatched.size() != 1)
    return finding(kEditClause, request + ": " + std::to_string(unmatched.size()) + " of " +
                                    std::to_string(got.vertices.size()) + " vertices are not OpenSubdiv's (of " +
                                    std::to_string(plain.positions.size()) +
                                    "); an edit at the answer's own level moves exactly one");
  if (kind == kSet && got.vertices[unmatched[0]] != d.edit.value)
    return finding(kEditClause, request + ": the moved vertex is at " + point_text(got.vertices[unmatched[0]]) +
                                    "; \"set\" puts it at " + point_text(d.edit.value));
  return std::nullopt;
}

// The rest has no external oracle (OpenSubdiv 3 dropped hierarchical
// edits): the reference's reading (hierarchical_edit.h).
std::optional<Finding> check_reference_edit(const MeshArrays& mesh, int level, const DrawnEdit& d,
                                            const SubdivisionAnswer& got, const std::string& request) {
  std::vector<SubdivisionLevel> ref;
  if (subdivide_with_edits(mesh, level, {d.edit}, &ref) != EditStatus::Ok) return std::nullopt;
  const SubdivisionLevel& want = ref.back();
  long kept = 0;
  for (unsigned char h : want.face_hole) kept += h ? 0 : 1;
  std::vector<int> g2w;
  if (auto problem = compare_with_level(got, want.positions, kept, "the reference's hierarchical edit", &g2w))
    return finding(kEditClause, request + ": " + *problem);
  std::vector<char> kept_faces(want.face_hole.size());
  for (std::size_t f = 0; f < kept_faces.size(); ++f) kept_faces[f] = want.face_hole[f] ? 0 : 1;
  return faces_among(got, want.positions, want.face_sizes, want.face_vertices, kept_faces, request,
                     "the reference's hierarchical edit");
}

// One edit of `kind` (0 hole, 1 set, 2 add 0, 3 add) chosen from `draw`;
// see check_edits.
// `mesh` is the model's polygons without unused vertices, `osd` its
// OpenSubdiv refinement to `level` (oracle_refinement).
std::optional<Finding> check_one_edit(const MeshArrays& mesh, const OsdResult& osd, Implementation& sut, int level,
                                      std::uint32_t draw, int kind) {
  const DrawnEdit d = draw_edit(mesh, level, draw, kind);
  if (d.level >= 2)
    if (auto f = check_level_above_edit(osd, sut, d)) return f;
  SubdivisionAnswer got;
  std::string request;
  if (auto f = ask_edit(sut, level, d.text, &got, &request)) return f;
  const OsdLevel& plain = osd.levels.back();
  if (kind == kHole && d.level == 0) return check_base_hole(mesh, level, d, got, request);
  if (kind == kHole || kind == kAddZero) {
    if (auto f = check_nothing_moved(plain, level, kind, d, got, request)) return f;
    if (kind == kAddZero) return std::nullopt;
  }
  // Only where the tolerance is far below the move: coordinates up to 1e6.
  if (d.level == level && kind != kHole && tolerance_of(plain.positions) <= 1e-3)
    if (auto f = check_one_vertex_moved(plain, kind, d, got, request)) return f;
  return check_reference_edit(mesh, level, d, got, request);
}

}  // namespace

std::optional<Finding> check_edits(const Node& model, Implementation& sut, int level, std::uint32_t draw) {
  // Every kind in each case, each with its own path from the same draw, so
  // that a fault in one kind does not hide behind the others' cases.
  const MeshArrays mesh = remove_unused_vertices(extract_mesh(model));
  if (mesh.face_count() == 0) return std::nullopt;  // no face for an edit to name
  std::string why;
  const std::optional<OsdResult> osd = oracle_refinement(mesh, OsdScheme::CatmullClark, level, &why);
  if (!osd) return not_judged("EDIT-HIERARCHY-1", "?subdivide-edit " + std::to_string(level) + ": " + why);
  for (int kind = 0; kind < 4; ++kind)
    if (auto f = check_one_edit(mesh, *osd, sut, level, draw + 0x632BE5ABu * static_cast<std::uint32_t>(kind), kind))
      return f;
  return std::nullopt;
}

}  // namespace vgc
