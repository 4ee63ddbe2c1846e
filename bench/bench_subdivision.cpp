// bench_subdivision.cpp — not a test: times the reference Catmull-Clark
// (reference/geometry/catmull_clark.h) against OpenSubdiv
// (oracles/osd_subdivision.h) refining the same 100k-face mesh with the same
// creases, after checking that the two agree.
//
// Spec: 000 section 2.6 (Catmull/Clark with vertex and edge creases), 2.6.2
// (crease values).
//
// Usage: bench_subdivision [levels [repeats]]   (default: levels 2, 3 runs)
//
// The mesh is a 400 x 250 quad torus whose ring j = 0 is a semi-sharp edge
// crease (0x40000000, stored on both polygons of each ring edge) and every
// vertex at i % 97 == 0, j % 89 == 0 an infinitely sharp vertex crease.
// OpenSubdiv gets that node's creases through the oracle's own mapping,
// osd_input_from_mesh (the one certify uses); the bench checks that it
// received exactly the 400 ring edges and the corner vertices, then that
// every level agrees with the reference by parent component
// (compare_subdivision_by_parent: counts, positions within 1e-9, sharpness),
// and only then times. Each timed run is a fresh forked process, so its
// peak resident memory (getrusage ru_maxrss) is that side's alone; a process
// that does nothing gives the baseline every fork inherits. Reported: the
// median of the runs for wall time, CPU time (user + sys, the fair figure on
// a shared machine) and peak memory above the baseline. OpenSubdiv's time
// includes copying every level out into plain arrays (OsdResult), as the
// reference's result holds them.
#include "bench_args.h"
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "catmull_clark.h"
#include "crease_sharpness.h"
#include "osd_subdivision.h"
#include "subdivision_comparison.h"

namespace {

constexpr int kNu = 400, kNv = 250;
constexpr std::uint32_t kRingCrease = 0x40000000u;

bool is_corner_vertex(int i, int j) { return i % 97 == 0 && j % 89 == 0; }

vgc::MeshArrays crease_torus() {
  vgc::MeshArrays m;
  for (int j = 0; j < kNv; ++j)
    for (int i = 0; i < kNu; ++i) {
      const double u = 2 * M_PI * i / kNu, v = 2 * M_PI * j / kNv;
      m.positions.push_back({(3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)});
      m.vertex_ids.push_back(static_cast<std::uint32_t>(m.vertex_ids.size()));
      m.vertex_creases.push_back(is_corner_vertex(i, j) ? 0xFFFFFFFFu : 0u);
    }
  for (int j = 0; j < kNv; ++j)
    for (int i = 0; i < kNu; ++i) {
      const int a = j * kNu + i, b = j * kNu + (i + 1) % kNu, c = ((j + 1) % kNv) * kNu + (i + 1) % kNu,
                d = ((j + 1) % kNv) * kNu + i;
      m.polygon_ids.push_back(static_cast<std::uint32_t>(m.polygon_ids.size()));
      m.face_sizes.push_back(4);
      for (int x : {a, b, c, d}) m.face_vertices.push_back(x);
      // Corner k's crease is the edge from corner k to k + 1: a -> b lies on
      // ring 0 in row 0, c -> d in row kNv - 1.
      const bool ring_ab = j == 0, ring_cd = j == kNv - 1;
      for (int k = 0; k < 4; ++k)
        m.corner_edge_creases.push_back((k == 0 && ring_ab) || (k == 2 && ring_cd) ? kRingCrease : 0u);
    }
  vgc::update_face_offsets(m);
  return m;
}

// OpenSubdiv's input must carry exactly the creases the node holds.
std::string check_same_creases(const vgc::OsdInput& in) {
  int corners = 0;
  for (int j = 0; j < kNv; ++j)
    for (int i = 0; i < kNu; ++i) corners += is_corner_vertex(i, j) ? 1 : 0;
  if (static_cast<int>(in.crease_edges.size()) != kNu)
    return std::to_string(in.crease_edges.size()) + " crease edges given to OpenSubdiv, not the ring's " + std::to_string(kNu);
  for (std::size_t k = 0; k < in.crease_edges.size(); ++k)
    if (in.crease_edges[k][0] >= kNu || in.crease_edges[k][1] >= kNu ||
        in.crease_sharpness[k] != vgc::crease_to_sharpness(kRingCrease))
      return "crease edge " + std::to_string(k) + " is not a ring edge with the ring's sharpness";
  if (static_cast<int>(in.corner_vertices.size()) != corners)
    return std::to_string(in.corner_vertices.size()) + " corner vertices given to OpenSubdiv, not " + std::to_string(corners);
  return "";
}

struct Run {
  bool ok = false;
  double wall = 0, cpu = 0;  // seconds
  long max_rss_kb = 0;
};

// Runs `work` in a forked child; the child reports its own wall time of
// `work` through a pipe and exits 0 if `work` returned true.
Run run_in_child(const std::function<bool()>& work) {
  Run r;
  int fd[2];
  if (pipe(fd) != 0) return r;
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return r;
  if (pid == 0) {
    close(fd[0]);
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = work();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    (void)!write(fd[1], &s, sizeof s);
    std::fflush(nullptr);
    _exit(ok ? 0 : 1);
  }
  close(fd[1]);
  double s = 0;
  const bool got = read(fd[0], &s, sizeof s) == static_cast<ssize_t>(sizeof s);
  close(fd[0]);
  int status = 0;
  rusage u{};
  if (wait4(pid, &status, 0, &u) != pid) return r;
  r.ok = got && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  r.wall = s;
  r.cpu = static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  r.max_rss_kb = u.ru_maxrss;
  return r;
}

template <typename T>
T median(std::vector<T> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Summary {
  double wall, cpu, mb;
};

Summary summarize(const std::vector<Run>& runs, long baseline_kb) {
  std::vector<double> wall, cpu, mb;
  for (const Run& r : runs) {
    wall.push_back(r.wall);
    cpu.push_back(r.cpu);
    mb.push_back(static_cast<double>(r.max_rss_kb - baseline_kb) / 1024.0);
  }
  return {median(wall), median(cpu), median(mb)};
}

}  // namespace

int main(int argc, char** argv) {
  const int levels = argc > 1 ? static_cast<int>(vgc::bench::count_argument("bench_subdivision", "levels", argv[1], 1, 4)) : 2;
  const int repeats = argc > 2 ? static_cast<int>(vgc::bench::count_argument("bench_subdivision", "repeats", argv[2], 1, 1000)) : 3;
  if (levels < 1 || levels > 4 || repeats < 1) {
    std::fprintf(stderr, "usage: bench_subdivision [levels 1..4 [repeats >= 1]]\n");
    return 2;
  }
  const vgc::MeshArrays mesh = crease_torus();
  const vgc::OsdInput in = vgc::osd_input_from_mesh(mesh, vgc::OsdScheme::CatmullClark, levels);
  std::printf("mesh: %d vertices, %d faces; %zu crease edges, %zu corner vertices; level %d; median of %d runs\n",
              mesh.vertex_count(), mesh.face_count(), in.crease_edges.size(), in.corner_vertices.size(), levels,
              repeats);
  if (const std::string why = check_same_creases(in); !why.empty()) {
    std::printf("not the same creases: %s\n", why.c_str());
    return 1;
  }

  // Agreement first, in its own process (its memory is not the timed runs').
  const Run agree = run_in_child([&] {
    const std::string why =
        vgc::compare_subdivision_by_parent(vgc::subdivide_catmull_clark(mesh, levels), vgc::osd_refine_uniform(in), 1e-9, true);
    if (!why.empty()) std::printf("the reference and OpenSubdiv disagree: %s\n", why.c_str());
    return why.empty();
  });
  if (!agree.ok) {
    std::printf("not timed: the two sides must agree before their times mean anything\n");
    return 1;
  }
  std::printf("agree at every level 0..%d (counts, positions within 1e-9, sharpness, by parent)\n", levels);

  std::vector<Run> ref_runs, osd_runs, idle_runs;
  for (int r = 0; r < repeats; ++r) {
    idle_runs.push_back(run_in_child([] { return true; }));
    ref_runs.push_back(run_in_child([&] { return !vgc::subdivide_catmull_clark(mesh, levels).empty(); }));
    osd_runs.push_back(run_in_child([&] { return vgc::osd_refine_uniform(in).ok; }));
    if (!ref_runs.back().ok || !osd_runs.back().ok) {
      std::printf("a timed run failed (reference %s, OpenSubdiv %s)\n", ref_runs.back().ok ? "ok" : "failed",
                  osd_runs.back().ok ? "ok" : "failed");
      return 1;
    }
  }
  const std::size_t faces = static_cast<std::size_t>(mesh.face_count()) << (2 * levels);
  std::vector<long> idle_kb;
  for (const Run& r : idle_runs) idle_kb.push_back(r.max_rss_kb);
  const long baseline = median(idle_kb);
  const Summary ref = summarize(ref_runs, baseline), osd = summarize(osd_runs, baseline);
  std::printf("%-11s %9s %9s %12s   (%zu faces at level %d)\n", "side", "wall s", "CPU s", "peak MB", faces, levels);
  std::printf("%-11s %9.3f %9.3f %12.0f\n", "reference", ref.wall, ref.cpu, ref.mb);
  std::printf("%-11s %9.3f %9.3f %12.0f\n", "OpenSubdiv", osd.wall, osd.cpu, osd.mb);
  std::printf("ratio reference/OpenSubdiv: wall %.2f, CPU %.2f, memory %.2f (peak above a forked process's %.0f MB)\n",
              ref.wall / osd.wall, ref.cpu / osd.cpu, ref.mb / osd.mb, static_cast<double>(baseline) / 1024.0);
  return 0;
}
