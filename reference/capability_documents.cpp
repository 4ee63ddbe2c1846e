// capability_documents.cpp — see capability_documents.h.
#include "capability_documents.h"

#include <vector>

#include "catmull_clark.h"
#include "mesh_arrays.h"
#include "mesh_topology.h"
#include "number_text.h"

namespace vgc {
namespace {

const char* yes_no(bool b) { return b ? "yes" : "no"; }


}  // namespace

std::string print_capabilities() { return "capabilities manifold subdivision\nend\n"; }

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
    const auto levels = subdivide_catmull_clark(mesh, level);
    if (levels.size() != static_cast<std::size_t>(level) + 1) return "error the mesh cannot be subdivided\n";
    for (const auto& p : levels.back().positions)
      out += "vertex " + format_f64(p[0]) + " " + format_f64(p[1]) + " " + format_f64(p[2]) + "\n";
    faces = levels.back().face_sizes.size();
  }
  return out + "faces " + std::to_string(faces) + "\nend\n";
}

std::optional<std::string> answer_capability_request(const Node& node, const std::string& line,
                                                     const CapabilityDocumentFaults& faults) {
  if (line == "?capabilities") return print_capabilities();
  if (line == "?classify") return print_classify(node, faults);
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
