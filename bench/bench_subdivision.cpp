// bench_subdivision.cpp — not a test: times the reference Catmull-Clark
// (reference/geometry/catmull_clark.h) against OpenSubdiv (oracles/osd_subdivision.h)
// refining a 100k-face mesh (a 400 x 250 quad torus with a few creases) to
// level 2. Usage: bench_subdivision [levels] [repeats]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "catmull_clark.h"
#include "crease_sharpness.h"
#include "osd_subdivision.h"

namespace {

vgc::MeshArrays torus(int nu, int nv) {
  vgc::MeshArrays m;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      m.positions.push_back({(3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)});
      m.vertex_ids.push_back(static_cast<std::uint32_t>(m.vertex_ids.size()));
      m.vertex_creases.push_back(i % 97 == 0 && j % 89 == 0 ? 0xFFFFFFFFu : 0u);
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = j * nu + i, b = j * nu + (i + 1) % nu, c = ((j + 1) % nv) * nu + (i + 1) % nu, d = ((j + 1) % nv) * nu + i;
      m.polygon_ids.push_back(static_cast<std::uint32_t>(m.polygon_ids.size()));
      m.face_sizes.push_back(4);
      for (int x : {a, b, c, d}) m.face_vertices.push_back(x);
      for (int k = 0; k < 4; ++k) m.corner_edge_creases.push_back(j == 0 ? 0x40000000u : 0u);  // a semi-sharp ring
    }
  vgc::update_face_offsets(m);
  return m;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const int levels = argc > 1 ? std::atoi(argv[1]) : 2;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  const vgc::MeshArrays mesh = torus(400, 250);
  std::printf("mesh: %d vertices, %d faces; levels %d; best of %d\n", mesh.vertex_count(), mesh.face_count(), levels, repeats);

  vgc::OsdInput in;
  in.levels = levels;
  in.positions = mesh.positions;
  in.face_sizes = mesh.face_sizes;
  in.face_vertices = mesh.face_vertices;
  for (int v = 0; v < mesh.vertex_count(); ++v)
    if (mesh.vertex_creases[v]) {
      in.corner_vertices.push_back(v);
      in.corner_sharpness.push_back(vgc::crease_to_sharpness(mesh.vertex_creases[v]));
    }
  for (int i = 0; i < 400; ++i) {
    in.crease_edges.push_back({i, (i + 1) % 400});
    in.crease_sharpness.push_back(vgc::crease_to_sharpness(0x40000000u));
  }

  double best_ref = 1e30, best_osd = 1e30;
  std::size_t ref_faces = 0, osd_faces = 0;
  for (int r = 0; r < repeats; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    const auto levels_ref = vgc::subdivide_catmull_clark(mesh, levels);
    best_ref = std::min(best_ref, seconds_since(t0));
    ref_faces = levels_ref.empty() ? 0 : levels_ref.back().face_sizes.size();
    t0 = std::chrono::steady_clock::now();
    const vgc::OsdResult osd = vgc::osd_refine_uniform(in);
    best_osd = std::min(best_osd, seconds_since(t0));
    osd_faces = osd.ok ? osd.levels.back().face_sizes.size() : 0;
  }
  std::printf("reference  : %8.3f s  (%zu faces at level %d)\n", best_ref, ref_faces, levels);
  std::printf("OpenSubdiv : %8.3f s  (%zu faces at level %d; includes copying every level out)\n", best_osd, osd_faces, levels);
  std::printf("ratio reference/OpenSubdiv: %.2f\n", best_ref / best_osd);
  return ref_faces == osd_faces && ref_faces > 0 ? 0 : 1;
}
