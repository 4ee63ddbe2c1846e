// bench_real_meshes.cpp — not a test: on real meshes (Debian libcgal-demo's
// data/meshes, or any OBJ/OFF/PLY/STL), the time of each derived-geometry
// check `vgc certify --mesh` runs against the reference in process, beside
// the time its oracle alone takes on the same mesh (issue 28 item 1: "about
// what OpenSubdiv and CGAL cost").
//
// Spec: clauses MESH-CLASSIFY-1, NORMALS-SPLIT-1, SUBD-CATMARK-1 and
// LOOP-TRIANGLE-1 (oracles/capability_checks.h).
//
// Usage: bench_real_meshes [--levels N] [--repeats R] MESH...
//
// Per mesh and check, the median of R runs (default 3) of: "vgc" the whole
// check as certify runs it (the reference answers the request, its document
// is read back, the oracle refines or classifies, the two are compared);
// "oracle" the oracle alone (CGAL's classification for manifold,
// OpenSubdiv's refinement for subdivision and loop, the reference's split
// normals for normals: spec 003 has no external oracle); and their ratio.
// Wall times on a shared machine: read the ratio, not the seconds.
#include "bench_args.h"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "capability_checks.h"
#include "cgal_manifold.h"
#include "mesh_arrays.h"
#include "mesh_import.h"
#include "osd_subdivision.h"
#include "reference_implementation.h"
#include "split_normals.h"

namespace {

double median_seconds(int repeats, const std::function<void()>& f) {
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

struct Row {
  std::string check;
  std::function<bool()> vgc;     // true when the check passed
  std::function<void()> oracle;
};

int bench_mesh(const std::string& path, int levels, int repeats) {
  vgc::MeshProgram mesh;
  vgc::MeshFileError error;
  if (!vgc::import_mesh(path, vgc::MeshImportOptions{true}, &mesh, &error)) {
    std::fprintf(stderr, "%s:%zu: %s\n", path.c_str(), error.line, error.message.c_str());
    return 1;
  }
  vgc::ReferenceImplementation sut;
  sut.reset();
  for (const auto& c : mesh.program.commands) sut.apply(c);
  const vgc::Node& model = sut.node();
  const vgc::MeshArrays arrays = vgc::remove_unused_vertices(vgc::extract_mesh(model));
  std::vector<Row> rows;
  rows.push_back({"manifold", [&] { return !vgc::check_classify(model, sut); },
                  [&] { vgc::cgal_classify_mesh(vgc::extract_mesh(model)); }});
  rows.push_back({"normals", [&] { return !vgc::check_normals(model, sut); },
                  [&] { vgc::compute_split_normals(vgc::extract_mesh(model)); }});
  for (int l = 1; l <= levels; ++l)
    rows.push_back({"subdivision " + std::to_string(l), [&, l] { return !vgc::check_subdivision(model, sut, l); },
                    [&, l] {
                      vgc::osd_refine_uniform(vgc::osd_input_from_mesh(arrays, vgc::OsdScheme::CatmullClark, l));
                    }});
  if (mesh.quads == 0)
    for (int l = 1; l <= levels; ++l)
      rows.push_back({"loop " + std::to_string(l), [&, l] { return !vgc::check_loop(model, sut, l); },
                      [&, l] { vgc::osd_refine_uniform(vgc::osd_input_from_mesh(arrays, vgc::OsdScheme::Loop, l)); }});
  const std::string name = path.substr(path.find_last_of('/') + 1);
  double total_vgc = 0, total_oracle = 0;
  for (const Row& r : rows) {
    bool passed = true;
    const double v = median_seconds(repeats, [&] { passed = r.vgc() && passed; });
    const double o = median_seconds(repeats, r.oracle);
    total_vgc += v, total_oracle += o;
    std::printf("%-24s %8zu %8zu  %-14s %8.3f %8.3f %6.2fx  %s\n", name.c_str(), mesh.vertices,
                mesh.triangles + mesh.quads, r.check.c_str(), v, o, v / o, passed ? "pass" : "FAIL");
  }
  std::printf("%-24s %8zu %8zu  %-14s %8.3f %8.3f %6.2fx\n", name.c_str(), mesh.vertices, mesh.triangles + mesh.quads,
              "all checks", total_vgc, total_oracle, total_vgc / total_oracle);
  std::fflush(stdout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int levels = 2, repeats = 3;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--levels" && i + 1 < argc) levels = static_cast<int>(vgc::bench::count_argument("bench_real_meshes", "--levels", argv[++i], 1, 4));
    else if (a == "--repeats" && i + 1 < argc) repeats = static_cast<int>(vgc::bench::count_argument("bench_real_meshes", "--repeats", argv[++i], 1, 1000));
    else meshes.push_back(a);
  }
  if (meshes.empty() || levels < 1 || repeats < 1) {
    std::fprintf(stderr, "usage: bench_real_meshes [--levels N] [--repeats R] MESH...\n");
    return 2;
  }
  std::printf("%-24s %8s %8s  %-14s %8s %8s %7s  (seconds, median of %d)\n", "mesh", "vertices", "faces", "check",
              "vgc", "oracle", "ratio", repeats);
  int rc = 0;
  for (const auto& m : meshes) rc |= bench_mesh(m, levels, repeats);
  return rc;
}
