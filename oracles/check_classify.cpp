// check_classify.cpp — ?classify against CGAL Polygon Mesh Processing (capability_checks.h).
//
// Spec: clause MESH-CLASSIFY-1; the document of docs/adapters.md "Optional
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
#include "cgal_manifold.h"
#include "mesh_arrays.h"
#include "mesh_topology.h"

namespace vgc {

using namespace capability_answer;

std::optional<Finding> check_classify(const Node& model, Implementation& sut) {
  static const char* kClause = "MESH-CLASSIFY-1";
  const Document d = sut.request("?classify");
  if (auto f = check_answer(kClause, "?classify", d, "vgc-classify")) return f;
  std::map<std::string, std::string> got;
  for (const auto& [k, v] : document_lines(d.text)) got[std::string(k)] = std::string(v);

  const MeshArrays mesh = extract_mesh(model);
  const CgalManifoldReport cgal = cgal_classify_mesh(mesh);
  if (cgal.status != MeshStatus::Ok) return std::nullopt;  // CGAL cannot answer for this soup
  std::vector<std::pair<std::string, std::string>> expected;
  const bool pm = cgal.soup_is_polygon_mesh;
  expected.emplace_back("polygon_mesh", pm ? "yes" : "no");
  if (pm && cgal.mesh_built && cgal.mesh_matches_input) {
    expected.emplace_back("closed", cgal.closed ? "yes" : "no");
    if (cgal.consistently_oriented) expected.emplace_back("oriented", *cgal.consistently_oriented ? "yes" : "no");
    expected.emplace_back("euler", std::to_string(cgal.euler_characteristic));
    expected.emplace_back("components", std::to_string(cgal.component_count));
    expected.emplace_back("boundary_loops", std::to_string(cgal.boundary_cycles.size()));
  }
  for (const auto& [key, want] : expected) {
    auto it = got.find(key);
    const std::string have = it == got.end() ? "(missing)" : it->second;
    if (have != want)
      return finding(kClause, "?classify says " + key + " " + have + "; CGAL Polygon Mesh Processing says " + want +
                                  " for the node's " + std::to_string(mesh.face_count()) + " polygons");
  }
  return std::nullopt;
}

}  // namespace vgc
