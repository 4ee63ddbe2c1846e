// polygon_triangulation.cpp — see polygon_triangulation.h.
#include "polygon_triangulation.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <set>

namespace vgc {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

// The triangles of one face (indices into `face`'s corners), or false.
bool triangulate_face(const PolygonSoup& soup, const std::vector<std::size_t>& face,
                      std::vector<std::array<std::size_t, 3>>* out) {
  if (std::set<std::size_t>(face.begin(), face.end()).size() != face.size()) return false;
  Mesh m;
  std::vector<Mesh::Vertex_index> vs;
  for (std::size_t v : face) {
    const auto& p = soup.points[v];
    vs.push_back(m.add_vertex(Kernel::Point_3(p[0], p[1], p[2])));
  }
  if (m.add_face(vs) == Mesh::null_face()) return false;
  if (!CGAL::Polygon_mesh_processing::triangulate_faces(m)) return false;
  for (const auto f : m.faces()) {
    std::array<std::size_t, 3> t{};
    std::size_t k = 0;
    for (const auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
      if (k == 3) return false;
      t[k++] = face[static_cast<std::size_t>(v.idx())];
    }
    if (k != 3) return false;
    out->push_back(t);
  }
  return out->size() == face.size() - 2;
}

}  // namespace

bool triangulate_large_faces(PolygonSoup* soup, std::size_t* split, MeshFileError* error) {
  *split = 0;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<std::size_t> lines, columns;
  polygons.reserve(soup->polygons.size());
  for (std::size_t f = 0; f < soup->polygons.size(); ++f) {
    const auto& face = soup->polygons[f];
    const std::size_t line = f < soup->polygon_lines.size() ? soup->polygon_lines[f] : 0;
    const std::size_t column = f < soup->polygon_columns.size() ? soup->polygon_columns[f] : 0;
    bool in_range = true;
    for (std::size_t v : face) in_range = in_range && v < soup->points.size();
    if (face.size() <= 4 || !in_range) {  // left to program_from_soup's checks
      polygons.push_back(face), lines.push_back(line), columns.push_back(column);
      continue;
    }
    std::vector<std::array<std::size_t, 3>> triangles;
    if (!triangulate_face(*soup, face, &triangles)) {
      error->line = line, error->column = column;
      error->message = "CGAL cannot triangulate this face of " + std::to_string(face.size()) +
                       " corners (a corner repeated, or no plane through it: all corners on one line)" +
                       (line ? "" : " (face " + std::to_string(f + 1) + " of the file)");
      return false;
    }
    for (const auto& t : triangles) {
      polygons.push_back({t[0], t[1], t[2]});
      lines.push_back(line), columns.push_back(column);
    }
    ++*split;
  }
  soup->polygons = std::move(polygons);
  soup->polygon_lines = std::move(lines);
  soup->polygon_columns = std::move(columns);
  return true;
}

}  // namespace vgc
