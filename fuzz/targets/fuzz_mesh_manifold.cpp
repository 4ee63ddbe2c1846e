// fuzz_mesh_manifold.cpp — the reference's connectivity and manifoldness
// (reference/geometry/mesh_topology.h classify_mesh) against CGAL's
// (oracles/cgal_manifold.h cgal_classify_mesh) on arbitrary small meshes.
//
// Spec: 002 (winged-edge connectivity, the manifold rules: an edge in one
// or two polygons, disc / half-disc vertex neighbourhoods), 000 section
// 2.6 (consistent front side).
//
// Per input: the bytes decode to a MeshArrays (fuzz/targets/mesh_bytes.h: up to 16
// vertices, up to 24 faces of 0..6 corners, repeated and out-of-range
// indices, any mix of orientations). classify_mesh and cgal_classify_mesh
// run on it and compare_topology_with_cgal (oracles/topology_comparison.h,
// the same comparison tests/oracles_manifold makes) must find no
// disagreement: status and bad face; polygon mesh; non-manifold edges and
// vertices; orientable and consistently oriented; and, where CGAL built a
// mesh matching the input, counts, Euler characteristic, boundary edges,
// vertices and loops, closedness, components. A disagreement prints the
// mesh and aborts (mesh_bytes.h report_mesh_finding).
#include <cstddef>
#include <cstdint>
#include <string>

#include "cgal_manifold.h"
#include "mesh_bytes.h"
#include "mesh_topology.h"
#include "topology_comparison.h"

namespace {
constexpr const char* kTarget = "fuzz_mesh_manifold";
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vgc;
  const MeshArrays mesh = fuzz::decode_mesh_bytes(data, size);
  const MeshTopology reference = classify_mesh(mesh);
  const CgalManifoldReport cgal = cgal_classify_mesh(mesh);
  const std::string why = compare_topology_with_cgal(reference, cgal);
  if (!why.empty())
    fuzz::report_mesh_finding(kTarget, std::string("reference vs CGAL: ") + why + " (reference status " +
                                           to_string(reference.status) + ")",
                              mesh);
  return 0;
}
