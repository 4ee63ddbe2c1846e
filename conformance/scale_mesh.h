// scale_mesh.h — the cases of the property at scale: meshes of 10^4 to 10^5
// elements, built and edited command by command.
//
// Spec: 000 section 2.6 (2.6.1 vertices, polygons and the layers that grow
// with them; 2.6.2 creases) and the README's id widths (vertex and polygon
// ids are uint32: any id up to 0xFFFFFFFE).
//
// Rationale (issue 21 item 2): every other property's cases hold a handful
// of elements, and some deviations only exist at size: the r6 host drops
// every vertex and polygon id past its storage bound (4,129 on a fresh
// node), which no small case shows except by a lucky id. A scale case draws
// a shape (a grid of quads, a torus, a fan of triangles, a grid of
// triangles), a size between 10^4 and 10^5 elements (vertices plus
// polygons; drawn between 4*10^4 and 6*10^4, shrunk towards 10^4), whether the ids are dense from 0 or spread over the whole id
// range (a bijection of the indexes onto 0 .. 0xFFFFFFFE), and a seed for
// the edits interleaved with the building: vertices moved and deleted,
// polygons re-defined and deleted, a crease layer of each stack written and
// named in the crease settings, a real layer written. Everything is a plain
// command, judged by the same comparison as every other step.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "command.h"

namespace vgc {

enum class ScaleShape { Grid, Torus, Fan, Triangles };
inline constexpr int kScaleShapes = 4;
inline constexpr int kScaleMinElements = 10000;
inline constexpr int kScaleMaxElements = 100000;
// A case draws its size from this band, and shrinks towards
// kScaleMinElements: every case then costs about the same (within 1.5x),
// so that `--shard` can split the property's cases over the shards evenly
// (shard_plan.cpp assign_shards); a size drawn anywhere from 10^4 to 10^5 made
// one shard's single case ten times another's.
inline constexpr int kScaleDrawLow = 40000;
inline constexpr int kScaleDrawHigh = 60000;

struct ScaleCase {
  ScaleShape shape = ScaleShape::Grid;
  int elements = kScaleMinElements;  // vertices plus polygons, about
  bool spread_ids = false;
  std::uint64_t seed = 0;  // the edits
};

// "torus of 24,200 elements, ids spread over the id range, edits seed 7".
std::string describe(const ScaleCase& c);

// The case's commands: deterministic in `c` (the same on every platform).
std::vector<Command> scale_case_commands(const ScaleCase& c);

}  // namespace vgc
