// bench_replay.cpp — how long checking a long command program takes: the
// same comparison `vgc replay` makes (replay_program, runner.h), with the
// reference in process and with `vgc serve` behind exec: (issue 21: the cost
// of checking must grow with the program, not with its square).
//
// Spec: none of its own; it times the check of every command of 000 2.6
// that a fan or a grid of polygons sends.
//
// Run: build/bench/bench_replay [--vgc PATH] [--routes reference,exec]
//      [--shape fan|grid] [--repeats 3] SIZE...
// SIZE is a number of commands (e.g. 4000 16000 100000). For each size and
// route it prints the median of the repeats and every run, in seconds, and
// whether the program was found to agree (it must: the reference checks
// itself). --vgc defaults to the vgc next to this build (../cli/vgc).
#include "bench_args.h"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "command_text.h"
#include "implementation.h"
#include "program_text.h"
#include "route.h"
#include "runner.h"

namespace {

using Clock = std::chrono::steady_clock;

// A fan of triangles around vertex 0 (fan) or a strip-wise grid of quads
// (grid), cut at `size` commands: vertices first where a polygon needs them.
std::string program_text(const std::string& shape, std::size_t size) {
  std::string text;
  std::size_t n = 0;
  auto add = [&](const std::string& line) {
    if (n < size) text += line + "\n", ++n;
  };
  if (shape == "grid") {
    const std::size_t w = 100;  // vertices per row
    for (std::size_t j = 0; n < size; ++j) {
      for (std::size_t i = 0; i < w; ++i)
        add("vertex_set_xyz_real64 0 " + std::to_string(j * w + i) + " " + std::to_string(i) + " " +
            std::to_string(j) + " 0");
      if (j == 0) continue;
      for (std::size_t i = 0; i + 1 < w; ++i) {
        const std::size_t a = (j - 1) * w + i;
        add("polygon_set_corner_uint32 1 " + std::to_string((j - 1) * w + i) + " " + std::to_string(a) + " " +
            std::to_string(a + w) + " " + std::to_string(a + w + 1) + " " + std::to_string(a + 1));
      }
    }
    return text;
  }
  add("vertex_set_xyz_real64 0 0 0 0 0");
  add("vertex_set_xyz_real64 0 1 1 0 0");
  for (std::size_t t = 0; n < size; ++t) {
    const double a = 0.001 * static_cast<double>(t + 1);
    add("vertex_set_xyz_real64 0 " + std::to_string(t + 2) + " " + std::to_string(1.0 - a) + " " +
        std::to_string(a) + " 0");
    add("polygon_set_corner_uint32 1 " + std::to_string(t) + " 0 " + std::to_string(t + 1) + " " +
        std::to_string(t + 2) + " 4294967295");
  }
  return text;
}

std::string default_vgc(const char* argv0) {
  std::string self = argv0;
  const auto slash = self.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : self.substr(0, slash);
  return dir + "/../cli/vgc";
}

}  // namespace

int main(int argc, char** argv) {
  std::string vgc = default_vgc(argv[0]);
  std::string routes = "reference,exec";
  std::string shape = "fan";
  int repeats = 3;
  std::vector<std::size_t> sizes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--vgc" && has_value) vgc = argv[++i];
    else if (a == "--routes" && has_value) routes = argv[++i];
    else if (a == "--shape" && has_value) shape = argv[++i];
    else if (a == "--repeats" && has_value) repeats = static_cast<int>(vgc::bench::count_argument("bench_replay", "--repeats", argv[++i], 1, 1000));
    else if (!a.empty() && a[0] != '-') sizes.push_back(static_cast<std::size_t>(vgc::bench::count_argument("bench_replay", "SIZE", a, 1, 100000000)));
    else {
      std::fprintf(stderr, "usage: bench_replay [--vgc PATH] [--routes reference,exec] [--shape fan|grid] "
                           "[--repeats N] SIZE...\n");
      return 2;
    }
  }
  if (sizes.empty()) sizes = {4000, 16000, 100000};
  std::printf("%-9s %-10s %8s %10s  %s\n", "shape", "route", "commands", "median_s", "runs");
  for (std::size_t size : sizes) {
    vgc::Program program;
    vgc::TextError error;
    if (!vgc::parse_program(program_text(shape, size), &program, &error)) {
      std::fprintf(stderr, "bench_replay: generated program does not parse: %s\n", error.message.c_str());
      return 2;
    }
    for (const std::string& route : {std::string("reference"), std::string("exec")}) {
      if (routes.find(route) == std::string::npos) continue;
      const std::string spec =
          route == "reference" ? vgc::route_spec(vgc::RouteKind::Reference, "")
                               : vgc::route_spec(vgc::RouteKind::Exec, vgc + " serve");
      std::vector<double> runs;
      bool agreed = true;
      for (int r = 0; r < repeats; ++r) {
        vgc::OpenOptions options;
        options.timeout_seconds = 60;
        std::string open_error;
        auto sut = vgc::open_implementation(spec, options, &open_error);
        if (!sut) {
          std::fprintf(stderr, "bench_replay: cannot open %s: %s\n", spec.c_str(), open_error.c_str());
          return 2;
        }
        const auto start = Clock::now();
        const vgc::ReplayResult result = vgc::replay_program(program, *sut);
        runs.push_back(std::chrono::duration<double>(Clock::now() - start).count());
        agreed = agreed && !result.failure;
      }
      std::vector<double> sorted = runs;
      std::sort(sorted.begin(), sorted.end());
      std::string all;
      for (double s : runs) all += (all.empty() ? "" : " ") + std::to_string(s);
      std::printf("%-9s %-10s %8zu %10.3f  %s%s\n", shape.c_str(), route.c_str(), program.commands.size(),
                  sorted[sorted.size() / 2], all.c_str(), agreed ? "" : "  (DISAGREED: a bug in the check)");
      std::fflush(stdout);
    }
  }
  return 0;
}
