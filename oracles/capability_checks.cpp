// capability_checks.cpp — see capability_checks.h.
#include "capability_checks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cgal_manifold.h"
#include "crease_sharpness.h"
#include "mesh_arrays.h"
#include "mesh_topology.h"
#include "number_text.h"
#include "osd_subdivision.h"

namespace vgc {
namespace {

Finding finding(const char* clause, std::string message, FindingStatus st = FindingStatus::Fail) {
  return Finding{clause, st, std::move(message)};
}

// A failed call, an "error" answer or a document not of `header`: the finding, else nullopt.
std::optional<Finding> check_answer(const char* clause, const std::string& request, const Document& d,
                                    const char* header) {
  if (d.status != CallStatus::Ok) {
    const FindingStatus st = d.status == CallStatus::Timeout ? FindingStatus::Timeout
                             : d.status == CallStatus::Crash ? FindingStatus::Crash
                                                             : FindingStatus::Fail;
    return finding(clause, std::string(call_status_name(d.status)) + " on " + request + ": " + d.detail, st);
  }
  if (d.text.rfind(std::string(header) + " 1\n", 0) != 0)
    return finding(clause, "answered " + request + " with \"" + d.text.substr(0, d.text.find('\n')) +
                               "\" although it claims the capability; expected a document starting \"" + header +
                               " 1\"");
  return std::nullopt;
}

// "key value" lines of a document (first word -> rest), header and end left out.
std::vector<std::pair<std::string, std::string>> document_lines(const std::string& text) {
  std::vector<std::pair<std::string, std::string>> out;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line == "end") break;
    const auto sp = line.find(' ');
    out.emplace_back(line.substr(0, sp), sp == std::string::npos ? std::string() : line.substr(sp + 1));
  }
  return out;
}



std::string point_text(const std::array<double, 3>& p) {
  return "(" + format_f64(p[0]) + ", " + format_f64(p[1]) + ", " + format_f64(p[2]) + ")";
}

}  // namespace

std::optional<Finding> check_classify(const Node& model, Implementation& sut) {
  static const char* kClause = "MESH-CLASSIFY-1";
  const Document d = sut.request("?classify");
  if (auto f = check_answer(kClause, "?classify", d, "vgc-classify")) return f;
  std::map<std::string, std::string> got;
  for (const auto& [k, v] : document_lines(d.text)) got[k] = v;

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

std::optional<Finding> check_subdivision(const Node& model, Implementation& sut, int level) {
  static const char* kClause = "SUBD-CATMARK-1";
  const std::string request = "?subdivide " + std::to_string(level);
  const Document d = sut.request(request);
  if (auto f = check_answer(kClause, request, d, "vgc-subdivision")) return f;

  std::vector<std::array<double, 3>> got;
  long faces = -1, got_level = -1;
  for (const auto& [k, v] : document_lines(d.text)) {
    if (k == "vertex") {
      std::istringstream in(v);
      std::string x, y, z;
      std::array<double, 3> p{};
      if (!(in >> x >> y >> z) || !parse_f64(x, &p[0]) || !parse_f64(y, &p[1]) || !parse_f64(z, &p[2]))
        return finding(kClause, request + ": unreadable line \"vertex " + v + "\"");
      got.push_back(p);
    } else if (k == "faces") {
      faces = std::strtol(v.c_str(), nullptr, 10);
    } else if (k == "level") {
      got_level = std::strtol(v.c_str(), nullptr, 10);
    }
  }
  if (got_level != level) return finding(kClause, request + ": the document says level " + std::to_string(got_level));

  const MeshArrays mesh = remove_unused_vertices(extract_mesh(model));
  if (mesh.face_count() == 0) {
    if (!got.empty() || faces != 0)
      return finding(kClause, request + ": no polygons, yet " + std::to_string(got.size()) + " vertices and " +
                                  std::to_string(faces) + " faces");
    return std::nullopt;
  }
  const MeshTopology topo = classify_mesh(mesh);
  if (topo.status != MeshStatus::Ok || !topo.is_polygon_mesh) return std::nullopt;  // not compared (clause reading)
  const OsdResult osd = osd_refine_uniform(osd_input_from_mesh(mesh, OsdScheme::CatmullClark, level));
  if (!osd.ok || osd.levels.size() != static_cast<std::size_t>(level) + 1) return std::nullopt;
  const OsdLevel& want = osd.levels.back();

  if (faces != static_cast<long>(want.face_sizes.size()))
    return finding(kClause, request + ": " + std::to_string(faces) + " faces; OpenSubdiv refines to " +
                                std::to_string(want.face_sizes.size()));
  if (got.size() != want.positions.size())
    return finding(kClause, request + ": " + std::to_string(got.size()) + " vertices; OpenSubdiv refines to " +
                                std::to_string(want.positions.size()));
  double scale = 1;
  for (const auto& p : want.positions)
    for (double c : p) scale = std::max(scale, std::fabs(c));
  const double tol = 1e-9 * scale;
  // Bijection by nearest position: both sides sorted by x, each expected
  // vertex takes the nearest unused answer within the tolerance.
  std::vector<std::size_t> order(got.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return got[a][0] < got[b][0]; });
  std::vector<double> xs(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) xs[i] = got[order[i]][0];
  std::vector<char> used(got.size(), 0);
  for (const auto& p : want.positions) {
    auto lo = std::lower_bound(xs.begin(), xs.end(), p[0] - tol);
    std::size_t best = got.size();
    double best_d = tol;
    for (auto it = lo; it != xs.end() && *it <= p[0] + tol; ++it) {
      const std::size_t g = order[static_cast<std::size_t>(it - xs.begin())];
      if (used[g]) continue;
      const double dist = std::max({std::fabs(got[g][0] - p[0]), std::fabs(got[g][1] - p[1]), std::fabs(got[g][2] - p[2])});
      if (dist <= best_d) best = g, best_d = dist;
    }
    if (best == got.size())
      return finding(kClause, request + ": OpenSubdiv has a vertex at " + point_text(p) +
                                  " and the answer has none within " + format_f64(tol) + " (not already matched)");
    used[best] = 1;
  }
  return std::nullopt;
}

void register_capability_checks() {
  register_capability_check({"manifold", [](const Node& m, Implementation& s, int) { return check_classify(m, s); }});
  register_capability_check({"subdivision", [](const Node& m, Implementation& s, int level) {
                               return check_subdivision(m, s, level);
                             }});
}

}  // namespace vgc
