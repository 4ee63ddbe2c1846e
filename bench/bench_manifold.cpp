// bench_manifold.cpp — how long the reference (reference/geometry/mesh_topology.h)
// and CGAL (oracles/cgal_manifold.h) take to classify a closed quad torus
// of 320 x 320 = 102400 faces, and the reference's split normals on it.
// A timing executable, not a test: run build-*/bench/bench_manifold.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>

#include "cgal_manifold.h"
#include "mesh_arrays.h"
#include "mesh_topology.h"
#include "split_normals.h"

namespace {

vgc::MeshArrays torus(int w, int h) {
  vgc::MeshArrays m;
  const double pi = std::acos(-1.0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double u = 2 * pi * i / w, v = 2 * pi * j / h;
      m.positions.push_back({(3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)});
      m.vertex_ids.push_back(static_cast<std::uint32_t>(m.vertex_ids.size()));
      m.vertex_creases.push_back(0);
    }
  auto id = [w, h](int i, int j) { return (j % h) * w + (i % w); };
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      m.polygon_ids.push_back(static_cast<std::uint32_t>(m.polygon_ids.size()));
      m.face_sizes.push_back(4);
      for (int v : {id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)}) {
        m.face_vertices.push_back(v);
        m.corner_edge_creases.push_back((i % 8 == 0) ? 0xFFFFFFFFu : 0u);
      }
    }
  vgc::update_face_offsets(m);
  return m;
}

const vgc::MeshArrays& mesh() {
  static const vgc::MeshArrays m = torus(320, 320);
  return m;
}

void BM_ReferenceClassify(benchmark::State& state) {
  for (auto _ : state) {
    vgc::MeshTopology t = vgc::classify_mesh(mesh());
    benchmark::DoNotOptimize(t.euler_characteristic);
  }
  state.counters["faces"] = mesh().face_count();
}

void BM_CgalClassify(benchmark::State& state) {
  for (auto _ : state) {
    vgc::CgalManifoldReport r = vgc::cgal_classify_mesh(mesh());
    benchmark::DoNotOptimize(r.euler_characteristic);
  }
  state.counters["faces"] = mesh().face_count();
}

void BM_ReferenceSplitNormals(benchmark::State& state) {
  for (auto _ : state) {
    vgc::SplitNormals s = vgc::compute_split_normals(mesh());
    benchmark::DoNotOptimize(s.fan_count);
  }
  state.counters["faces"] = mesh().face_count();
}

BENCHMARK(BM_ReferenceClassify)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CgalClassify)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReferenceSplitNormals)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
