// check_loop.cpp — ?subdivide-loop against OpenSubdiv's Loop scheme (capability_checks.h).
//
// Spec: clause LOOP-TRIANGLE-1; the document of docs/adapters.md "Optional
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

std::optional<Finding> check_loop(const Node& model, Implementation& sut, int level) {
  static const char* kClause = "LOOP-TRIANGLE-1";
  const std::string request = "?subdivide-loop " + std::to_string(level);
  const MeshArrays mesh = remove_unused_vertices(extract_mesh(model));
  const Document d = sut.request(request);
  bool triangles = true;
  for (int size : mesh.face_sizes) triangles = triangles && size == 3;
  if (!triangles) {
    // Loop subdivides triangles only (OpenSubdiv's SCHEME_LOOP refuses other faces).
    if (d.status == CallStatus::Ok && (d.text == "error\n" || d.text.rfind("error ", 0) == 0)) return std::nullopt;
    if (auto f = check_answer(kClause, request, d, "vgc-subdivision")) return f;
    return finding(kClause, request + ": answered a document although a live polygon is a quad; the answer must be "
                                "one line \"error ...\"");
  }
  if (auto f = check_answer(kClause, request, d, "vgc-subdivision")) return f;
  SubdivisionAnswer got;
  if (auto problem = read_subdivision(d.text, &got)) return finding(kClause, request + ": " + *problem);
  if (got.level != level) return finding(kClause, request + ": the document says level " + std::to_string(got.level));
  if (mesh.face_count() == 0) {
    if (!got.vertices.empty() || got.faces != 0 || !got.face_lines.empty())
      return finding(kClause, request + ": no polygons, yet " + std::to_string(got.vertices.size()) + " vertices and " +
                                  std::to_string(got.faces) + " faces");
    return std::nullopt;
  }
  std::string why;
  const std::optional<OsdResult> refined = oracle_refinement(mesh, OsdScheme::Loop, level, &why);
  if (!refined) return not_judged(kClause, request + ": " + why);
  const OsdResult& osd = *refined;
  std::vector<int> got_to_want;
  if (auto problem = compare_with_level(got, osd.levels.back().positions,
                                        static_cast<long>(osd.levels.back().face_sizes.size()), "OpenSubdiv Loop",
                                        &got_to_want))
    return finding(kClause, request + ": " + *problem);

  // The triangle tree (spec 004), built on OpenSubdiv's levels: base
  // triangles in order; the children of [v0 v1 v2] are T0 = [s0 s1 s2] (the
  // centre) and T(j+1) = [vj' s(j+2) s(j+1)] (nearest vertex j), sk the
  // child of the edge opposite vertex k, vj' the child of vertex j. Each
  // must be one of OpenSubdiv's child faces of the parent, same orientation.
  struct Tri {
    int face;
    std::array<int, 3> v;
  };
  std::vector<Tri> tree;
  const OsdLevel& base = osd.levels.front();
  for (int f = 0; f < static_cast<int>(base.face_sizes.size()); ++f)
    tree.push_back({f, {base.face_vertices[3 * f], base.face_vertices[3 * f + 1], base.face_vertices[3 * f + 2]}});
  for (int l = 1; l <= level; ++l) {
    const OsdLevel& parent = osd.levels[static_cast<std::size_t>(l - 1)];
    const OsdLevel& child = osd.levels[static_cast<std::size_t>(l)];
    std::vector<Tri> next;
    for (const Tri& t : tree) {
      std::array<int, 3> s{}, vc{};
      for (int k = 0; k < 3; ++k) {
        // The edge opposite vertex k, through the parent face's own edges
        // (GetFaceEdges; never by vertex pair: a Loop "pillow" has two
        // edges on one pair).
        const int a = t.v[static_cast<std::size_t>((k + 1) % 3)], b = t.v[static_cast<std::size_t>((k + 2) % 3)];
        int edge = -1;
        for (int c = 0; c < 3; ++c)
          if (parent.face_vertices[static_cast<std::size_t>(3 * t.face + c)] == a &&
              parent.face_vertices[static_cast<std::size_t>(3 * t.face + (c + 1) % 3)] == b)
            edge = parent.face_edges[static_cast<std::size_t>(3 * t.face + c)];
        if (edge < 0)
          return not_judged(kClause, request + ": OpenSubdiv's level " + std::to_string(l - 1) +
                                         " is not what the triangle tree assumes");
        s[static_cast<std::size_t>(k)] = child.child_of_parent_edge[static_cast<std::size_t>(edge)];
        vc[static_cast<std::size_t>(k)] = child.child_of_parent_vertex[static_cast<std::size_t>(t.v[static_cast<std::size_t>(k)])];
      }
      const std::array<std::array<int, 3>, 4> kids = {{{s[0], s[1], s[2]},
                                                       {vc[0], s[2], s[1]},
                                                       {vc[1], s[0], s[2]},
                                                       {vc[2], s[1], s[0]}}};
      for (const auto& kid : kids) {
        int found = -1;
        for (int cf : child.child_faces_of_parent_face[static_cast<std::size_t>(t.face)])
          for (int r = 0; r < 3; ++r) {
            bool same = true;
            for (int k = 0; k < 3; ++k)
              same = same && child.face_vertices[static_cast<std::size_t>(3 * cf + (k + r) % 3)] == kid[static_cast<std::size_t>(k)];
            if (same) found = cf;
          }
        if (found < 0)
          return not_judged(kClause, request + ": OpenSubdiv's children at level " + std::to_string(l) +
                                         " are not what the triangle tree assumes");
        next.push_back({found, kid});
      }
    }
    tree = std::move(next);
  }
  if (got.face_lines.size() != tree.size())
    return finding(kClause, request + ": " + std::to_string(got.face_lines.size()) + " face lines; the triangle tree "
                                "has " + std::to_string(tree.size()) + " triangles at level " + std::to_string(level));
  static const char* kChild[] = {"T0 (the centre)", "T1 (nearest vertex 0)", "T2 (nearest vertex 1)",
                                 "T3 (nearest vertex 2)"};
  // By position (the vertices already matched one to one): coinciding
  // vertices make any pairing by index arbitrary. One tolerance for the
  // level (it was computed per face line: faces x vertices).
  const double tol = tolerance_of(osd.levels.back().positions);
  for (std::size_t i = 0; i < tree.size(); ++i) {
    const auto& line = got.face_lines[i];
    bool same = line.size() == 3;
    for (std::size_t k = 0; same && k < 3; ++k)
      same = near(got.vertices[static_cast<std::size_t>(line[k])],
                  osd.levels.back().positions[static_cast<std::size_t>(tree[i].v[k])], tol);
    if (!same) {
      std::string have, want;
      for (int x : line) have += " " + point_text(got.vertices[static_cast<std::size_t>(x)]);
      for (int x : tree[i].v) want += " " + point_text(osd.levels.back().positions[static_cast<std::size_t>(x)]);
      return finding(kClause, request + ": face line " + std::to_string(i) + " should be child " + kChild[i % 4] +
                                  " of its parent, in the order [vj' s(j+2) s(j+1)] / [s0 s1 s2]:" + want +
                                  "; the answer has" + have);
    }
  }
  return std::nullopt;
}

}  // namespace vgc
