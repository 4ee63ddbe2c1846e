// cgal_manifold.cpp — see cgal_manifold.h. The only file including CGAL.
#include "cgal_manifold.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <memory>
#include <set>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

namespace vgc {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polygon = std::vector<std::size_t>;

// What the visitor hears. CGAL copies the visitor, so the state lives
// behind a shared pointer.
struct Heard {
  std::map<std::pair<int, int>, int> non_manifold_edges;
  std::map<int, int> singular_vertices;
  int reversed = 0;
};

struct Visitor : PMP::Default_orientation_visitor {
  std::shared_ptr<Heard> heard;
  explicit Visitor(std::shared_ptr<Heard> h) : heard(std::move(h)) {}
  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t uses) {
    const int x = static_cast<int>(std::min(a, b)), y = static_cast<int>(std::max(a, b));
    heard->non_manifold_edges[{x, y}] = static_cast<int>(uses);
  }
  void non_manifold_vertex(std::size_t v, std::size_t link_components) {
    heard->singular_vertices[static_cast<int>(v)] = static_cast<int>(link_components);
  }
  void polygon_orientation_reversed(std::size_t) { ++heard->reversed; }
};

// Hand-written input check (CGAL checks no index range): same precedence as
// reference check_mesh, written independently.
MeshStatus check_input(const MeshArrays& m, int* bad_face) {
  *bad_face = -1;
  if (m.face_offsets.size() != m.face_sizes.size()) return MeshStatus::BadArrays;
  long long expected_offset = 0;
  for (std::size_t f = 0; f < m.face_sizes.size(); ++f) {
    const long long o = m.face_offsets[f], n = m.face_sizes[f];
    if (n < 0 || o != expected_offset || o + n > static_cast<long long>(m.face_vertices.size())) {
      *bad_face = static_cast<int>(f);
      return MeshStatus::BadArrays;
    }
    expected_offset += n;
  }
  if (expected_offset != static_cast<long long>(m.face_vertices.size())) return MeshStatus::BadArrays;
  for (std::size_t f = 0; f < m.face_sizes.size(); ++f) {
    const int o = m.face_offsets[f], n = m.face_sizes[f];
    MeshStatus s = MeshStatus::Ok;
    std::set<int> distinct;
    if (n < 3) s = MeshStatus::TooFewCorners;
    for (int i = 0; s == MeshStatus::Ok && i < n; ++i) {
      const int v = m.face_vertices[static_cast<std::size_t>(o + i)];
      if (v < 0 || v >= static_cast<int>(m.positions.size())) s = MeshStatus::IndexOutOfRange;
    }
    for (int i = 0; s == MeshStatus::Ok && i < n; ++i)
      if (!distinct.insert(m.face_vertices[static_cast<std::size_t>(o + i)]).second) s = MeshStatus::RepeatedVertex;
    if (s != MeshStatus::Ok) {
      *bad_face = static_cast<int>(f);
      return s;
    }
  }
  return MeshStatus::Ok;
}

int index_of(const Mesh& mesh, Mesh::Vertex_index v) { return static_cast<int>(mesh.point(v).x()); }

}  // namespace

CgalManifoldReport cgal_classify_mesh(const MeshArrays& m) {
  CgalManifoldReport r;
  r.status = check_input(m, &r.bad_face);
  if (r.status != MeshStatus::Ok) return r;

  std::vector<Point> points;
  points.reserve(m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) points.emplace_back(static_cast<double>(i), 0.0, 0.0);
  std::vector<Polygon> polygons(m.face_sizes.size());
  for (std::size_t f = 0; f < m.face_sizes.size(); ++f)
    for (int i = 0; i < m.face_sizes[f]; ++i)
      polygons[f].push_back(static_cast<std::size_t>(m.face_vertices[static_cast<std::size_t>(m.face_offsets[f] + i)]));

  r.soup_is_polygon_mesh = PMP::is_polygon_soup_a_polygon_mesh(polygons);

  auto heard = std::make_shared<Heard>();
  std::vector<Point> oriented_points = points;
  std::vector<Polygon> oriented = polygons;
  const bool no_duplication =
      PMP::orient_polygon_soup(oriented_points, oriented, CGAL::parameters::visitor(Visitor(heard)));
  r.orient_duplicated_points = !no_duplication;
  for (const auto& [e, n] : heard->non_manifold_edges) r.non_manifold_edges.push_back({e.first, e.second, n});
  for (const auto& [v, n] : heard->singular_vertices) r.singular_vertices.emplace_back(v, n);
  r.reversed_polygon_count = heard->reversed;
  r.oriented_soup_is_polygon_mesh = PMP::is_polygon_soup_a_polygon_mesh(oriented);
  if (!r.oriented_soup_is_polygon_mesh) {
    // A conflict edge kept both ends: it is still used twice one way.
    r.orientable = false;
    r.consistently_oriented = false;
    return r;
  }
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(oriented_points, oriented, mesh);
  r.mesh_built = true;
  r.mesh_matches_input = no_duplication;

  // An input edge that became several mesh edges was cut by CGAL: either a
  // non-manifold edge or an orientation conflict.
  std::map<std::pair<int, int>, int> pieces;
  for (Mesh::Edge_index e : mesh.edges()) {
    const int a = index_of(mesh, mesh.vertex(e, 0)), b = index_of(mesh, mesh.vertex(e, 1));
    ++pieces[{std::min(a, b), std::max(a, b)}];
  }
  bool conflict_cut = false;
  for (const auto& [e, n] : pieces)
    if (n > 1 && !heard->non_manifold_edges.count(e)) conflict_cut = true;
  r.orientable = !conflict_cut;
  r.consistently_oriented = !conflict_cut && r.reversed_polygon_count == 0;

  r.vertex_count = static_cast<int>(mesh.number_of_vertices());
  for (Mesh::Vertex_index v : mesh.vertices())
    if (mesh.is_isolated(v)) ++r.isolated_vertex_count;
  r.edge_count = static_cast<int>(mesh.number_of_edges());
  r.face_count = static_cast<int>(mesh.number_of_faces());
  for (Mesh::Edge_index e : mesh.edges()) {
    if (!mesh.is_border(e)) continue;
    ++r.border_edge_count;
    const int a = index_of(mesh, mesh.vertex(e, 0)), b = index_of(mesh, mesh.vertex(e, 1));
    r.border_edges.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(r.border_edges.begin(), r.border_edges.end());
  for (Mesh::Vertex_index v : mesh.vertices())
    if (!mesh.is_isolated(v) && mesh.is_border(v, true)) r.border_vertices.push_back(index_of(mesh, v));
  std::sort(r.border_vertices.begin(), r.border_vertices.end());
  r.euler_characteristic = static_cast<long>(r.vertex_count - r.isolated_vertex_count) - r.edge_count + r.face_count;
  r.closed = CGAL::is_closed(mesh);
  r.valid_polygon_mesh = CGAL::is_valid_polygon_mesh(mesh);

  std::vector<Mesh::Halfedge_index> umbrellas;
  PMP::non_manifold_vertices(mesh, std::back_inserter(umbrellas));
  for (Mesh::Halfedge_index h : umbrellas) r.mesh_non_manifold_vertices.push_back(index_of(mesh, mesh.target(h)));
  std::sort(r.mesh_non_manifold_vertices.begin(), r.mesh_non_manifold_vertices.end());
  r.mesh_non_manifold_vertices.erase(std::unique(r.mesh_non_manifold_vertices.begin(), r.mesh_non_manifold_vertices.end()),
                                     r.mesh_non_manifold_vertices.end());

  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  for (Mesh::Halfedge_index h0 : cycles) {
    std::vector<int> loop;
    Mesh::Halfedge_index h = h0;
    do {
      loop.push_back(index_of(mesh, mesh.source(h)));
      h = mesh.next(h);
    } while (h != h0);
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    r.boundary_cycles.push_back(std::move(loop));
  }
  std::sort(r.boundary_cycles.begin(), r.boundary_cycles.end());

  auto fcc = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:vgc_cc", 0).first;
  r.component_count = static_cast<int>(PMP::connected_components(mesh, fcc));
  std::map<std::size_t, int> renumber;
  for (Mesh::Face_index f : mesh.faces()) {
    auto it = renumber.emplace(fcc[f], static_cast<int>(renumber.size())).first;
    r.face_component.push_back(it->second);
  }
  return r;
}

}  // namespace vgc
