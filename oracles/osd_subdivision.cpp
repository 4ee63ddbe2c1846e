// osd_subdivision.cpp — see osd_subdivision.h. The only file that includes
// OpenSubdiv headers.
#include "osd_subdivision.h"

#include <opensubdiv/far/error.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <map>
#include <memory>

#include "crease_sharpness.h"

namespace vgc {
namespace {

using namespace OpenSubdiv;

// OpenSubdiv's callbacks are global and carry no user pointer.
std::vector<std::string>* g_messages = nullptr;

void on_error(Far::ErrorType, const char* message) {
  if (g_messages) g_messages->push_back(std::string("error: ") + message);
}
void on_warning(const char* message) {
  if (g_messages) g_messages->push_back(std::string("warning: ") + message);
}

struct Point {
  double p[3] = {0, 0, 0};
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const Point& s, double w) {
    p[0] += w * s.p[0];
    p[1] += w * s.p[1];
    p[2] += w * s.p[2];
  }
};

std::string check_input(const OsdInput& in) {
  const int nv = static_cast<int>(in.positions.size());
  if (in.levels < 1 || in.levels > 10) return "levels outside 1..10";
  long long corners = 0;
  for (int n : in.face_sizes) {
    if (n < 3) return "a face with fewer than 3 corners";
    if (in.scheme == OsdScheme::Loop && n != 3) return "Loop needs triangles";
    corners += n;
  }
  if (corners != static_cast<long long>(in.face_vertices.size())) return "face sizes do not sum to the corner count";
  for (int v : in.face_vertices)
    if (v < 0 || v >= nv) return "corner index out of range";
  if (in.crease_edges.size() != in.crease_sharpness.size()) return "crease arrays differ in length";
  for (const auto& e : in.crease_edges)
    if (e[0] < 0 || e[0] >= nv || e[1] < 0 || e[1] >= nv) return "crease vertex out of range";
  if (in.corner_vertices.size() != in.corner_sharpness.size()) return "corner arrays differ in length";
  for (int v : in.corner_vertices)
    if (v < 0 || v >= nv) return "corner vertex out of range";
  for (int f : in.hole_faces)
    if (f < 0 || f >= static_cast<int>(in.face_sizes.size())) return "hole face out of range";
  return {};
}

}  // namespace

OsdResult osd_refine_uniform(const OsdInput& in) {
  OsdResult result;
  result.failure = check_input(in);
  if (!result.failure.empty()) return result;

  g_messages = &result.messages;
  Far::SetErrorCallback(on_error);
  Far::SetWarningCallback(on_warning);

  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  sdc.SetCreasingMethod(Sdc::Options::CREASE_UNIFORM);
  sdc.SetTriangleSubdivision(Sdc::Options::TRI_SUB_CATMARK);
  sdc.SetFVarLinearInterpolation(Sdc::Options::FVAR_LINEAR_ALL);

  std::vector<int> crease_pairs;
  for (const auto& e : in.crease_edges) crease_pairs.insert(crease_pairs.end(), {e[0], e[1]});

  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(in.positions.size());
  desc.numFaces = static_cast<int>(in.face_sizes.size());
  desc.numVertsPerFace = in.face_sizes.data();
  desc.vertIndicesPerFace = in.face_vertices.data();
  desc.numCreases = static_cast<int>(in.crease_edges.size());
  desc.creaseVertexIndexPairs = crease_pairs.data();
  desc.creaseWeights = in.crease_sharpness.data();
  desc.numCorners = static_cast<int>(in.corner_vertices.size());
  desc.cornerVertexIndices = in.corner_vertices.data();
  desc.cornerWeights = in.corner_sharpness.data();
  desc.numHoles = static_cast<int>(in.hole_faces.size());
  desc.holeIndices = in.hole_faces.data();

  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  Factory::Options options(in.scheme == OsdScheme::Loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, sdc);
  options.validateFullTopology = true;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, options));
  if (!refiner) {
    result.failure = "TopologyRefinerFactory::Create returned null";
    g_messages = nullptr;
    return result;
  }
  Far::TopologyRefiner::UniformOptions uniform(in.levels);
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);

  std::vector<std::vector<Point>> points(static_cast<std::size_t>(in.levels + 1));
  for (const auto& p : in.positions) {
    Point q;
    q.p[0] = p[0], q.p[1] = p[1], q.p[2] = p[2];
    points[0].push_back(q);
  }
  Far::PrimvarRefinerReal<double> primvar(*refiner);
  for (int l = 1; l <= in.levels; ++l) {
    points[static_cast<std::size_t>(l)].resize(static_cast<std::size_t>(refiner->GetLevel(l).GetNumVertices()));
    Point* src = points[static_cast<std::size_t>(l - 1)].data();
    Point* dst = points[static_cast<std::size_t>(l)].data();
    primvar.Interpolate(l, src, dst);
  }

  for (int l = 0; l <= in.levels; ++l) {
    const Far::TopologyLevel& t = refiner->GetLevel(l);
    OsdLevel out;
    for (const Point& q : points[static_cast<std::size_t>(l)]) out.positions.push_back({q.p[0], q.p[1], q.p[2]});
    for (int f = 0; f < t.GetNumFaces(); ++f) {
      Far::ConstIndexArray fv = t.GetFaceVertices(f);
      Far::ConstIndexArray fe = t.GetFaceEdges(f);
      out.face_sizes.push_back(fv.size());
      for (int k = 0; k < fv.size(); ++k) out.face_vertices.push_back(fv[k]);
      for (int k = 0; k < fe.size(); ++k) out.face_edges.push_back(fe[k]);
      out.face_hole.push_back(t.IsFaceHole(f) ? 1 : 0);
    }
    for (int e = 0; e < t.GetNumEdges(); ++e) {
      Far::ConstIndexArray ev = t.GetEdgeVertices(e);
      out.edges.push_back({ev[0], ev[1]});
      out.edge_sharpness.push_back(t.GetEdgeSharpness(e));
    }
    for (int v = 0; v < t.GetNumVertices(); ++v) out.vertex_sharpness.push_back(t.GetVertexSharpness(v));
    if (l > 0) {
      const Far::TopologyLevel& parent = refiner->GetLevel(l - 1);
      for (int v = 0; v < parent.GetNumVertices(); ++v) out.child_of_parent_vertex.push_back(parent.GetVertexChildVertex(v));
      for (int e = 0; e < parent.GetNumEdges(); ++e) out.child_of_parent_edge.push_back(parent.GetEdgeChildVertex(e));
      for (int f = 0; f < parent.GetNumFaces(); ++f) {
        // GetFaceChildVertex on a Loop refiner crashes: Loop has no face points.
        if (in.scheme == OsdScheme::CatmullClark) out.child_of_parent_face.push_back(parent.GetFaceChildVertex(f));
        Far::ConstIndexArray cf = parent.GetFaceChildFaces(f);
        out.child_faces_of_parent_face.emplace_back(cf.begin(), cf.end());
      }
    }
    result.levels.push_back(std::move(out));
  }
  g_messages = nullptr;
  result.ok = true;
  return result;
}

OsdInput osd_input_from_mesh(const MeshArrays& m, OsdScheme scheme, int levels) {
  OsdInput in;
  in.scheme = scheme;
  in.levels = levels;
  in.positions = m.positions;
  in.face_sizes = m.face_sizes;
  in.face_vertices = m.face_vertices;
  std::map<std::pair<int, int>, std::vector<std::uint32_t>> stored;
  for (int f = 0; f < m.face_count(); ++f)
    for (int c = 0; c < m.face_sizes[f]; ++c) {
      const int a = m.face_vertices[m.face_offsets[f] + c];
      const int b = m.face_vertices[m.face_offsets[f] + (c + 1) % m.face_sizes[f]];
      stored[{std::min(a, b), std::max(a, b)}].push_back(m.corner_edge_creases[m.face_offsets[f] + c]);
    }
  for (const auto& [e, creases] : stored) {
    const float s = crease_to_sharpness(combine_edge_creases(creases));
    if (s > 0) {
      in.crease_edges.push_back({e.first, e.second});
      in.crease_sharpness.push_back(s);
    }
  }
  for (int v = 0; v < m.vertex_count(); ++v) {
    const float s = crease_to_sharpness(m.vertex_creases[static_cast<std::size_t>(v)]);
    if (s > 0) {
      in.corner_vertices.push_back(v);
      in.corner_sharpness.push_back(s);
    }
  }
  return in;
}

}  // namespace vgc
