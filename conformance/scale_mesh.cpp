// scale_mesh.cpp — see scale_mesh.h.
#include "scale_mesh.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace vgc {
namespace {

// i -> (i * K + offset) mod (2^32 - 1) is a bijection of 0 .. 2^32 - 2 when
// K is coprime to 2^32 - 1 = 3 * 5 * 17 * 257 * 65537 (K prime and none of
// them): ids spread over the whole range, never 0xFFFFFFFF ("pick an id").
std::uint32_t spread(std::uint64_t i, std::uint64_t k, std::uint64_t offset) {
  return static_cast<std::uint32_t>((i * k + offset) % 0xFFFFFFFFull);
}

class Builder {
 public:
  explicit Builder(const ScaleCase& c) : c_(c), rng_(c.seed) {}

  std::uint32_t vid(std::uint32_t i) const { return c_.spread_ids ? spread(i, 2654435761ull, 977) : i; }
  std::uint32_t pid(std::uint32_t j) const { return c_.spread_ids ? spread(j, 40503ull * 65521ull, 31337) : j; }

  void vertex(std::uint32_t i, double x, double y, double z) {
    emit(cmd::VertexSetXyzReal64{0, vid(i), x, y, z});
    vertices_ = std::max(vertices_, i + 1);
  }
  void polygon(std::array<std::uint32_t, 4> corners) {
    for (auto& v : corners)
      if (v != kNone32) v = vid(v);
    polygons_.push_back(corners);
    emit(cmd::PolygonSetCornerUint32{1, pid(static_cast<std::uint32_t>(polygons_.size() - 1)), corners});
  }
  std::vector<Command> take() { return std::move(out_); }

 private:
  void emit(Command c) {
    out_.push_back(std::move(c));
    if (++since_edit_ >= kEditEvery && vertices_ > 0 && !polygons_.empty()) {
      since_edit_ = 0;
      edit();
    }
  }
  std::uint64_t draw(std::uint64_t n) { return rng_() % n; }  // mt19937_64 is the same everywhere
  std::uint32_t some_vertex() { return vid(static_cast<std::uint32_t>(draw(vertices_))); }
  std::uint32_t some_polygon_index() { return static_cast<std::uint32_t>(draw(polygons_.size())); }

  // One edit among those a modeller makes on a big mesh. Any edit is a
  // plain command: the reference decides whether it applies (a deleted
  // vertex moved is created again, a polygon on a deleted vertex is
  // rejected), and the implementation must agree.
  void edit() {
    switch (draw(8)) {
      case 0:  // move a vertex
        out_.push_back(cmd::VertexSetXyzReal64{0, some_vertex(), double(draw(1000)) / 8, double(draw(1000)) / 8,
                                               double(draw(64)) - 32});
        break;
      case 1:  // delete a polygon
        out_.push_back(cmd::PolygonDelete{pid(some_polygon_index())});
        break;
      case 2: {  // re-define a polygon: its corners rotated
        const std::uint32_t j = some_polygon_index();
        auto v = polygons_[j];
        if (v[3] == kNone32) std::rotate(v.begin(), v.begin() + 1, v.begin() + 3);
        else std::rotate(v.begin(), v.begin() + 1, v.end());
        out_.push_back(cmd::PolygonSetCornerUint32{1, pid(j), v});
        break;
      }
      case 3:  // a vertex crease layer, named, and written
        if (!vertex_creases_) {
          out_.push_back(cmd::LayerCreate{2, "sharp", static_cast<std::uint8_t>(LayerType::VertexUint32), 0, 0});
          out_.push_back(cmd::CreaseSetVertex{"sharp", 0});
          vertex_creases_ = true;
        }
        out_.push_back(cmd::VertexSetUint32{2, some_vertex(), static_cast<std::uint32_t>(rng_())});
        break;
      case 4:  // an edge crease layer, named, and written
        if (!edge_creases_) {
          out_.push_back(
              cmd::LayerCreate{3, "edges", static_cast<std::uint8_t>(LayerType::PolygonCornerUint32), 0, 0});
          out_.push_back(cmd::CreaseSetEdge{"edges", 0});
          edge_creases_ = true;
        }
        out_.push_back(cmd::PolygonSetCornerUint32{
            3, pid(some_polygon_index()),
            {static_cast<std::uint32_t>(rng_()), 0, 0xFFFFFFFFu, static_cast<std::uint32_t>(draw(4))}});
        break;
      case 5:  // delete a vertex, and its polygons with it (a few per case: the cascade reads every polygon)
        if (vertex_deletes_ < kMaxVertexDeletes) {
          ++vertex_deletes_;
          out_.push_back(cmd::VertexDelete{some_vertex()});
        }
        break;
      case 6:  // a real layer, written
        if (!weights_) {
          out_.push_back(cmd::LayerCreate{4, "weight", static_cast<std::uint8_t>(LayerType::VertexReal), 0, 0.5});
          weights_ = true;
        }
        out_.push_back(cmd::VertexSetReal64{4, some_vertex(), double(draw(1u << 20)) / 1024});
        break;
      default:  // a new vertex far up the id range, and a triangle on it
        if (far_++ < kMaxFar) {
          const std::uint32_t far = 0xFFFFFFFEu - static_cast<std::uint32_t>(draw(1u << 30));
          out_.push_back(cmd::VertexSetXyzReal64{0, far, 0.5, 0.5, 1});
          out_.push_back(cmd::PolygonSetCornerUint32{1, 0xFFFFFFFEu - static_cast<std::uint32_t>(draw(1u << 30)),
                                                     {far, some_vertex(), some_vertex(), kNone32}});
        }
        break;
    }
  }

  static constexpr int kEditEvery = 400;
  static constexpr int kMaxVertexDeletes = 12;
  static constexpr int kMaxFar = 12;
  ScaleCase c_;
  std::mt19937_64 rng_;
  std::vector<Command> out_;
  std::vector<std::array<std::uint32_t, 4>> polygons_;  // by index, corners as sent
  std::uint32_t vertices_ = 0;  // vertex indexes 0 .. vertices_ - 1 sent so far
  int since_edit_ = 0, vertex_deletes_ = 0, far_ = 0;
  bool vertex_creases_ = false, edge_creases_ = false, weights_ = false;
};

// A w x h grid of vertices, row by row, with the quads (or two triangles
// each) of a row as soon as its upper row exists; wrapped into a torus.
void grid(Builder& b, std::uint32_t w, std::uint32_t h, ScaleShape shape) {
  const bool torus = shape == ScaleShape::Torus;
  const double pi = 3.14159265358979323846;
  auto at = [w](std::uint32_t i, std::uint32_t j) { return j * w + i; };
  auto row_polygons = [&](std::uint32_t j0, std::uint32_t j1) {
    const std::uint32_t columns = torus ? w : w - 1;
    for (std::uint32_t i = 0; i < columns; ++i) {
      const std::uint32_t i1 = (i + 1) % w;
      const std::uint32_t a = at(i, j0), bb = at(i, j1), c = at(i1, j1), d = at(i1, j0);
      if (shape == ScaleShape::Triangles) {
        b.polygon({a, bb, c, kNone32});
        b.polygon({a, c, d, kNone32});
      } else {
        b.polygon({a, bb, c, d});
      }
    }
  };
  for (std::uint32_t j = 0; j < h; ++j) {
    for (std::uint32_t i = 0; i < w; ++i) {
      if (torus) {
        const double u = 2 * pi * i / w, v = 2 * pi * j / h;
        b.vertex(at(i, j), (3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v));
      } else {
        b.vertex(at(i, j), i, j, double((i * 7 + j * 3) % 5) / 4);
      }
    }
    if (j > 0) row_polygons(j - 1, j);
  }
  if (torus) row_polygons(h - 1, 0);
}

}  // namespace

std::string describe(const ScaleCase& c) {
  static const char* names[] = {"grid of quads", "torus", "fan of triangles", "grid of triangles"};
  return std::string(names[static_cast<int>(c.shape)]) + " of about " + std::to_string(c.elements) +
         " elements, ids " + (c.spread_ids ? "spread over the whole id range" : "dense from 0") + ", edits seed " +
         std::to_string(c.seed);
}

std::vector<Command> scale_case_commands(const ScaleCase& c) {
  Builder b(c);
  const auto n = static_cast<std::uint32_t>(std::clamp(c.elements, 16, 1 << 24));
  switch (c.shape) {
    case ScaleShape::Fan: {
      const std::uint32_t triangles = n / 2;
      b.vertex(0, 0, 0, 0);
      b.vertex(1, 1, 0, 0);
      for (std::uint32_t t = 0; t < triangles; ++t) {
        const double a = 6.283185307179586 * (t + 1) / (triangles + 1);
        b.vertex(t + 2, std::cos(a), std::sin(a), 0);
        b.polygon({0, t + 1, t + 2, kNone32});
      }
      break;
    }
    case ScaleShape::Triangles: {  // 3 elements per vertex: w*h vertices, 2(w-1)(h-1) triangles
      const auto w = static_cast<std::uint32_t>(std::max(3.0, std::sqrt(n / 3.0)));
      grid(b, w, w, c.shape);
      break;
    }
    default: {  // 2 elements per vertex
      const auto w = static_cast<std::uint32_t>(std::max(3.0, std::sqrt(n / 2.0)));
      grid(b, w, w, c.shape);
      break;
    }
  }
  return b.take();
}

}  // namespace vgc
