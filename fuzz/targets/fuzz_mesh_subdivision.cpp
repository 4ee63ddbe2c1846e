// fuzz_mesh_subdivision.cpp — the reference's uniform Catmull-Clark
// (reference/geometry/catmull_clark.h) and Loop (reference/geometry/loop_subdivision.h)
// against OpenSubdiv (oracles/osd_subdivision.h) on arbitrary small meshes
// with vertex and edge creases.
//
// Spec: 000 section 2.6 (Catmull/Clark subdivision surfaces with vertex and
// edge creases), 2.6.2 (crease values, via crease_sharpness.h), 004 (Loop
// subdivision of triangles), 001 (children named by parent).
//
// Per input: the bytes decode to a MeshArrays (fuzz/targets/mesh_bytes.h: lattice
// positions, creases smooth / fractional / semi-sharp / infinite, faces of
// 3..6 corners). Compared on every mesh that passes check_mesh (every mesh
// a geometry node can hold, and n-gons besides), non-manifold included:
// the reference follows OpenSubdiv's non-manifold rules
// (reference/geometry/catmull_clark.h build_base_level: non-manifold edges, and
// edges two faces use the same way, infinitely sharp; non-manifold
// vertices infinitely sharp corners except on an interior non-manifold
// crease) and builds Loop's child edges from the parent topology
// (loop_subdivision.h), so fins, bow-ties, pillows and same-direction
// neighbours are compared like any other mesh. The vertices no face uses
// are removed (the reference keeps them fixed; OpenSubdiv is not compared
// there). Then subdivide_catmull_clark and OpenSubdiv's SCHEME_CATMARK to
// kLevels levels, and for all-triangle meshes subdivide_loop and
// SCHEME_LOOP, compared level by level by parent component
// (oracles/subdivision_comparison.h, the comparison of
// tests/oracles_subdivision): counts, the parent-child bijection, child
// faces up to rotation, edges through the faces using them, positions
// within 1e-9 * max(1, largest coordinate), vertex and edge sharpness,
// holes. A disagreement, or the reference refusing a mesh OpenSubdiv
// refines, prints the mesh and aborts. A mesh OpenSubdiv refuses is not
// judged (no finding: nothing was compared).
//
// Seeded faults (to show the target can fail): VGC_FUZZ_MESH_FAULT names
// one switch of CatmullClarkFaults or LoopFaults (cc-pin-boundary,
// cc-no-fractional-blend, cc-wrong-crease-weights, cc-no-non-manifold-rule,
// loop-warren, loop-no-fractional-blend, loop-no-non-manifold-rule,
// loop-edges-by-vertex-pair); unset or empty, the reference is run as is.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "catmull_clark.h"
#include "loop_subdivision.h"
#include "mesh_bytes.h"
#include "mesh_topology.h"
#include "osd_subdivision.h"
#include "subdivision_comparison.h"

namespace {

constexpr const char* kTarget = "fuzz_mesh_subdivision";
constexpr int kLevels = 3;

vgc::CatmullClarkFaults g_cc_faults;
vgc::LoopFaults g_loop_faults;
bool g_initialized = false;

void init() {
  g_initialized = true;
  const char* f = std::getenv("VGC_FUZZ_MESH_FAULT");
  if (!f || !*f) return;
  const std::string fault = f;
  if (fault == "cc-pin-boundary") g_cc_faults.pin_boundary_vertices = true;
  else if (fault == "cc-no-fractional-blend") g_cc_faults.no_fractional_blend = true;
  else if (fault == "cc-wrong-crease-weights") g_cc_faults.wrong_crease_weights = true;
  else if (fault == "loop-warren") g_loop_faults.warren_weights = true;
  else if (fault == "loop-no-fractional-blend") g_loop_faults.no_fractional_blend = true;
  else if (fault == "cc-no-non-manifold-rule") g_cc_faults.no_non_manifold_rule = true;
  else if (fault == "loop-no-non-manifold-rule") g_loop_faults.no_non_manifold_rule = true;
  else if (fault == "loop-edges-by-vertex-pair") g_loop_faults.edges_by_vertex_pair = true;
  else {
    std::fprintf(stderr, "vgc-fuzz: unknown VGC_FUZZ_MESH_FAULT '%s'\n", f);
    std::exit(2);
  }
  std::fprintf(stderr, "vgc-fuzz: %s runs a reference with the seeded fault %s\n", kTarget, f);
}

double mesh_scale(const vgc::MeshArrays& m) {
  double s = 1.0;
  for (const auto& p : m.positions)
    for (double x : p) s = std::max(s, std::abs(x));
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vgc;
  if (!g_initialized) init();
  const MeshArrays decoded = fuzz::decode_mesh_bytes(data, size);
  const MeshTopology topology = classify_mesh(decoded);
  if (topology.status != MeshStatus::Ok || decoded.face_count() == 0) return 0;
  const MeshArrays mesh = remove_unused_vertices(decoded);
  const double tolerance = 1e-9 * mesh_scale(mesh);

  const auto cc = subdivide_catmull_clark(mesh, kLevels, g_cc_faults);
  const OsdResult osd_cc = osd_refine_uniform(osd_input_from_mesh(mesh, OsdScheme::CatmullClark, kLevels));
  if (cc.empty() && osd_cc.ok) fuzz::report_mesh_finding(kTarget, "Catmull-Clark: the reference refused a mesh OpenSubdiv refines", mesh);
  if (!osd_cc.ok) return 0;  // not judged: OpenSubdiv cannot be asked
  if (const std::string why = compare_subdivision_by_parent(cc, osd_cc, tolerance, true); !why.empty())
    fuzz::report_mesh_finding(kTarget, "Catmull-Clark reference vs OpenSubdiv: " + why, mesh);

  const bool triangles = std::all_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](int n) { return n == 3; });
  if (!triangles) return 0;
  const auto loop = subdivide_loop(mesh, kLevels, g_loop_faults);
  const OsdResult osd_loop = osd_refine_uniform(osd_input_from_mesh(mesh, OsdScheme::Loop, kLevels));
  if (loop.empty() && osd_loop.ok) fuzz::report_mesh_finding(kTarget, "Loop: the reference refused a mesh OpenSubdiv refines", mesh);
  if (!osd_loop.ok) return 0;  // not judged: OpenSubdiv cannot be asked
  if (const std::string why = compare_subdivision_by_parent(loop, osd_loop, tolerance, false); !why.empty())
    fuzz::report_mesh_finding(kTarget, "Loop reference vs OpenSubdiv: " + why, mesh);
  return 0;
}
