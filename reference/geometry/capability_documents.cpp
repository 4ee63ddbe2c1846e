// capability_documents.cpp — see capability_documents.h.
#include "capability_documents.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "catmull_clark.h"
#include "hierarchical_edit.h"
#include "loop_subdivision.h"
#include "mesh_arrays.h"
#include "mesh_topology.h"
#include "number_text.h"
#include "split_normals.h"

namespace vgc {
namespace {

const char* yes_no(bool b) { return b ? "yes" : "no"; }

// Reads an edit of ?subdivide-edit: "hole (<polygon id> <child>...)" or
// "set|add (<polygon id> <child>... <vertex>) <x> <y> <z>"; false if malformed.
bool parse_edit(const std::string& text, HierarchicalEdit* e, std::uint32_t* polygon_id) {
  const auto open = text.find('('), close = text.find(')');
  if (open == std::string::npos || close == std::string::npos || close < open) return false;
  std::istringstream head(text.substr(0, open)), path(text.substr(open + 1, close - open - 1)),
      tail(text.substr(close + 1));
  std::string op, w, extra;
  if (!(head >> op) || (head >> extra)) return false;
  std::vector<std::uint32_t> numbers;
  while (path >> w) {
    std::uint32_t n = 0;
    if (!parse_uint(w, 32, &n)) return false;
    numbers.push_back(n);
  }
  if (op == "hole") {
    e->kind = EditKind::FaceHole;
    if (numbers.empty() || (tail >> extra)) return false;
  } else if (op == "set" || op == "add") {
    e->kind = EditKind::VertexValue;
    e->op = op == "set" ? EditOp::Set : EditOp::Add;
    if (numbers.size() < 2) return false;
    e->index = static_cast<int>(std::min<std::uint32_t>(numbers.back(), 1u << 30));
    numbers.pop_back();
    for (double& x : e->value)
      if (!(tail >> w) || !parse_f64(w, &x) || !std::isfinite(x)) return false;
    if (tail >> extra) return false;
  } else {
    return false;
  }
  if (numbers.size() > 4) return false;  // paths to level 3 at most
  *polygon_id = numbers[0];
  e->face.children.clear();
  for (std::size_t i = 1; i < numbers.size(); ++i)
    e->face.children.push_back(static_cast<int>(std::min<std::uint32_t>(numbers[i], 1u << 30)));
  return true;
}



}  // namespace

std::string print_capabilities() { return "capabilities manifold subdivision normals loop edits\nend\n"; }

const char* capability_document_header(const std::string& line) {
  const std::string word = line.substr(0, line.find(' '));
  if (word == "?capabilities") return "capabilities";
  if (word == "?classify") return "vgc-classify";
  if (word == "?subdivide") return "vgc-subdivision";
  if (word == "?normals") return "vgc-normals";
  if (word == "?subdivide-loop" || word == "?subdivide-edit") return "vgc-subdivision";
  return nullptr;
}

std::string print_normals(const Node& node, const CapabilityDocumentFaults& faults) {
  const MeshArrays mesh = extract_mesh(node);
  const SplitNormals s = compute_split_normals(mesh);
  if (s.status != MeshStatus::Ok) return "error the polygons cannot be given split normals\n";
  std::string out = "vgc-normals 1\n";
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int k = 0; k < mesh.face_sizes[static_cast<std::size_t>(f)]; ++k) {
      const auto c = static_cast<std::size_t>(mesh.face_offsets[static_cast<std::size_t>(f)] + k);
      Vec3 n = faults.flat_normals ? s.face_normals[static_cast<std::size_t>(f)] : s.corner_normals[c];
      const auto fan = static_cast<std::size_t>(s.corner_fan[c]);
      const int fan_size = s.fan_corner_offsets[fan + 1] - s.fan_corner_offsets[fan];
      if (faults.perturb_fan_normals && fan_size > 1) n[0] += 1e-6;
      if (faults.negate_lone_corners && fan_size == 1)
        for (double& x : n) x = -x;
      out += "corner " + std::to_string(mesh.polygon_ids[static_cast<std::size_t>(f)]) + " " + std::to_string(k) +
             " " + format_f64(n[0]) + " " + format_f64(n[1]) + " " + format_f64(n[2]) + "\n";
    }
  return out + "end\n";
}

std::string print_classify(const Node& node, const CapabilityDocumentFaults& faults) {
  const MeshTopology t = classify_mesh(extract_mesh(node));
  std::string out = "vgc-classify 1\n";
  const bool pm = t.status == MeshStatus::Ok && t.is_polygon_mesh;
  out += std::string("polygon_mesh ") + yes_no(pm) + "\n";
  if (pm) {
    out += std::string("closed ") + yes_no(t.closed) + "\n";
    out += std::string("oriented ") + yes_no(t.consistently_oriented) + "\n";
    out += "euler " + std::to_string(t.euler_characteristic) + "\n";
    out += "components " + std::to_string(t.component_count) + "\n";
    const std::size_t loops = t.boundary_loops ? t.boundary_loops->size() : 0;
    out += "boundary_loops " + std::to_string(faults.zero_boundary_loops ? 0 : loops) + "\n";
  }
  return out + "end\n";
}

std::string print_subdivision(const Node& node, int level, const CapabilityDocumentFaults& faults) {
  if (level < 1 || level > 3) return "error ?subdivide takes a level from 1 to 3\n";
  MeshArrays mesh = remove_unused_vertices(extract_mesh(node));
  if (faults.ignore_creases) {
    for (auto& c : mesh.vertex_creases) c = 0;
    for (auto& c : mesh.corner_edge_creases) c = 0;
  }
  std::string out = "vgc-subdivision 1\nlevel " + std::to_string(level) + "\n";
  std::size_t faces = 0;
  if (mesh.face_count() > 0) {
    CatmullClarkFaults cf;
    cf.no_non_manifold_rule = faults.non_manifold_smooth;
    const auto levels = subdivide_catmull_clark(mesh, level, cf);
    if (levels.size() != static_cast<std::size_t>(level) + 1) return "error the mesh cannot be subdivided\n";
    for (const auto& p : levels.back().positions)
      out += "vertex " + format_f64(p[0]) + " " + format_f64(p[1]) + " " + format_f64(p[2]) + "\n";
    faces = levels.back().face_sizes.size();
  }
  return out + "faces " + std::to_string(faces) + "\nend\n";
}

std::string print_loop_subdivision(const Node& node, int level, const CapabilityDocumentFaults& faults) {
  if (level < 1 || level > 3) return "error ?subdivide-loop takes a level from 1 to 3\n";
  const MeshArrays mesh = remove_unused_vertices(extract_mesh(node));
  for (int size : mesh.face_sizes)
    if (size != 3)
      return faults.loop_answers_quads ? "vgc-subdivision 1\nlevel " + std::to_string(level) + "\nfaces 0\nend\n"
                                       : "error ?subdivide-loop needs every polygon to be a triangle\n";
  std::string out = "vgc-subdivision 1\nlevel " + std::to_string(level) + "\n";
  std::size_t faces = 0;
  if (mesh.face_count() > 0) {
    LoopFaults lf;
    lf.warren_weights = faults.loop_warren_weights;
    lf.edges_by_vertex_pair = faults.loop_edges_by_vertex_pair;
    const auto levels = subdivide_loop(mesh, level, lf);
    if (levels.size() != static_cast<std::size_t>(level) + 1) return "error the mesh cannot be subdivided\n";
    const SubdivisionLevel& last = levels.back();
    for (const auto& p : last.positions)
      out += "vertex " + format_f64(p[0]) + " " + format_f64(p[1]) + " " + format_f64(p[2]) + "\n";
    // refine_loop puts each parent's children T0..T3 consecutively, in
    // parent order: the level's face order is the tree order.
    for (int f = 0; f < last.face_count(); ++f) {
      const int o = last.face_offsets[static_cast<std::size_t>(f)];
      const int r = faults.loop_tree_rotated ? 1 : 0;
      out += "face";
      for (int k = 0; k < 3; ++k) out += " " + std::to_string(last.face_vertices[static_cast<std::size_t>(o + (k + r) % 3)]);
      out += "\n";
    }
    faces = last.face_sizes.size();
  }
  return out + "faces " + std::to_string(faces) + "\nend\n";
}

std::string print_edit_subdivision(const Node& node, int level, const std::string& edit_text,
                                   const CapabilityDocumentFaults& faults) {
  if (level < 1 || level > 3) return "error ?subdivide-edit takes a level from 1 to 3\n";
  HierarchicalEdit e;
  std::uint32_t polygon_id = 0;
  if (!parse_edit(edit_text, &e, &polygon_id))
    return "error ?subdivide-edit takes an edit: hole (<polygon> <child>...), set|add (<polygon> <child>... "
           "<vertex>) <x> <y> <z>\n";
  const MeshArrays mesh = remove_unused_vertices(extract_mesh(node));
  const auto it = std::find(mesh.polygon_ids.begin(), mesh.polygon_ids.end(), polygon_id);
  if (it == mesh.polygon_ids.end()) return "error the edit names no live polygon\n";
  e.face.base_face = static_cast<int>(it - mesh.polygon_ids.begin());
  if (faults.edit_at_base_level) {
    e.face.children.clear();
    e.index = std::min(e.index, mesh.face_sizes[static_cast<std::size_t>(e.face.base_face)] - 1);
  }
  if (faults.edit_hole_wrong_face && e.kind == EditKind::FaceHole) {
    if (e.face.children.empty()) e.face.base_face = (e.face.base_face + 1) % mesh.face_count();
    else e.face.children.back() = (e.face.children.back() + 1) % (e.face.level() == 1 ? 3 : 4);
  }
  if (faults.edit_truncated_path && e.face.level() > level) e.face.children.resize(static_cast<std::size_t>(level));
  if (faults.edit_add_zero_as_set && e.kind == EditKind::VertexValue && e.op == EditOp::Add &&
      e.value == std::array<double, 3>{0, 0, 0})
    e.op = EditOp::Set;
  std::vector<SubdivisionLevel> levels;
  // Refined as deep as the edit, so that its path is checked; a level
  // coarser than the edit is the plain refinement (001: an edit changes its
  // own level and the finer ones).
  if (subdivide_with_edits(mesh, std::max(level, e.face.level()), {e}, &levels) != EditStatus::Ok)
    return "error the edit names no face or vertex of the refinement\n";
  const SubdivisionLevel& l = levels[static_cast<std::size_t>(level)];
  std::string out = "vgc-subdivision 1\nlevel " + std::to_string(level) + "\n";
  for (const auto& p : l.positions)
    out += "vertex " + format_f64(p[0]) + " " + format_f64(p[1]) + " " + format_f64(p[2]) + "\n";
  std::size_t faces = 0;
  for (int f = 0; f < l.face_count(); ++f) {
    if (l.face_hole[static_cast<std::size_t>(f)] && !faults.edit_holes_ignored) continue;
    out += "face";
    for (int k = 0; k < l.face_sizes[static_cast<std::size_t>(f)]; ++k)
      out += " " + std::to_string(l.face_vertices[static_cast<std::size_t>(l.face_offsets[static_cast<std::size_t>(f)] + k)]);
    out += "\n";
    ++faces;
  }
  return out + "faces " + std::to_string(faces) + "\nend\n";
}

std::optional<std::string> answer_capability_request(const Node& node, const std::string& line,
                                                     const CapabilityDocumentFaults& faults) {
  if (line == "?capabilities") return print_capabilities();
  if (line == "?classify") return print_classify(node, faults);
  if (line == "?normals") return print_normals(node, faults);
  const std::string word = line.substr(0, line.find(' '));
  if (word == "?subdivide-edit") {
    std::istringstream in(line.substr(word.size()));
    std::string level_text, rest;
    std::uint32_t level = 0;
    if (!(in >> level_text) || !parse_uint(level_text, 32, &level) || level < 1 || level > 3)
      return std::string("error ?subdivide-edit takes a level from 1 to 3, then an edit\n");
    std::getline(in, rest);
    return print_edit_subdivision(node, static_cast<int>(level), rest, faults);
  }
  if (word == "?subdivide-loop") {
    std::uint32_t level = 0;
    if (line.size() <= word.size() + 1 || !parse_uint(line.substr(word.size() + 1), 32, &level) || level < 1 ||
        level > 3)
      return std::string("error ?subdivide-loop takes a level from 1 to 3\n");
    return print_loop_subdivision(node, static_cast<int>(level), faults);
  }
  static const std::string kSub = "?subdivide";
  if (line.rfind(kSub, 0) == 0 && (line.size() == kSub.size() || line[kSub.size()] == ' ')) {
    std::uint32_t level = 0;
    const std::string arg = line.size() > kSub.size() ? line.substr(kSub.size() + 1) : std::string();
    if (!parse_uint(arg, 32, &level) || level < 1 || level > 3)
      return std::string("error ?subdivide takes a level from 1 to 3\n");
    return print_subdivision(node, static_cast<int>(level), faults);
  }
  return std::nullopt;
}

}  // namespace vgc
