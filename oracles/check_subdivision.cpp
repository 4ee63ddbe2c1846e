// check_subdivision.cpp — ?subdivide against OpenSubdiv's Catmull-Clark (capability_checks.h).
//
// Spec: clause SUBD-CATMARK-1; the document of docs/adapters.md "Optional
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
#include "mesh_arrays.h"
#include "osd_subdivision.h"

namespace vgc {

using namespace capability_answer;

std::optional<Finding> check_subdivision(const Node& model, Implementation& sut, int level) {
  static const char* kClause = "SUBD-CATMARK-1";
  const std::string request = "?subdivide " + std::to_string(level);
  const Document d = sut.request(request);
  if (auto f = check_answer(kClause, request, d, "vgc-subdivision")) return f;
  SubdivisionAnswer got;
  if (auto problem = read_subdivision(d.text, &got)) return finding(kClause, request + ": " + *problem);
  if (got.level != level) return finding(kClause, request + ": the document says level " + std::to_string(got.level));

  const MeshArrays mesh = remove_unused_vertices(extract_mesh(model));
  if (mesh.face_count() == 0) {
    if (!got.vertices.empty() || got.faces != 0)
      return finding(kClause, request + ": no polygons, yet " + std::to_string(got.vertices.size()) + " vertices and " +
                                  std::to_string(got.faces) + " faces");
    return std::nullopt;
  }
  std::string why;
  const std::optional<OsdResult> osd = oracle_refinement(mesh, OsdScheme::CatmullClark, level, &why);
  if (!osd) return not_judged(kClause, request + ": " + why);
  const OsdLevel& want = osd->levels.back();
  std::vector<int> got_to_want;
  if (auto problem = compare_with_level(got, want.positions, static_cast<long>(want.face_sizes.size()), "OpenSubdiv",
                                        &got_to_want))
    return finding(kClause, request + ": " + *problem);
  return std::nullopt;
}

}  // namespace vgc
