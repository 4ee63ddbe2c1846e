// subdivision_comparison.cpp — see subdivision_comparison.h.
#include "subdivision_comparison.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <sstream>

namespace vgc {

namespace {

std::uint64_t pair_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

// The correspondence of the current level, reference index -> OpenSubdiv
// index: vertices, faces (frot[f]: reference corner k of face f is
// OpenSubdiv's corner (k + frot[f]) % n of face fmap[f]) and edges.
struct LevelMatch {
  std::vector<int> vmap, fmap, frot, emap;
};

// Level 0 is numbered alike: the identity on vertices and faces.
LevelMatch identity_match(const SubdivisionLevel& base) {
  LevelMatch m;
  m.vmap.resize(static_cast<std::size_t>(base.vertex_count()));
  std::iota(m.vmap.begin(), m.vmap.end(), 0);
  m.fmap.resize(static_cast<std::size_t>(base.face_count()));
  std::iota(m.fmap.begin(), m.fmap.end(), 0);
  m.frot.assign(m.fmap.size(), 0);
  return m;
}

std::string compare_counts(std::size_t l, const SubdivisionLevel& r, const OsdLevel& o) {
  if (r.vertex_count() == static_cast<int>(o.positions.size()) && r.face_count() == static_cast<int>(o.face_sizes.size()) &&
      r.edge_count() == static_cast<int>(o.edges.size()))
    return {};
  std::ostringstream why;
  why << "level " << l << ": counts differ (v " << r.vertex_count() << "/" << o.positions.size() << ", f "
      << r.face_count() << "/" << o.face_sizes.size() << ", e " << r.edge_count() << "/" << o.edges.size() << ")";
  return why.str();
}

// The child of a parent vertex, edge and (Catmull-Clark: face_points) face
// is mapped to OpenSubdiv's child of the matched parent (001).
void map_child_vertices(const SubdivisionLevel& rp, const SubdivisionLevel& r, const OsdLevel& o, bool face_points,
                        LevelMatch& m) {
  std::vector<int> child(static_cast<std::size_t>(r.vertex_count()), -1);
  for (int v = 0; v < rp.vertex_count(); ++v)
    child[static_cast<std::size_t>(r.child_of_parent_vertex[v])] = o.child_of_parent_vertex[m.vmap[v]];
  for (int e = 0; e < rp.edge_count(); ++e)
    child[static_cast<std::size_t>(r.child_of_parent_edge[e])] = o.child_of_parent_edge[m.emap[static_cast<std::size_t>(e)]];
  if (face_points)
    for (int f = 0; f < rp.face_count(); ++f)
      child[static_cast<std::size_t>(r.child_of_parent_face[f])] = o.child_of_parent_face[m.fmap[f]];
  m.vmap = child;
}

// Child faces: every child of a parent face equals one of OpenSubdiv's
// GetFaceChildFaces of the matched parent, same vertices up to rotation.
std::string match_child_faces(std::size_t l, const SubdivisionLevel& rp, const SubdivisionLevel& r, const OsdLevel& o,
                              const std::vector<int>& ooffsets, LevelMatch& m) {
  std::vector<int> cf(static_cast<std::size_t>(r.face_count()), -1), crot(cf.size(), 0);
  for (int f = 0; f < rp.face_count(); ++f) {
    const auto& ochildren = o.child_faces_of_parent_face[m.fmap[f]];
    const int first = r.first_child_of_parent_face[f];
    const int n = (f + 1 < rp.face_count() ? r.first_child_of_parent_face[f + 1] : r.face_count()) - first;
    if (n != static_cast<int>(ochildren.size())) return "child face counts differ";
    for (int k = first; k < first + n; ++k) {
      std::vector<int> rv;
      for (int c = 0; c < r.face_sizes[k]; ++c) rv.push_back(m.vmap[r.face_vertices[r.face_offsets[k] + c]]);
      for (int oc : ochildren) {
        const int ooff = ooffsets[static_cast<std::size_t>(oc)];
        if (o.face_sizes[oc] != static_cast<int>(rv.size())) continue;
        for (std::size_t rot = 0; rot < rv.size(); ++rot) {
          bool same = true;
          for (std::size_t c = 0; c < rv.size() && same; ++c)
            same = o.face_vertices[static_cast<std::size_t>(ooff) + (c + rot) % rv.size()] == rv[c];
          if (same) {
            cf[static_cast<std::size_t>(k)] = oc;
            crot[static_cast<std::size_t>(k)] = static_cast<int>(rot);
          }
        }
      }
      if (cf[static_cast<std::size_t>(k)] < 0) {
        std::ostringstream why;
        why << "level " << l << ": child face " << k << " of parent face " << f << " has no OpenSubdiv counterpart";
        return why.str();
      }
    }
  }
  m.fmap = cf;
  m.frot = crot;
  return {};
}

// Edges, through the faces that use them (never by vertex pair: two edges
// may join the same two vertices, as in a Loop "pillow"); one to one.
std::string match_edges(std::size_t l, const SubdivisionLevel& r, const OsdLevel& o, const std::vector<int>& ooffsets,
                        LevelMatch& m) {
  std::ostringstream why;
  m.emap.assign(static_cast<std::size_t>(r.edge_count()), -1);
  std::vector<int> etaken(o.edges.size(), -1);
  for (int f = 0; f < r.face_count(); ++f) {
    const int n = r.face_sizes[f];
    for (int k = 0; k < n; ++k) {
      const int re = r.face_edges[r.face_offsets[f] + k];
      const int oe = o.face_edges[static_cast<std::size_t>(ooffsets[static_cast<std::size_t>(m.fmap[f])] + (k + m.frot[f]) % n)];
      int& e = m.emap[static_cast<std::size_t>(re)];
      if (e < 0 && etaken[static_cast<std::size_t>(oe)] < 0) {
        e = oe;
        etaken[static_cast<std::size_t>(oe)] = re;
      } else if (e != oe) {
        why << "level " << l << ": edge " << re << " (corner " << k << " of face " << f
            << ") has no single OpenSubdiv counterpart";
        return why.str();
      }
    }
  }
  for (int e = 0; e < r.edge_count(); ++e)
    if (m.emap[static_cast<std::size_t>(e)] < 0) {
      why << "level " << l << ": edge " << e << " has no OpenSubdiv counterpart (no face uses it)";
      return why.str();
    }
  return {};
}

// The vertex map is a bijection; positions agree within `tolerance`
// (absolute, max norm); vertex sharpness is equal.
std::string compare_vertices(std::size_t l, const SubdivisionLevel& r, const OsdLevel& o, double tolerance,
                             const LevelMatch& m) {
  std::ostringstream why;
  std::vector<int> seen(o.positions.size(), 0);
  for (int v = 0; v < r.vertex_count(); ++v) {
    const int ov = m.vmap[static_cast<std::size_t>(v)];
    if (ov < 0 || ov >= static_cast<int>(o.positions.size()) || seen[static_cast<std::size_t>(ov)]++) {
      why << "level " << l << ": vertex " << v << " is not matched one to one";
      return why.str();
    }
    double d = 0;
    for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(r.positions[v][k] - o.positions[ov][k]));
    if (!(d <= tolerance)) {
      why << "level " << l << ": vertex " << v << " differs by " << d << " (ref " << r.positions[v][0] << ","
          << r.positions[v][1] << "," << r.positions[v][2] << " osd " << o.positions[ov][0] << ","
          << o.positions[ov][1] << "," << o.positions[ov][2] << ")";
      return why.str();
    }
    if (r.vertex_sharpness[v] != o.vertex_sharpness[ov]) {
      why << "level " << l << ": vertex " << v << " sharpness " << r.vertex_sharpness[v] << " vs "
          << o.vertex_sharpness[ov];
      return why.str();
    }
  }
  return {};
}

// Every edge joins the matched vertices with equal sharpness; hole flags
// are equal.
std::string compare_edges_and_holes(std::size_t l, const SubdivisionLevel& r, const OsdLevel& o, const LevelMatch& m) {
  std::ostringstream why;
  for (int e = 0; e < r.edge_count(); ++e) {
    const auto& oe = o.edges[static_cast<std::size_t>(m.emap[static_cast<std::size_t>(e)])];
    if (pair_key(m.vmap[r.edges[e][0]], m.vmap[r.edges[e][1]]) != pair_key(oe[0], oe[1]) ||
        r.edge_sharpness[e] != o.edge_sharpness[static_cast<std::size_t>(m.emap[static_cast<std::size_t>(e)])]) {
      why << "level " << l << ": edge " << e << " missing or sharpness differs (" << r.edge_sharpness[e] << " vs "
          << o.edge_sharpness[static_cast<std::size_t>(m.emap[static_cast<std::size_t>(e)])] << ")";
      return why.str();
    }
  }
  for (int f = 0; f < r.face_count(); ++f)
    if (r.face_hole[f] != o.face_hole[m.fmap[f]]) {
      why << "level " << l << ": face " << f << " hole flag differs";
      return why.str();
    }
  return {};
}

}  // namespace

std::string compare_subdivision_by_parent(const std::vector<SubdivisionLevel>& ref, const OsdResult& osd,
                                          double tolerance, bool face_points) {
  if (!osd.ok) return "oracle failed: " + osd.failure;
  if (ref.size() != osd.levels.size()) return "level count differs";
  LevelMatch m = identity_match(ref[0]);
  for (std::size_t l = 0; l < ref.size(); ++l) {
    const SubdivisionLevel& r = ref[l];
    const OsdLevel& o = osd.levels[l];
    std::string why = compare_counts(l, r, o);
    if (!why.empty()) return why;
    std::vector<int> ooffsets(o.face_sizes.size() + 1, 0);
    for (std::size_t g = 0; g < o.face_sizes.size(); ++g) ooffsets[g + 1] = ooffsets[g] + o.face_sizes[g];
    if (l > 0) {
      map_child_vertices(ref[l - 1], r, o, face_points, m);
      why = match_child_faces(l, ref[l - 1], r, o, ooffsets, m);
      if (!why.empty()) return why;
    }
    why = match_edges(l, r, o, ooffsets, m);
    if (!why.empty()) return why;
    why = compare_vertices(l, r, o, tolerance, m);
    if (!why.empty()) return why;
    why = compare_edges_and_holes(l, r, o, m);
    if (!why.empty()) return why;
  }
  return {};
}

}  // namespace vgc
