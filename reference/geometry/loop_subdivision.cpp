// loop_subdivision.cpp — see loop_subdivision.h.
#include "loop_subdivision.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "crease_sharpness.h"

namespace vgc {
namespace {

using Vec3 = std::array<double, 3>;

void add_scaled(Vec3& acc, const Vec3& p, double w) {
  acc[0] += w * p[0];
  acc[1] += w * p[1];
  acc[2] += w * p[2];
}

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

int other_end(const std::array<int, 2>& e, int v) { return e[0] == v ? e[1] : e[0]; }

// The vertex of triangle f that is on neither end of edge e.
int opposite_vertex(const SubdivisionLevel& l, int f, int e) {
  for (int k = 0; k < 3; ++k) {
    const int v = l.face_vertices[l.face_offsets[f] + k];
    if (v != l.edges[e][0] && v != l.edges[e][1]) return v;
  }
  return -1;
}

// Loop's smooth vertex weights (Sdc Loop scheme): {vertex weight, neighbour weight}.
std::array<double, 2> smooth_vertex_weights(int valence, bool warren) {
  if (warren) {
    const double e = valence == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * valence);
    return {1.0 - e * valence, e};
  }
  if (valence == 6) return {0.625, 0.0625};
  const double n = valence;
  const double inv = 1.0 / n;
  const double cos_theta = std::cos(M_PI * 2.0 * inv);
  const double beta = 0.25 * cos_theta + 0.375;
  const double e = (0.625 - beta * beta) * inv;
  return {1.0 - e * n, e};
}

// The parent's incidences refine_loop reads: the edges at each vertex, the
// faces of each edge, the number of faces at each vertex.
struct LoopIncidence {
  std::vector<std::vector<int>> vertex_edges, edge_faces;
  std::vector<int> vertex_face_count;
};

LoopIncidence loop_incidence_of(const SubdivisionLevel& p) {
  const int nv = p.vertex_count(), nf = p.face_count(), ne = p.edge_count();
  LoopIncidence in;
  in.vertex_edges.resize(static_cast<std::size_t>(nv));
  in.edge_faces.resize(static_cast<std::size_t>(ne));
  in.vertex_face_count.assign(static_cast<std::size_t>(nv), 0);
  for (int e = 0; e < ne; ++e)
    for (int end = 0; end < 2; ++end) in.vertex_edges[static_cast<std::size_t>(p.edges[e][end])].push_back(e);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      ++in.vertex_face_count[static_cast<std::size_t>(p.face_vertices[p.face_offsets[f] + k])];
      in.edge_faces[static_cast<std::size_t>(p.face_edges[p.face_offsets[f] + k])].push_back(f);
    }
  return in;
}

// Edge points (Sdc Loop edge rule): 3/8 of each end and 1/8 of each
// opposite vertex (shared among the faces when not two); a sharp edge the
// crease rule (the midpoint), a sharpness in (0, 1] blended by it.
void place_loop_edge_points(const SubdivisionLevel& p, const LoopIncidence& in, const LoopFaults& faults,
                            SubdivisionLevel& c) {
  const int nv = p.vertex_count(), ne = p.edge_count();
  for (int e = 0; e < ne; ++e) {
    const float s = p.edge_sharpness[e];
    const auto& faces = in.edge_faces[e];
    double vw = 0.375;
    double fw = faces.size() == 2 ? 0.125 : 0.125 * 2.0 / static_cast<double>(faces.size());
    if (is_sharp(s)) {
      if (s > 1.0f) {
        vw = 0.5;
        fw = 0.0;
      } else if (!faults.no_fractional_blend) {
        const double pw = s, cw = 1.0f - pw;
        vw = pw * 0.5 + cw * vw;
        fw *= cw;
      }
    }
    Vec3& ep = c.positions[static_cast<std::size_t>(nv + e)];
    add_scaled(ep, p.positions[p.edges[e][0]], vw);
    add_scaled(ep, p.positions[p.edges[e][1]], vw);
    for (int f : faces) add_scaled(ep, p.positions[opposite_vertex(p, f, e)], fw);
  }
}

// Adds `weight` times vertex v's point by one vertex rule (Sdc): smooth and
// dart by Loop's (or Warren's) weights over the neighbours, crease 3/4 of v
// and 1/8 of each sharp neighbour, corner v itself.
void add_loop_vertex_rule(Vec3& acc, const SubdivisionLevel& p, int v, const std::vector<int>& vedges,
                          int face_count, CreaseRule rule, const std::vector<float>& sharp, double weight,
                          bool warren) {
  if (rule == CreaseRule::Smooth || rule == CreaseRule::Dart) {
    const auto w = smooth_vertex_weights(face_count, warren);
    for (int e : vedges) add_scaled(acc, p.positions[other_end(p.edges[e], v)], weight * w[1]);
    add_scaled(acc, p.positions[v], weight * w[0]);
  } else if (rule == CreaseRule::Crease) {
    for (std::size_t i = 0; i < vedges.size(); ++i)
      if (is_sharp(sharp[i])) add_scaled(acc, p.positions[other_end(p.edges[vedges[i]], v)], weight * 0.125);
    add_scaled(acc, p.positions[v], weight * 0.75);
  } else {
    add_scaled(acc, p.positions[v], weight);
  }
}

// Vertex points: the parent's rule, or where the child's rule differs (and
// the parent's is not smooth) the two blended by the fractional weight.
void place_loop_vertex_points(const SubdivisionLevel& p, const LoopIncidence& in, const LoopFaults& faults,
                              SubdivisionLevel& c) {
  const int nv = p.vertex_count();
  for (int v = 0; v < nv; ++v) {
    const auto& vedges = in.vertex_edges[v];
    std::vector<float> es, ces;
    for (int e : vedges) {
      es.push_back(p.edge_sharpness[e]);
      ces.push_back(subdivide_sharpness(p.edge_sharpness[e]));
    }
    const float vs = p.vertex_sharpness[v], cvs = subdivide_sharpness(vs);
    c.vertex_sharpness[static_cast<std::size_t>(v)] = cvs;
    CreaseRule prule = determine_vertex_rule(vs, es), crule = determine_vertex_rule(cvs, ces);
    if (vedges.empty()) prule = crule = CreaseRule::Corner;
    const int face_count = in.vertex_face_count[static_cast<std::size_t>(v)];
    Vec3 acc{0, 0, 0};
    if (prule == crule || prule == CreaseRule::Smooth || prule == CreaseRule::Dart) {
      add_loop_vertex_rule(acc, p, v, vedges, face_count, prule, es, 1.0, faults.warren_weights);
    } else {
      const double w = faults.no_fractional_blend ? 0.0 : fractional_weight_at_vertex(vs, cvs, es);
      add_loop_vertex_rule(acc, p, v, vedges, face_count, prule, es, w, faults.warren_weights);
      add_loop_vertex_rule(acc, p, v, vedges, face_count, crule, ces, 1.0 - w, faults.warren_weights);
    }
    c.positions[static_cast<std::size_t>(v)] = acc;
  }
}

// Child triangles T0..T3 (triangle_tree.h), oriented as the parent.
void build_loop_child_triangles(const SubdivisionLevel& p, SubdivisionLevel& c) {
  const int nv = p.vertex_count(), nf = p.face_count();
  for (int f = 0; f < nf; ++f) {
    const int o = p.face_offsets[f];
    std::array<int, 3> vc{}, sub{};
    for (int k = 0; k < 3; ++k) {
      vc[static_cast<std::size_t>(k)] = p.face_vertices[o + k];
      sub[static_cast<std::size_t>(k)] = nv + p.face_edges[o + (k + 1) % 3];  // edge k is opposite vertex k
    }
    c.first_child_of_parent_face.push_back(c.face_count());
    std::array<std::array<int, 3>, 4> kids{};
    kids[0] = {sub[0], sub[1], sub[2]};
    for (int j = 0; j < 3; ++j)
      kids[static_cast<std::size_t>(j + 1)] = {vc[static_cast<std::size_t>(j)], sub[static_cast<std::size_t>((j + 2) % 3)],
                                               sub[static_cast<std::size_t>((j + 1) % 3)]};
    for (const auto& t : kids) {
      c.face_offsets.push_back(static_cast<int>(c.face_vertices.size()));
      c.face_sizes.push_back(3);
      c.face_vertices.insert(c.face_vertices.end(), t.begin(), t.end());
      c.parent_face.push_back(f);
      c.face_hole.push_back(p.face_hole[f]);
    }
  }
}

// The seeded fault (LoopFaults::edges_by_vertex_pair): edges rebuilt from
// vertex pairs (merges the child edges of two triangles on the same three
// vertices).
void build_loop_child_edges_by_vertex_pair(const SubdivisionLevel& p, SubdivisionLevel& c) {
  const int nv = p.vertex_count(), ne = p.edge_count();
  build_level_edges(&c);
  std::unordered_map<std::uint64_t, int> cindex;
  for (int e = 0; e < c.edge_count(); ++e) cindex.emplace(edge_key(c.edges[e][0], c.edges[e][1]), e);
  c.edge_sharpness.assign(c.edges.size(), kSharpnessSmooth);
  for (int e = 0; e < ne; ++e) {
    const float cs = subdivide_sharpness(p.edge_sharpness[e]);
    for (int end = 0; end < 2; ++end) {
      auto it = cindex.find(edge_key(p.edges[e][end], nv + e));
      if (it != cindex.end()) c.edge_sharpness[static_cast<std::size_t>(it->second)] = cs;
    }
  }
}

// Child edges from the parent's topology (see the header, as OpenSubdiv's
// Vtr::TriRefinement): the halves of each parent edge, then three inside
// each parent face; and each child triangle's face_edges.
void build_loop_child_edges(const SubdivisionLevel& p, const LoopIncidence& in, SubdivisionLevel& c) {
  const int nv = p.vertex_count(), nf = p.face_count(), ne = p.edge_count();
  c.edges.assign(static_cast<std::size_t>(2 * ne + 3 * nf), {0, 0});
  c.edge_sharpness.assign(c.edges.size(), kSharpnessSmooth);
  c.edge_face_count.assign(c.edges.size(), 2);
  for (int e = 0; e < ne; ++e) {
    const float cs = subdivide_sharpness(p.edge_sharpness[e]);
    const int faces = static_cast<int>(in.edge_faces[static_cast<std::size_t>(e)].size());
    for (int end = 0; end < 2; ++end) {
      const auto ce = static_cast<std::size_t>(2 * e + end);
      c.edges[ce] = {p.edges[e][end], nv + e};
      c.edge_sharpness[ce] = cs;
      c.edge_face_count[ce] = faces;
    }
  }
  // The half of parent edge e at its end vertex w.
  auto half = [&](int e, int w) { return 2 * e + (p.edges[e][0] == w ? 0 : 1); };
  c.face_edges.assign(c.face_vertices.size(), -1);
  for (int f = 0; f < nf; ++f) {
    const int o = p.face_offsets[f];
    const int inner = 2 * ne + 3 * f;  // inner + j joins s(j+1) and s(j+2)
    std::array<int, 3> sub{};
    for (int k = 0; k < 3; ++k) sub[static_cast<std::size_t>(k)] = nv + p.face_edges[o + (k + 1) % 3];
    for (int j = 0; j < 3; ++j)
      c.edges[static_cast<std::size_t>(inner + j)] = {sub[static_cast<std::size_t>((j + 1) % 3)],
                                                      sub[static_cast<std::size_t>((j + 2) % 3)]};
    const int first = c.first_child_of_parent_face[static_cast<std::size_t>(f)];
    // T0 = [s0 s1 s2]: s0->s1 is inner 2, s1->s2 inner 0, s2->s0 inner 1.
    int* t0 = c.face_edges.data() + c.face_offsets[static_cast<std::size_t>(first)];
    t0[0] = inner + 2;
    t0[1] = inner + 0;
    t0[2] = inner + 1;
    // T(j+1) = [vj s(j+2) s(j+1)]: vj->s(j+2) is the half of the edge from
    // corner j to j+1 at vj; s(j+2)->s(j+1) is inner j; s(j+1)->vj the half
    // of the edge from corner j+2 to j at vj.
    for (int j = 0; j < 3; ++j) {
      const int vj = p.face_vertices[o + j];
      int* tj = c.face_edges.data() + c.face_offsets[static_cast<std::size_t>(first + j + 1)];
      tj[0] = half(p.face_edges[o + j], vj);
      tj[1] = inner + j;
      tj[2] = half(p.face_edges[o + (j + 2) % 3], vj);
    }
  }
}

}  // namespace

SubdivisionLevel refine_loop(const SubdivisionLevel& p, const LoopFaults& faults) {
  for (int n : p.face_sizes)
    if (n != 3) return {};
  const int nv = p.vertex_count(), ne = p.edge_count();
  const LoopIncidence in = loop_incidence_of(p);
  SubdivisionLevel c;
  c.positions.assign(static_cast<std::size_t>(nv + ne), Vec3{0, 0, 0});
  c.vertex_sharpness.assign(c.positions.size(), kSharpnessSmooth);
  for (int v = 0; v < nv; ++v) c.child_of_parent_vertex.push_back(v);
  for (int e = 0; e < ne; ++e) c.child_of_parent_edge.push_back(nv + e);
  place_loop_edge_points(p, in, faults, c);
  place_loop_vertex_points(p, in, faults, c);
  build_loop_child_triangles(p, c);
  if (faults.edges_by_vertex_pair)
    build_loop_child_edges_by_vertex_pair(p, c);
  else
    build_loop_child_edges(p, in, c);
  return c;
}

std::vector<SubdivisionLevel> subdivide_loop(const MeshArrays& mesh, int levels, const LoopFaults& faults) {
  std::vector<SubdivisionLevel> out;
  if (levels < 0 || levels > 6) return out;
  for (int n : mesh.face_sizes)
    if (n != 3) return out;
  SubdivisionLevel base;
  if (!build_base_level(mesh, &base, !faults.no_non_manifold_rule)) return out;
  out.push_back(std::move(base));
  for (int k = 1; k <= levels; ++k) out.push_back(refine_loop(out.back(), faults));
  return out;
}

}  // namespace vgc
