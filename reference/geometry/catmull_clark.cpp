// catmull_clark.cpp — see catmull_clark.h.
#include "catmull_clark.h"

#include <algorithm>
#include <cstdint>

#include "crease_sharpness.h"
#include "mesh_topology.h"

namespace vgc {
namespace {

using Vec3 = std::array<double, 3>;

void add_scaled(Vec3& acc, const Vec3& p, double w) {
  acc[0] += w * p[0];
  acc[1] += w * p[1];
  acc[2] += w * p[2];
}

// Incident edges and faces of every vertex and the faces of every edge, in
// no particular order, as offset tables (CSR): the items of vertex v are
// vertex_edges[vertex_edge_offsets[v] .. vertex_edge_offsets[v + 1]).
struct Incidence {
  std::vector<int> vertex_edge_offsets, vertex_edges;
  std::vector<int> vertex_face_offsets, vertex_faces;
  std::vector<int> edge_face_offsets, edge_faces;
};

// Fills a CSR table from (key, item) pairs given twice by `each`: once to count, once to place.
template <typename Each>
void fill_csr(int keys, std::vector<int>& offsets, std::vector<int>& items, Each each) {
  offsets.assign(static_cast<std::size_t>(keys) + 1, 0);
  each([&](int key, int) { ++offsets[static_cast<std::size_t>(key) + 1]; });
  for (int k = 0; k < keys; ++k) offsets[static_cast<std::size_t>(k) + 1] += offsets[static_cast<std::size_t>(k)];
  items.assign(static_cast<std::size_t>(offsets.back()), -1);
  std::vector<int> next(offsets.begin(), offsets.end() - 1);
  each([&](int key, int item) { items[static_cast<std::size_t>(next[static_cast<std::size_t>(key)]++)] = item; });
}

Incidence incidence_of(const SubdivisionLevel& l) {
  Incidence in;
  fill_csr(l.vertex_count(), in.vertex_edge_offsets, in.vertex_edges, [&](auto put) {
    for (int e = 0; e < l.edge_count(); ++e)
      for (int end = 0; end < 2; ++end) put(l.edges[static_cast<std::size_t>(e)][static_cast<std::size_t>(end)], e);
  });
  fill_csr(l.vertex_count(), in.vertex_face_offsets, in.vertex_faces, [&](auto put) {
    for (int f = 0; f < l.face_count(); ++f)
      for (int c = 0; c < l.face_sizes[f]; ++c) put(l.face_vertices[l.face_offsets[f] + c], f);
  });
  fill_csr(l.edge_count(), in.edge_face_offsets, in.edge_faces, [&](auto put) {
    for (int f = 0; f < l.face_count(); ++f)
      for (int c = 0; c < l.face_sizes[f]; ++c) put(l.face_edges[l.face_offsets[f] + c], f);
  });
  return in;
}

int other_end(const std::array<int, 2>& e, int v) { return e[0] == v ? e[1] : e[0]; }

}  // namespace

// Edges by first appearance, without hashing: each edge is looked up among
// the edges found so far at its end with fewer edge uses (a face side
// touching it; ties: the lower index), held in a CSR table of (other end,
// edge) slots sized by those uses. A lookup scans at most min(uses of a,
// uses of b) slots, so a fan of 10^5 triangles costs its rim vertices' few
// slots, not the hub's 10^5.
void build_level_edges(SubdivisionLevel* level) {
  SubdivisionLevel& l = *level;
  int nv = 0;
  for (int v : l.face_vertices) nv = std::max(nv, v + 1);
  std::vector<int> degree(static_cast<std::size_t>(nv), 0);  // edge uses: 2 per corner of a vertex
  for (int v : l.face_vertices) degree[static_cast<std::size_t>(v)] += 2;
  auto key_end = [&](int a, int b) {
    const int da = degree[static_cast<std::size_t>(a)], db = degree[static_cast<std::size_t>(b)];
    return da < db || (da == db && a < b) ? a : b;
  };
  // Slots of vertex v: [offset[v], offset[v] + used[v]), at most its uses.
  std::vector<int> offset(static_cast<std::size_t>(nv) + 1, 0);
  for (int v = 0; v < nv; ++v) offset[static_cast<std::size_t>(v) + 1] = offset[static_cast<std::size_t>(v)] + degree[static_cast<std::size_t>(v)];
  std::vector<int> used(static_cast<std::size_t>(nv), 0);
  std::vector<int> slot_other(2 * l.face_vertices.size()), slot_edge(2 * l.face_vertices.size());
  l.edges.clear();
  l.edges.reserve(l.face_vertices.size() / 2 + 1);
  l.edge_face_count.clear();
  l.edge_face_count.reserve(l.edges.capacity());
  l.face_edges.assign(l.face_vertices.size(), -1);
  for (int f = 0; f < l.face_count(); ++f) {
    const int n = l.face_sizes[f], o = l.face_offsets[f];
    for (int c = 0; c < n; ++c) {
      const int a = l.face_vertices[o + c], b = l.face_vertices[o + (c + 1) % n];
      const int k = key_end(a, b), other = k == a ? b : a;
      const int first = offset[static_cast<std::size_t>(k)], end = first + used[static_cast<std::size_t>(k)];
      int e = -1;
      for (int s = first; s < end && e < 0; ++s)
        if (slot_other[static_cast<std::size_t>(s)] == other) e = slot_edge[static_cast<std::size_t>(s)];
      if (e < 0) {
        e = l.edge_count();
        l.edges.push_back({a, b});
        l.edge_face_count.push_back(0);
        slot_other[static_cast<std::size_t>(end)] = other;
        slot_edge[static_cast<std::size_t>(end)] = e;
        ++used[static_cast<std::size_t>(k)];
      }
      l.face_edges[o + c] = e;
      ++l.edge_face_count[static_cast<std::size_t>(e)];
    }
  }
}

NonManifoldTags non_manifold_tags(const MeshArrays& mesh, const SubdivisionLevel& l) {
  NonManifoldTags tags;
  const int nv = l.vertex_count(), ne = l.edge_count();
  tags.edge.assign(static_cast<std::size_t>(ne), 0);
  tags.vertex.assign(static_cast<std::size_t>(nv), 0);
  tags.vertex_sharpened.assign(static_cast<std::size_t>(nv), 0);
  // Edges: a third use, or a second use starting where the first did
  // (edges[e][0] is the first use's start).
  std::vector<int> uses(static_cast<std::size_t>(ne), 0);
  for (int f = 0; f < l.face_count(); ++f)
    for (int c = 0; c < l.face_sizes[f]; ++c) {
      const int corner = l.face_offsets[f] + c;
      const auto e = static_cast<std::size_t>(l.face_edges[corner]);
      const int n = ++uses[e];
      if (n > 2 || (n == 2 && l.face_vertices[corner] == l.edges[e][0])) tags.edge[e] = 1;
    }
  for (int e = 0; e < ne; ++e)
    if (tags.edge[static_cast<std::size_t>(e)])
      for (int end = 0; end < 2; ++end) tags.vertex[static_cast<std::size_t>(l.edges[e][end])] = 1;
  // Vertices: in no face, or in more than one fan (mesh_topology.h; with
  // every incident edge manifold, the fans are OpenSubdiv's walk).
  const MeshTopology t = classify_mesh(mesh);
  for (int v = 0; v < nv; ++v) {
    const auto sv = static_cast<std::size_t>(v);
    if (t.status != MeshStatus::Ok || t.vertex_kinds[sv] == VertexKind::Isolated || t.vertex_fan_counts[sv] != 1)
      tags.vertex[sv] = 1;
  }
  // Sharpening, with the exception of an interior non-manifold crease.
  std::vector<int> vedges(static_cast<std::size_t>(nv), 0), vfaces(static_cast<std::size_t>(nv), 0),
      vnm(static_cast<std::size_t>(nv), 0), vboundary(static_cast<std::size_t>(nv), 0);
  for (int e = 0; e < ne; ++e)
    for (int end = 0; end < 2; ++end) {
      const auto v = static_cast<std::size_t>(l.edges[e][end]);
      ++vedges[v];
      vnm[v] += tags.edge[static_cast<std::size_t>(e)];
      vboundary[v] += uses[static_cast<std::size_t>(e)] < 2 ? 1 : 0;
    }
  for (int v : l.face_vertices) ++vfaces[static_cast<std::size_t>(v)];
  for (std::size_t v = 0; v < static_cast<std::size_t>(nv); ++v)
    if (tags.vertex[v] && !(vnm[v] == 2 && vboundary[v] == 0 && vfaces[v] > vedges[v])) tags.vertex_sharpened[v] = 1;
  return tags;
}

bool build_base_level(const MeshArrays& mesh, SubdivisionLevel* out, bool non_manifold_rule) {
  const int nv = mesh.vertex_count();
  if (static_cast<int>(mesh.vertex_creases.size()) != nv) return false;
  if (mesh.face_offsets.size() != mesh.face_sizes.size()) return false;
  if (mesh.corner_edge_creases.size() != mesh.face_vertices.size()) return false;
  SubdivisionLevel l;
  l.positions = mesh.positions;
  for (std::uint32_t c : mesh.vertex_creases) l.vertex_sharpness.push_back(crease_to_sharpness(c));
  l.face_sizes = mesh.face_sizes;
  int offset = 0;
  for (int f = 0; f < mesh.face_count(); ++f) {
    const int n = mesh.face_sizes[f];
    if (n < 3 || mesh.face_offsets[f] < 0 ||
        mesh.face_offsets[f] + n > static_cast<int>(mesh.face_vertices.size()))
      return false;
    l.face_offsets.push_back(offset);
    for (int c = 0; c < n; ++c) {
      const int v = mesh.face_vertices[mesh.face_offsets[f] + c];
      if (v < 0 || v >= nv) return false;
      for (int d = 0; d < c; ++d)
        if (mesh.face_vertices[mesh.face_offsets[f] + d] == v) return false;  // repeated corner
      l.face_vertices.push_back(v);
    }
    offset += n;
  }
  build_level_edges(&l);
  // Shared edges: the maximum of the creases stored for them.
  std::vector<std::vector<std::uint32_t>> stored(l.edges.size());
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int c = 0; c < mesh.face_sizes[f]; ++c)
      stored[static_cast<std::size_t>(l.face_edges[l.face_offsets[f] + c])].push_back(
          mesh.corner_edge_creases[static_cast<std::size_t>(mesh.face_offsets[f] + c)]);
  for (int e = 0; e < l.edge_count(); ++e)
    l.edge_sharpness.push_back(edge_sharpness_for(combine_edge_creases(stored[e]), l.edge_face_count[e]));
  if (non_manifold_rule) {
    // The mesh as given may have offsets that are not the level's; the tags
    // read the level's faces and classify a copy with the level's offsets.
    MeshArrays tiled = mesh;
    tiled.face_offsets = l.face_offsets;
    tiled.face_vertices = l.face_vertices;
    const NonManifoldTags tags = non_manifold_tags(tiled, l);
    for (int e = 0; e < l.edge_count(); ++e)
      if (tags.edge[static_cast<std::size_t>(e)]) l.edge_sharpness[static_cast<std::size_t>(e)] = kSharpnessInfinite;
    for (int v = 0; v < nv; ++v)
      if (tags.vertex_sharpened[static_cast<std::size_t>(v)]) l.vertex_sharpness[static_cast<std::size_t>(v)] = kSharpnessInfinite;
  }
  l.face_hole.assign(l.face_sizes.size(), 0);
  *out = std::move(l);
  return true;
}

namespace {

// refine_catmull_clark's steps. Child numbering (see the header): parent
// vertex v is child v, face f child nv + f, edge e child nv + nf + e.

// Face points: the average of the face's vertices.
void place_face_points(const SubdivisionLevel& p, SubdivisionLevel& c) {
  const int nv = p.vertex_count(), nf = p.face_count();
  for (int f = 0; f < nf; ++f) {
    Vec3& fp = c.positions[static_cast<std::size_t>(nv + f)];
    const double w = 1.0 / p.face_sizes[f];
    for (int k = 0; k < p.face_sizes[f]; ++k) add_scaled(fp, p.positions[p.face_vertices[p.face_offsets[f] + k]], w);
  }
}

// Edge points: a quarter of each end and of each face point (shared among
// the faces when not two); a sharp edge the crease rule (the midpoint), a
// sharpness in (0, 1] blended by it. Reads the face points.
void place_edge_points(const SubdivisionLevel& p, const Incidence& in, const CatmullClarkFaults& faults,
                       SubdivisionLevel& c) {
  const int nv = p.vertex_count(), nf = p.face_count(), ne = p.edge_count();
  for (int e = 0; e < ne; ++e) {
    const float s = p.edge_sharpness[e];
    const int* faces = in.edge_faces.data() + in.edge_face_offsets[static_cast<std::size_t>(e)];
    const int nfaces = in.edge_face_offsets[static_cast<std::size_t>(e) + 1] - in.edge_face_offsets[static_cast<std::size_t>(e)];
    double vw = 0.25;
    double fw = nfaces == 2 ? 0.25 : 0.5 / static_cast<double>(nfaces);
    if (is_sharp(s)) {
      if (s > 1.0f) {  // child edges still sharp: the crease rule
        vw = 0.5;
        fw = 0.0;
      } else if (!faults.no_fractional_blend) {  // s in (0, 1]: blend by s
        const double pw = s, cw = 1.0f - pw;
        vw = pw * 0.5 + cw * vw;
        fw *= cw;
      }
    }
    Vec3& ep = c.positions[static_cast<std::size_t>(nv + nf + e)];
    for (int i = 0; i < nfaces; ++i) add_scaled(ep, c.positions[static_cast<std::size_t>(nv + faces[i])], fw);
    add_scaled(ep, p.positions[p.edges[e][0]], vw);
    add_scaled(ep, p.positions[p.edges[e][1]], vw);
  }
}

// The edges and faces around one parent vertex, for its vertex rules.
struct VertexStar {
  int v = 0;
  std::vector<int> vedges, vfaces;
};

// Adds `weight` times the star's vertex point by one vertex rule (Sdc):
// smooth and dart (n - 2)/n of v and 1/n^2 of each face point and
// neighbour; crease 3/4 of v and 1/8 of each sharp neighbour; corner v.
void add_vertex_rule(Vec3& acc, const SubdivisionLevel& p, const SubdivisionLevel& c, const VertexStar& star,
                     CreaseRule rule, const std::vector<float>& sharp, double weight, bool wrong_crease_weights) {
  const int nv = p.vertex_count(), v = star.v;
  if (rule == CreaseRule::Smooth || rule == CreaseRule::Dart) {
    const double n = static_cast<double>(star.vedges.size());
    const double fw = 1.0 / (n * n);
    for (int f : star.vfaces) add_scaled(acc, c.positions[static_cast<std::size_t>(nv + f)], weight * fw);
    for (int e : star.vedges) add_scaled(acc, p.positions[other_end(p.edges[e], v)], weight * fw);
    add_scaled(acc, p.positions[v], weight * ((n - 2.0) / n));
  } else if (rule == CreaseRule::Crease) {
    const double ew = wrong_crease_weights ? 1.0 / 6.0 : 0.125;
    for (std::size_t i = 0; i < star.vedges.size(); ++i)
      if (is_sharp(sharp[i])) add_scaled(acc, p.positions[other_end(p.edges[star.vedges[i]], v)], weight * ew);
    add_scaled(acc, p.positions[v], weight * (1.0 - 2.0 * ew));
  } else {
    add_scaled(acc, p.positions[v], weight);
  }
}

// Vertex points: the parent's rule, or where the child's rule differs the
// two blended by the fractional weight (Sdc: a smooth parent is never
// blended). Reads the face points.
void place_vertex_points(const SubdivisionLevel& p, const Incidence& in, const CatmullClarkFaults& faults,
                         SubdivisionLevel& c) {
  const int nv = p.vertex_count();
  VertexStar star;
  std::vector<float> es, ces;
  for (int v = 0; v < nv; ++v) {
    const auto sv = static_cast<std::size_t>(v);
    star.v = v;
    star.vedges.assign(in.vertex_edges.begin() + in.vertex_edge_offsets[sv], in.vertex_edges.begin() + in.vertex_edge_offsets[sv + 1]);
    star.vfaces.assign(in.vertex_faces.begin() + in.vertex_face_offsets[sv], in.vertex_faces.begin() + in.vertex_face_offsets[sv + 1]);
    es.clear();
    ces.clear();
    bool on_boundary = false;
    for (int e : star.vedges) {
      es.push_back(p.edge_sharpness[e]);
      ces.push_back(subdivide_sharpness(p.edge_sharpness[e]));
      on_boundary = on_boundary || p.edge_face_count[e] == 1;
    }
    const float vs = p.vertex_sharpness[v], cvs = subdivide_sharpness(vs);
    c.vertex_sharpness[static_cast<std::size_t>(v)] = cvs;
    CreaseRule prule = determine_vertex_rule(vs, es), crule = determine_vertex_rule(cvs, ces);
    if (star.vedges.empty() || (faults.pin_boundary_vertices && on_boundary)) prule = crule = CreaseRule::Corner;

    Vec3 acc{0, 0, 0};
    const bool wrong = faults.wrong_crease_weights;
    if (prule == crule) {
      add_vertex_rule(acc, p, c, star, prule, es, 1.0, wrong);
    } else {
      const double w = faults.no_fractional_blend ? 0.0 : fractional_weight_at_vertex(vs, cvs, es);
      if (prule == CreaseRule::Smooth || prule == CreaseRule::Dart)  // Sdc: a smooth parent is never blended
        add_vertex_rule(acc, p, c, star, prule, es, 1.0, wrong);
      else {
        add_vertex_rule(acc, p, c, star, prule, es, w, wrong);
        add_vertex_rule(acc, p, c, star, crule, ces, 1.0 - w, wrong);
      }
    }
    c.positions[static_cast<std::size_t>(v)] = acc;
  }
}

// Child faces: n quads per parent n-gon, child i next to parent corner i
// (spec 001), then the child level's edges.
void build_child_faces(const SubdivisionLevel& p, SubdivisionLevel& c) {
  const int nv = p.vertex_count(), nf = p.face_count();
  for (int f = 0; f < nf; ++f) {
    const int n = p.face_sizes[f], o = p.face_offsets[f];
    const int fp = nv + f;
    c.first_child_of_parent_face.push_back(c.face_count());
    for (int i = 0; i < n; ++i) {
      const int vi = p.face_vertices[o + i];
      const int ei = nv + nf + p.face_edges[o + i];
      const int eprev = nv + nf + p.face_edges[o + (i + n - 1) % n];
      std::array<int, 4> q{vi, ei, fp, eprev};
      if (n == 4) {  // regular: the child of parent vertex i keeps index i (spec 001)
        std::array<int, 4> r{};
        for (int k = 0; k < 4; ++k) r[static_cast<std::size_t>((i + k) % 4)] = q[static_cast<std::size_t>(k)];
        q = r;
      }
      c.face_offsets.push_back(static_cast<int>(c.face_vertices.size()));
      c.face_sizes.push_back(4);
      c.face_vertices.insert(c.face_vertices.end(), q.begin(), q.end());
      c.parent_face.push_back(f);
      c.face_hole.push_back(p.face_hole[f]);
    }
  }
  build_level_edges(&c);
}

// Child edge sharpness: each half of a parent edge inherits the parent's
// subdivided sharpness; edges inside a parent face are smooth.
void assign_child_edge_sharpness(const SubdivisionLevel& p, SubdivisionLevel& c) {
  const int nv = p.vertex_count(), nf = p.face_count();
  c.edge_sharpness.assign(c.edges.size(), kSharpnessSmooth);
  for (int f = 0; f < c.face_count(); ++f)
    for (int k = 0; k < 4; ++k) {
      const int corner = c.face_offsets[f] + k;
      int a = c.face_vertices[corner], b = c.face_vertices[c.face_offsets[f] + (k + 1) % 4];
      if (a > b) std::swap(a, b);
      if (a < nv && b >= nv + nf)  // a half of parent edge b - nv - nf
        c.edge_sharpness[static_cast<std::size_t>(c.face_edges[corner])] = subdivide_sharpness(p.edge_sharpness[b - nv - nf]);
    }
}

}  // namespace

SubdivisionLevel refine_catmull_clark(const SubdivisionLevel& p, const CatmullClarkFaults& faults) {
  const int nv = p.vertex_count(), nf = p.face_count(), ne = p.edge_count();
  const Incidence in = incidence_of(p);
  SubdivisionLevel c;
  c.positions.assign(static_cast<std::size_t>(nv + nf + ne), Vec3{0, 0, 0});
  c.vertex_sharpness.assign(c.positions.size(), kSharpnessSmooth);
  for (int v = 0; v < nv; ++v) c.child_of_parent_vertex.push_back(v);
  for (int f = 0; f < nf; ++f) c.child_of_parent_face.push_back(nv + f);
  for (int e = 0; e < ne; ++e) c.child_of_parent_edge.push_back(nv + nf + e);
  place_face_points(p, c);
  place_edge_points(p, in, faults, c);
  place_vertex_points(p, in, faults, c);
  build_child_faces(p, c);
  assign_child_edge_sharpness(p, c);
  return c;
}

std::vector<SubdivisionLevel> subdivide_catmull_clark(const MeshArrays& mesh, int levels,
                                                      const CatmullClarkFaults& faults) {
  std::vector<SubdivisionLevel> out;
  if (levels < 0 || levels > 6) return out;
  SubdivisionLevel base;
  if (!build_base_level(mesh, &base, !faults.no_non_manifold_rule)) return out;
  out.push_back(std::move(base));
  for (int k = 1; k <= levels; ++k) out.push_back(refine_catmull_clark(out.back(), faults));
  return out;
}

}  // namespace vgc
