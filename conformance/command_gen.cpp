// command_gen.cpp — see command_gen.h.
#include "command_gen.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>

#include "crease.h"                 // corner_count
#include "gen/arbitrary_command.h"  // gen_quaternion_extreme
#include "gen/magnitude.h"

namespace vgc {
namespace {

using rc::Gen;
namespace gen = rc::gen;

// A uniform integer in [lo, hi), whatever the RapidCheck size. gen::inRange
// scales its range by the size (at size 0 it always gives lo, and certify's
// sizes stay at or below 50 of the nominal 100), so a choice made with it
// at a small size never reaches its upper alternatives: five of the eleven
// value writes were never sent. Every choice here is made with this; it
// still shrinks toward lo.
template <class T> Gen<T> uniform(T lo, T hi) { return gen::resize(rc::kNominalSize, gen::inRange<T>(lo, hi)); }

// An unsigned field of T drawn from its magnitude classes (gen/magnitude.h):
// the class uniformly, then a value in it. Shrinks toward class "0".
template <class T> Gen<T> magnitude() {
  constexpr int bits = static_cast<int>(sizeof(T) * 8);
  const std::size_t classes = ::vgc::gen::magnitude_classes(bits).size();
  return gen::exec([classes] {
    const std::size_t k = *uniform<std::size_t>(0, classes);
    return static_cast<T>(::vgc::gen::magnitude_value(bits, k, *uniform<std::uint64_t>(0, 16)));
  });
}

// A 32-bit value: anything, or (2 in 3) one of the magnitude classes.
Gen<std::uint32_t> u32_value() {
  return gen::weightedOneOf<std::uint32_t>({{1, gen::arbitrary<std::uint32_t>()}, {2, magnitude<std::uint32_t>()}});
}

// What the generators need to know of the model, copied out of it.
struct View {
  std::vector<std::uint32_t> vertices, polygons;
  std::vector<std::vector<std::uint32_t>> polygon_corners;  // per live polygon (polygons order)
  std::vector<std::uint16_t> layers;  // non-base layer ids
  std::vector<std::string> names;     // all layer names
  std::vector<std::uint16_t> vertex_uint_layers, vertex_real_layers, vertex_xyz_layers;
  std::vector<std::uint16_t> corner_uint_layers, corner_real_layers, face_u8_layers, face_u32_layers,
      face_real_layers;
  std::vector<std::string> vertex_uint_names, vertex_real_names, corner_uint_names, face_uint_names;
  std::vector<std::uint16_t> bones;
  std::string vertex_crease_layer, edge_crease_layer;  // the crease settings' names ("" for a constant)
  // Live vertices and polygons with a value other than its layer's default
  // in a layer of another type than the base layers' (not VERTEX_XYZ:
  // a new vertex's position is written there anyway), sorted: what a
  // delete, and the element made again at its id, must not keep
  // (delete_written).
  std::vector<std::uint32_t> written_vertices, written_polygons;
  // VERTEX_REAL and POLYGON_FACE_REAL layers whose default is 0 or -0,
  // each with whether it is -0 (signed_zero_write).
  std::vector<std::pair<std::uint16_t, bool>> zero_default_vertex_reals, zero_default_face_reals;
  // Whether a POLYGON_FACE_UINT8 layer has a default above 255 (grown_uint8_layer).
  bool wide_u8_default = false;
};

// Whether `s` holds other values than a new slot of `layer` (bit for bit).
bool off_default(const Layer& layer, const Slot& s) {
  const Slot d = default_slot(layer);
  return s.u != d.u || std::memcmp(s.r.data(), d.r.data(), sizeof s.r) != 0;
}

View view_of(const Node& m) {
  View v;
  v.vertices.reserve(m.vertices().size());
  v.polygons.reserve(m.polygons().size());
  v.polygon_corners.reserve(m.polygons().size());
  v.names.reserve(m.layers().size());
  for (const auto& [id, s] : m.vertices()) v.vertices.push_back(id);
  for (const auto& [id, s] : m.polygons()) {
    v.polygons.push_back(id);
    v.polygon_corners.emplace_back(s.u.begin(), s.u.begin() + corner_count(s));
  }
  for (const auto& [id, l] : m.layers()) {
    v.names.push_back(l.name);
    if (id < 2) continue;
    v.layers.push_back(id);
    switch (l.type) {
      case LayerType::VertexXyz: v.vertex_xyz_layers.push_back(id); break;
      case LayerType::VertexUint32:
        v.vertex_uint_layers.push_back(id);
        v.vertex_uint_names.push_back(l.name);
        break;
      case LayerType::VertexReal:
        v.vertex_real_layers.push_back(id);
        v.vertex_real_names.push_back(l.name);
        break;
      case LayerType::PolygonCornerUint32:
        v.corner_uint_layers.push_back(id);
        v.corner_uint_names.push_back(l.name);
        break;
      case LayerType::PolygonCornerReal: v.corner_real_layers.push_back(id); break;
      case LayerType::PolygonFaceUint8:
        v.face_u8_layers.push_back(id);
        v.wide_u8_default = v.wide_u8_default || l.def_uint > 255;
        break;
      case LayerType::PolygonFaceUint32:
        v.face_u32_layers.push_back(id);
        v.face_uint_names.push_back(l.name);
        break;
      case LayerType::PolygonFaceReal: v.face_real_layers.push_back(id); break;
    }
  }
  for (const auto& [id, b] : m.bones()) v.bones.push_back(id);
  for (const auto& [id, l] : m.layers()) {
    if (id >= 2 && l.def_real == 0.0 && l.type == LayerType::VertexReal)
      v.zero_default_vertex_reals.emplace_back(id, std::signbit(l.def_real));
    if (id >= 2 && l.def_real == 0.0 && l.type == LayerType::PolygonFaceReal)
      v.zero_default_face_reals.emplace_back(id, std::signbit(l.def_real));
    if (id < 2 || l.type == LayerType::VertexXyz) continue;
    auto& written = is_vertex_layer_type(l.type) ? v.written_vertices : v.written_polygons;
    for (const auto& [element, slot] : l.slots)
      if (off_default(l, slot)) written.push_back(element);
  }
  for (auto* w : {&v.written_vertices, &v.written_polygons}) {
    std::sort(w->begin(), w->end());
    w->erase(std::unique(w->begin(), w->end()), w->end());
  }
  v.vertex_crease_layer = m.vertex_crease().layer;
  v.edge_crease_layer = m.edge_crease().layer;
  return v;
}

// Mostly one of `live`, else one of `others`.
template <class T> Gen<T> pick(const std::vector<T>& live, Gen<T> others) {
  if (live.empty()) return others;
  return gen::weightedOneOf<T>({{4, gen::elementOf(live)}, {1, others}});
}

// The ids of `live` (sorted) that are most likely dead: the gaps among the
// small ids (below 64, up to 8 of them), else the lowest free id.
// Generators create at the lowest free id, so a small gap is almost always
// an element deleted earlier in the case (by a delete, an alias, or a
// vertex's polygons with it); with no gap, a deleted element is most often
// the lowest free id. A write there is where an implementation that keeps
// a deleted element's slots shows it.
std::vector<std::uint32_t> dead_ids(const std::vector<std::uint32_t>& live) {
  std::vector<std::uint32_t> dead;
  std::uint32_t expect = 0;
  for (std::uint32_t id : live) {
    if (id >= 64) break;
    for (; expect < id && dead.size() < 8; ++expect) dead.push_back(expect);
    expect = id + 1;
  }
  if (!dead.empty()) return dead;
  std::uint32_t next = 0;
  for (std::uint32_t id : live)
    if (id == next) ++next;
  return {next};
}

// Whether `live` has a small gap: almost surely an element deleted earlier
// in the case (dead_ids).
bool has_gap(const std::vector<std::uint32_t>& live) {
  std::uint32_t expect = 0;
  for (std::uint32_t id : live) {
    if (id >= 64) break;
    if (id != expect) return true;
    expect = id + 1;
  }
  return false;
}

// An element id: often the lowest free one (so meshes grow), often a live
// one (so they change), sometimes a small dead one, "pick one", or any of
// the magnitude classes (gen/magnitude.h: 2^8 .. 2^31 and their neighbours,
// where a node's storage bound is).
Gen<std::uint32_t> element_id(const std::vector<std::uint32_t>& live) {
  std::uint32_t next = 0;
  for (std::uint32_t id : live)
    if (id == next) ++next;
  const auto others = gen::weightedOneOf<std::uint32_t>({
      {5, uniform<std::uint32_t>(0, 10)},
      {4, gen::just(std::uint32_t(kNone32))},  // pick a free id (vertex/polygon.create.pick_id)
      {8, magnitude<std::uint32_t>()},
  });
  if (live.empty()) return gen::weightedOneOf<std::uint32_t>({{3, gen::just(next)}, {1, others}});
  return gen::weightedOneOf<std::uint32_t>({{3, gen::just(next)}, {4, gen::elementOf(live)}, {1, others}});
}

// A live element id mostly, for writes and deletes; else a small one, "pick
// one", or an id of any magnitude. (Writes aimed at deleted elements are
// write_dead's.)
Gen<std::uint32_t> live_id(const std::vector<std::uint32_t>& live) {
  return pick<std::uint32_t>(live, gen::weightedOneOf<std::uint32_t>({
                                       {8, uniform<std::uint32_t>(0, 10)},
                                       {1, gen::just(std::uint32_t(kNone32))},
                                       {3, magnitude<std::uint32_t>()},
                                   }));
}

Gen<std::uint16_t> layer_id(const View& v) {
  return pick<std::uint16_t>(v.layers, gen::weightedOneOf<std::uint16_t>({
                                           {8, uniform<std::uint16_t>(2, 7)},
                                           {1, gen::elementOf(std::vector<std::uint16_t>{0, 1})},
                                           {1, gen::just(std::uint16_t(kNone16))},
                                           {2, magnitude<std::uint16_t>()},
                                       }));
}

Gen<std::uint16_t> typed_layer(const std::vector<std::uint16_t>& right, const View& v) {
  return pick<std::uint16_t>(right, layer_id(v));
}

Gen<std::string> layer_name(const View& v) {
  return gen::weightedOneOf<std::string>({
      {6, gen::elementOf(std::vector<std::string>{"uv", "crease", "weight", "ref", "edges", "fifteen_bytes_x"})},
      {3, v.names.empty() ? gen::just(std::string("vertex")) : gen::elementOf(v.names)},
      {1, gen::elementOf(std::vector<std::string>{"sixteen_bytes_xx", std::string("nul\0in", 6), "vertex", "polygon"})},
  });
}

Gen<std::uint8_t> layer_type() {
  return gen::weightedOneOf<std::uint8_t>({
      {12, gen::elementOf(std::vector<std::uint8_t>{0, 1, 2, 128, 129, 130, 131, 132})},
      {1, gen::elementOf(std::vector<std::uint8_t>{3, 127, 133, 255})},
  });
}

double from_bits(std::uint64_t bits) {
  double d;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}

// Reals for data layers: ordinary values and every special the encoding
// must keep: -0, infinities, NaNs with payloads, subnormals, float edges;
// DBL_MAX and FLT_MAX, a value on a REAL layer, the vertex-delete alias in
// a vertex_set_xyz on any layer.
Gen<double> any_real() {
  return gen::weightedOneOf<double>({
      {6, gen::map(uniform<int>(-800, 800), [](int i) { return i / 8.0; })},
      {2, gen::elementOf(std::vector<double>{-0.0, 0.1, 1e300, -1e-310, std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(), double(FLT_MAX) * 2, 16777217.0,
                               1.0000000000000002, DBL_MAX, double(FLT_MAX)})},
      {1, gen::map(uniform<std::uint64_t>(1, (1ull << 51) - 1),
                   [](std::uint64_t p) { return from_bits(0x7FF0000000000000ull | p); })},
      {1, gen::map(uniform<std::uint64_t>(1, (1ull << 51) - 1),
                   [](std::uint64_t p) { return from_bits(0xFFF8000000000000ull | p); })},
  });
}

Gen<float> any_float() {
  return gen::weightedOneOf<float>({
      {6, gen::map(uniform<int>(-800, 800), [](int i) { return i / 8.0f; })},
      {2, gen::elementOf(std::vector<float>{-0.0f, 0.1f, 1e-40f, std::numeric_limits<float>::infinity(), 16777217.0f,
                                            FLT_MAX})},
      {1, gen::map(uniform<std::uint32_t>(1, (1u << 22) - 1), [](std::uint32_t p) {
         const std::uint32_t bits = 0x7F800000u | p;
         float f;
         std::memcpy(&f, &bits, sizeof f);
         return f;
       })},
  });
}

// Coordinates for the base layer: mostly small and finite, sometimes not.
Gen<double> coordinate() {
  return gen::weightedOneOf<double>({
      {20, gen::map(uniform<int>(-16, 17), [](int i) { return i / 4.0; })},
      {1, gen::elementOf(std::vector<double>{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                               -0.0, 1e300})},
  });
}

Gen<std::uint32_t> crease_value() {
  return gen::weightedOneOf<std::uint32_t>({
      {3, gen::elementOf(std::vector<std::uint32_t>{0u, 0xFFFFFFFFu})},
      {2, u32_value()},
  });
}

Gen<Command> create_layer(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)] {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    cmd::LayerCreate c;
    c.layer_id = *layer_id(v);
    c.name = *layer_name(v);
    c.type = *layer_type();
    c.def_uint = *gen::weightedOneOf<std::uint32_t>(
        {{3, gen::elementOf(std::vector<std::uint32_t>{0u, 7u, 300u, 0xFFFFFFFFu})}, {2, u32_value()}});
    c.def_real = *gen::weightedOneOf<double>({{3, gen::elementOf(std::vector<double>{0.0, 0.5, -2.0})}, {1, any_real()}});
    return Command{c};
  });
}

Gen<Command> destroy_layer(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)] {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    if (*uniform(0, 4) == 0) return Command{cmd::LayerCreate{*layer_id(v), "", 0, 0, 0.0}};  // wire alias
    // The base layers, which no destroy may remove (layer.destroy.base_id).
    if (*uniform(0, 7) == 0) return Command{cmd::LayerDestroy{*uniform<std::uint16_t>(0, 1)}};
    return Command{cmd::LayerDestroy{*layer_id(v)}};
  });
}

Gen<Command> subscribe(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)] {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    if (*uniform(0, 2) == 0) return Command{cmd::LayerUnsubscribe{*layer_id(v)}};
    // A format above REAL64 is the wire's unsubscribe (alias.layer_subscribe.format).
    return Command{cmd::LayerSubscribe{
        *layer_id(v), *gen::weightedElement<std::uint8_t>({{5, 0}, {5, 1}, {3, 2}, {1, 255}})}};
  });
}

Gen<Command> set_vertex(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)] {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    const std::uint32_t id = *element_id(v.vertices);
    if (*uniform(0, 3) == 0)
      return Command{cmd::VertexSetXyzReal32{0, id, static_cast<float>(*coordinate()),
                                             static_cast<float>(*coordinate()), static_cast<float>(*coordinate())}};
    return Command{cmd::VertexSetXyzReal64{0, id, *coordinate(), *coordinate(), *coordinate()}};
  });
}

// The layer a vertex-delete alias names. The alias is a condition on the
// command's coordinates, whatever layer it names (VERTEX-DELETE-1: the same
// bytes as the delete on the wire): layer 0 mostly, else another VERTEX_XYZ
// layer, a layer of another type (the polygon layer among them), or a layer
// that does not exist. Before, it was only ever sent on layer 0.
Gen<std::uint16_t> alias_layer(const View& v) {
  std::vector<std::uint16_t> other_types{Node::kPolygonLayer};
  for (std::uint16_t id : v.layers)
    if (std::find(v.vertex_xyz_layers.begin(), v.vertex_xyz_layers.end(), id) == v.vertex_xyz_layers.end())
      other_types.push_back(id);
  std::uint16_t missing = 2;
  while (std::find(v.layers.begin(), v.layers.end(), missing) != v.layers.end()) ++missing;
  return gen::weightedOneOf<std::uint16_t>({
      {3, gen::just(std::uint16_t(Node::kVertexLayer))},
      {v.vertex_xyz_layers.empty() ? 0u : 4u,
       v.vertex_xyz_layers.empty() ? gen::just(std::uint16_t(0)) : gen::elementOf(v.vertex_xyz_layers)},
      {2, gen::elementOf(other_types)},
      {1, gen::weightedOneOf<std::uint16_t>({{3, gen::just(missing)}, {1, magnitude<std::uint16_t>()}})},
  });
}

Gen<Command> delete_vertex(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)] {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    const std::uint32_t id = *live_id(v.vertices);
    switch (*uniform(0, 3)) {
      case 0: return Command{cmd::VertexDelete{id}};
      case 1: return Command{cmd::VertexSetXyzReal32{*alias_layer(v), id, 0.f, FLT_MAX, 0.f}};
      default: return Command{cmd::VertexSetXyzReal64{*alias_layer(v), id, DBL_MAX, 0.0, 0.0}};
    }
  });
}

// A polygon on layer 1. Mostly (8 in 10 once there are enough vertices) a
// valid one: three or four distinct live vertices, so that meshes are built
// and re-shaped; otherwise one near-miss: a corner repeated
// (POLY-DISTINCT-1), a corner naming no live vertex (POLY-VERTEX-REF-1), or
// 0xFFFFFFFF among the first three (POLY-CORNERS-1). A fourth corner is often
// vertex 0 (a quad, not the unused 0xFFFFFFFF: POLY-TRIANGLE-1).
Gen<Command> set_polygon(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)] {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    cmd::PolygonSetCornerUint32 c;
    c.layer_id = Node::kPolygonLayer;
    c.polygon_id = *element_id(v.polygons);
    // A quad when there are four vertices to make one of (3 in 5), a
    // triangle mostly when there are three.
    const bool quad = v.vertices.size() >= 4   ? *gen::weightedElement<int>({{3, 4}, {2, 3}}) == 4
                      : v.vertices.size() == 3 ? *uniform(0, 6) == 0
                                               : *gen::arbitrary<bool>();
    const std::size_t need = quad ? 4 : 3;
    const int miss = v.vertices.size() >= need
                         ? *gen::weightedElement<int>({{16, 0}, {2, 1}, {1, 2}, {1, 3}})
                         : *gen::weightedElement<int>({{1, 1}, {1, 2}, {1, 3}});
    // Distinct live corners, as many as there are (up to four).
    std::vector<std::uint32_t> pool = v.vertices;
    if (quad && v.vertices.size() >= 4 && v.vertices.front() == 0 && *uniform(0, 4) == 0) {
      pool.erase(pool.begin());  // vertex 0 goes last: a fourth corner of 0
      for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t k = *uniform<std::size_t>(0, pool.size());
        c.v[i] = pool[k];
        pool.erase(pool.begin() + static_cast<long>(k));
      }
      c.v[3] = 0;
    } else {
      for (std::size_t i = 0; i < 4; ++i) {
        if (pool.empty()) {
          c.v[i] = *uniform<std::uint32_t>(0, 10);
          continue;
        }
        const std::size_t k = *uniform<std::size_t>(0, pool.size());
        c.v[i] = pool[k];
        pool.erase(pool.begin() + static_cast<long>(k));
      }
    }
    if (!quad) c.v[3] = kNone32;
    const std::size_t at = *uniform<std::size_t>(0, need);  // the corner a near-miss spoils
    switch (miss) {
      case 1: c.v[at] = c.v[(at + 1) % need]; break;  // a corner repeated
      case 2: {                                      // a corner naming no live vertex
        std::uint32_t dead = 0;
        while (std::find(v.vertices.begin(), v.vertices.end(), dead) != v.vertices.end()) ++dead;
        c.v[at] = *gen::weightedOneOf<std::uint32_t>(
            {{3, gen::just(dead)}, {1, gen::elementOf(std::vector<std::uint32_t>{4000000000u, 0xFFFFFFFEu})}});
        break;
      }
      case 3: c.v[*uniform<std::size_t>(1, 3)] = kNone32; break;  // fewer than three corners (v0 = 0xFFFFFFFF would be a delete)
      default: break;
    }
    return Command{c};
  });
}

// A new polygon (at the lowest free id) that makes the mesh one OpenSubdiv
// treats with its non-manifold rules, next to a live polygon P = [p0 ..]:
//  - pillow: P's corners reversed (two faces on the same vertices; from
//    triangles, Loop's centre children share their vertices);
//  - same-direction twin: P's corners rotated (each edge used twice the
//    same way);
//  - same-direction neighbour: [p0 p1 x ...] (P's edge p0->p1 the way P
//    uses it);
//  - fin: [p1 p0 x ...] (a third face once P's edge has a neighbour);
//  - bow-tie: [p0 x y ...] with x, y not in P (two fans at p0 unless they
//    join elsewhere).
// x, y are live vertices not in P; a triangle mostly (Loop judges only
// all-triangle meshes), sometimes a quad. Where P has too few outside
// vertices for the shape, an ordinary polygon.
Gen<Command> non_manifold_polygon(const View& v) {
  if (v.polygons.empty()) return set_polygon(v);
  return gen::exec([pv = std::make_shared<const View>(v)]() -> Command {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    std::uint32_t next = 0;
    for (std::uint32_t id : v.polygons)
      if (id == next) ++next;
    const auto& p = v.polygon_corners[*uniform<std::size_t>(0, v.polygons.size())];
    std::vector<std::uint32_t> outside;
    for (std::uint32_t x : v.vertices)
      if (std::find(p.begin(), p.end(), x) == p.end()) outside.push_back(x);
    const int kind = *uniform(0, 5);
    const bool quad = *uniform(0, 4) == 0;
    cmd::PolygonSetCornerUint32 c;
    c.layer_id = Node::kPolygonLayer;
    c.polygon_id = next;
    c.v = {kNone32, kNone32, kNone32, kNone32};
    std::vector<std::uint32_t> corners;
    auto take_outside = [&](std::size_t n) {
      for (std::size_t i = 0; i < n && !outside.empty(); ++i) {
        const std::size_t k = *uniform<std::size_t>(0, outside.size());
        corners.push_back(outside[k]);
        outside.erase(outside.begin() + static_cast<long>(k));
      }
    };
    const std::size_t n = p.size();
    const std::size_t at = *uniform<std::size_t>(0, n);
    switch (kind) {
      case 0: corners.assign(p.rbegin(), p.rend()); break;  // pillow
      case 1:                                                // same-direction twin
        for (std::size_t i = 0; i < n; ++i) corners.push_back(p[(at + 1 + i) % n]);
        break;
      case 2:  // same-direction neighbour
        corners = {p[at], p[(at + 1) % n]};
        take_outside(quad ? 2 : 1);
        break;
      case 3:  // fin (or an ordinary neighbour the first time)
        corners = {p[(at + 1) % n], p[at]};
        take_outside(quad ? 2 : 1);
        break;
      default:  // bow-tie
        corners = {p[at]};
        take_outside(quad ? 3 : 2);
        break;
    }
    if (corners.size() < 3) return *set_polygon(v);
    for (std::size_t i = 0; i < corners.size() && i < 4; ++i) c.v[i] = corners[i];
    return Command{c};
  });
}

Gen<Command> delete_polygon(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)] {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    const std::uint32_t id = *live_id(v.polygons);
    if (*uniform(0, 2) == 0) return Command{cmd::PolygonDelete{id}};
    return Command{cmd::PolygonSetCornerUint32{Node::kPolygonLayer, id, {kNone32, 0, 0, 0}}};
  });
}

// A write of some value to some layer of some type (right type mostly).
// The value write of kind `kind` (0..10: vertex uint32, real64, real32,
// xyz; corner uint32, real64, real32; face uint8, uint32, real64, real32) to
// a layer of its type mostly.
Gen<Command> write_value_of(const View& v, Gen<int> kind, bool dead = false) {
  return gen::exec([pv = std::make_shared<const View>(v), kind, dead]() -> Command {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    const auto target = [dead](const std::vector<std::uint32_t>& live) {
      return dead ? *gen::elementOf(dead_ids(live)) : *live_id(live);
    };
    switch (*kind) {
      case 0:
        return cmd::VertexSetUint32{*typed_layer(v.vertex_uint_layers, v), target(v.vertices),
                                    *u32_value()};
      case 1: return cmd::VertexSetReal64{*typed_layer(v.vertex_real_layers, v), target(v.vertices), *any_real()};
      case 2: return cmd::VertexSetReal32{*typed_layer(v.vertex_real_layers, v), target(v.vertices), *any_float()};
      case 3:
        return cmd::VertexSetXyzReal64{*typed_layer(v.vertex_xyz_layers, v), target(v.vertices), *any_real(),
                                       *any_real(), *any_real()};
      case 4: {
        cmd::PolygonSetCornerUint32 c{*typed_layer(v.corner_uint_layers, v), target(v.polygons), {}};
        for (auto& x : c.v) x = *crease_value();
        return c;
      }
      case 5: {
        cmd::PolygonSetCornerReal64 c{*typed_layer(v.corner_real_layers, v), target(v.polygons), {}};
        for (auto& x : c.v) x = *any_real();
        return c;
      }
      case 6: {
        cmd::PolygonSetCornerReal32 c{*typed_layer(v.corner_real_layers, v), target(v.polygons), {}};
        for (auto& x : c.v) x = *any_float();
        return c;
      }
      case 7:
        return cmd::PolygonSetFaceUint8{*typed_layer(v.face_u8_layers, v), target(v.polygons),
                                        *gen::weightedOneOf<std::uint8_t>(
                                            {{1, gen::arbitrary<std::uint8_t>()}, {2, magnitude<std::uint8_t>()}})};
      case 8:
        return cmd::PolygonSetFaceUint32{*typed_layer(v.face_u32_layers, v), target(v.polygons),
                                         *u32_value()};
      case 9:
        return cmd::PolygonSetFaceReal64{*typed_layer(v.face_real_layers, v), target(v.polygons), *any_real()};
      default:
        return cmd::PolygonSetFaceReal32{*typed_layer(v.face_real_layers, v), target(v.polygons), *any_float()};
    }
  });
}

// A layer for values of one of `types`, at the lowest free id from 2, under
// a name no layer has, so that it is created.
Gen<Command> value_layer(const View& v, std::vector<std::uint8_t> types) {
  std::uint16_t id = 2;
  while (std::find(v.layers.begin(), v.layers.end(), id) != v.layers.end()) ++id;
  std::string name = "value" + std::to_string(id);
  while (std::find(v.names.begin(), v.names.end(), name) != v.names.end()) name += "x";
  return gen::exec([types, id, name]() -> Command {
    cmd::LayerCreate c;
    c.layer_id = id;
    c.name = name;
    c.type = *gen::elementOf(types);
    c.def_uint = *gen::elementOf(std::vector<std::uint32_t>{0u, 7u, 0xFFFFFFFFu});
    c.def_real = *gen::elementOf(std::vector<double>{0.0, 0.5, -2.0});
    return c;
  });
}

// The layers of the type value write kind `k` (write_value_of) needs, and that type.
std::pair<const std::vector<std::uint16_t>*, LayerType> layers_of_kind(const View& v, int k) {
  switch (k) {
    case 0: return {&v.vertex_uint_layers, LayerType::VertexUint32};
    case 1:
    case 2: return {&v.vertex_real_layers, LayerType::VertexReal};
    case 3: return {&v.vertex_xyz_layers, LayerType::VertexXyz};
    case 4: return {&v.corner_uint_layers, LayerType::PolygonCornerUint32};
    case 5:
    case 6: return {&v.corner_real_layers, LayerType::PolygonCornerReal};
    case 7: return {&v.face_u8_layers, LayerType::PolygonFaceUint8};
    case 8: return {&v.face_u32_layers, LayerType::PolygonFaceUint32};
    default: return {&v.face_real_layers, LayerType::PolygonFaceReal};
  }
}

// A layer for values of a type no layer has yet (any type once all eight exist).
Gen<Command> create_value_layer(const View& v) {
  std::vector<std::uint8_t> missing, all;
  for (int k : {0, 1, 3, 4, 5, 7, 8, 9}) {
    const auto [layers, type] = layers_of_kind(v, k);
    all.push_back(static_cast<std::uint8_t>(type));
    if (layers->empty()) missing.push_back(static_cast<std::uint8_t>(type));
  }
  return value_layer(v, missing.empty() ? all : missing);
}

Gen<Command> build_polygon(const View& v);
Gen<Command> grow_vertex(const View& v);

// One step toward a landing value write of a kind drawn uniformly: the
// write itself, or (3 times in 4 while it is missing) first the layer of its
// type, or first the vertices / polygon it writes to. Each of the eleven
// value writes thus gets an equal share of the steps.
Gen<Command> value_step(const View& v) {
  // Mostly a kind whose layer is there already (cases are short: a case
  // that has made a face_uint8 layer writes to it rather than make seven
  // more); the first layer a case makes is of a uniformly drawn kind, so
  // over many cases every kind gets its share.
  std::vector<int> ready;
  for (int k = 0; k < 11; ++k)
    if (!layers_of_kind(v, k).first->empty()) ready.push_back(k);
  const Gen<int> kind =
      ready.empty() ? uniform(0, 11) : gen::weightedOneOf<int>({{3, gen::elementOf(ready)}, {1, uniform(0, 11)}});
  return gen::exec([pv = std::make_shared<const View>(v), kind]() -> Command {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    const int k = *kind;
    const auto [layers, type] = layers_of_kind(v, k);
    if (layers->empty() && *uniform(0, 4) != 0) return *value_layer(v, {static_cast<std::uint8_t>(type)});
    const bool vertex_kind = k <= 3;
    if ((vertex_kind ? v.vertices.empty() : v.polygons.empty()) && *uniform(0, 4) != 0)
      return vertex_kind ? *grow_vertex(v) : *build_polygon(v);
    return *write_value_of(v, gen::just(k));
  });
}

// A value write of a kind whose layer exists, to a vertex or polygon that is
// most likely one deleted earlier in the case (dead_ids): where a node that
// keeps a deleted element's slots, or frees them only in some layers, shows
// it. Before, a face write to a deleted polygon happened 0 to 2 times in a
// default run.
// Face writes (kinds 7..10) weigh double.
Gen<Command> write_dead(const View& v) {
  std::vector<int> ready;
  for (int k = 0; k < 11; ++k)
    if (!layers_of_kind(v, k).first->empty())
      for (int copies = k >= 7 ? 2 : 1; copies > 0; --copies) ready.push_back(k);
  if (ready.empty()) return value_step(v);
  return write_value_of(v, gen::elementOf(ready), true);
}

// Whether signed_zero_write has a layer and an element to write.
bool signed_zero_ready(const View& v) {
  return (!v.zero_default_vertex_reals.empty() && !v.vertices.empty()) ||
         (!v.zero_default_face_reals.empty() && !v.polygons.empty());
}

// A write of the zero of the other sign than a layer's default 0 (or -0)
// to a live vertex or polygon of a VERTEX_REAL or POLYGON_FACE_REAL layer
// (signed_zero_ready): a value equal to the default as a number and not
// bit for bit. A host that stores it must keep its sign, and one that
// tells a new subscriber only the slots off their default must tell it
// this one (r6 compares with `==` and leaves it out: LAYER-SUBSCRIBE-1,
// docs/verse_wire.md section 11). Before, it came only as one of the
// specials of any_real and any_float, to a layer whose default was 0 one
// time in three.
Gen<Command> signed_zero_write(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)]() -> Command {
    const View& v = *pv;
    const bool vertex =
        !v.zero_default_vertex_reals.empty() && !v.vertices.empty() &&
        (v.zero_default_face_reals.empty() || v.polygons.empty() || *uniform(0, 2) == 0);
    const auto [layer, negative] = *gen::elementOf(vertex ? v.zero_default_vertex_reals : v.zero_default_face_reals);
    const std::uint32_t id = *gen::elementOf(vertex ? v.vertices : v.polygons);
    const double zero = negative ? 0.0 : -0.0;  // the other sign than the default's
    if (*uniform(0, 2) == 0)
      return vertex ? Command{cmd::VertexSetReal64{layer, id, zero}} : Command{cmd::PolygonSetFaceReal64{layer, id, zero}};
    const float z32 = static_cast<float>(zero);
    return vertex ? Command{cmd::VertexSetReal32{layer, id, z32}} : Command{cmd::PolygonSetFaceReal32{layer, id, z32}};
  });
}

// A new vertex, at the lowest free id, at a finite position: how a mesh
// grows (set_vertex mostly moves live vertices and tries the edges).
Gen<Command> grow_vertex(const View& v) {
  std::uint32_t next = 0;
  for (std::uint32_t id : v.vertices)
    if (id == next) ++next;
  const auto at = gen::map(uniform<int>(-16, 17), [](int i) { return i / 4.0; });
  return gen::exec([next, at]() -> Command {
    if (*uniform(0, 3) == 0)
      return cmd::VertexSetXyzReal32{0, next, static_cast<float>(*at), static_cast<float>(*at), static_cast<float>(*at)};
    return cmd::VertexSetXyzReal64{0, next, *at, *at, *at};
  });
}

// A polygon, or while there are fewer than three vertices mostly a new
// vertex: a polygon needs three or four live vertices to be accepted.
Gen<Command> build_polygon(const View& v) {
  if (v.vertices.size() >= 3) return set_polygon(v);
  return gen::weightedOneOf<Command>({{5, grow_vertex(v)}, {1, set_polygon(v)}});
}

// The highest live id of `live` (sorted), or nothing.
std::optional<std::uint32_t> highest(const std::vector<std::uint32_t>& live) {
  if (live.empty()) return std::nullopt;
  return live.back();
}

// A valid polygon (set_polygon's shape) far past the live ones: 30 to 90
// ids above the highest live polygon (or the lowest free id). A node that
// grows its storage in chunks grows it here, and the ids it skipped are
// where it may take an unused slot for a live polygon (r6 fills grown
// polygon storage with corners 0, not the unused marker: docs/verse_wire.md
// section 11, "What the watching session is not told").
Gen<Command> sparse_polygon(const View& v) {
  std::uint32_t next = 0;
  for (std::uint32_t id : v.polygons)
    if (id == next) ++next;
  const std::uint32_t base = std::max(next, highest(v.polygons).value_or(0) + 1);
  return gen::exec([pv = std::make_shared<const View>(v), base]() -> Command {
    Command c = *set_polygon(*pv);
    std::get<cmd::PolygonSetCornerUint32>(c).polygon_id = base + *uniform<std::uint32_t>(30, 91);
    return c;
  });
}

// Whether some polygon is live far past the lowest free id (sparse_polygon
// made one, or a magnitude id): ids below it, and just above it, were never
// created.
bool polygons_sparse(const View& v) {
  std::uint32_t next = 0;
  for (std::uint32_t id : v.polygons)
    if (id == next) ++next;
  return highest(v.polygons).value_or(0) > next + 8;
}

// A POLYGON_FACE_UINT8 layer, at the lowest free layer id under a name no
// layer has, with a default above 255 (which a UINT8 slot cannot hold: a
// new slot holds the default's low byte). Made after a polygon far past the
// others (polygons_sparse), its slots are one per live polygon
// (LAYER-STACK-1). A node that took the ids its storage grew by for live
// polygons has slots for them too, and a node that tells a subscriber only
// the slots that differ from the layer's default (r6: the default as 32
// bits against the slot's 8) shows them to every new subscriber: the
// watching session of the exec wrapper, which subscribes each new layer,
// as well as the wire route's late subscriber. With a default of 255 or
// less r6 keeps those slots to itself (docs/verse_wire.md section 12).
Gen<Command> grown_uint8_layer(const View& v) {
  std::uint16_t id = 2;
  for (std::uint16_t l : v.layers)
    if (l == id) ++id;
  std::string name = "grown";
  for (const char* candidate : {"grown", "grown_2", "grown_3", "grown_4"})
    if (std::find(v.names.begin(), v.names.end(), candidate) == v.names.end()) {
      name = candidate;
      break;
    }
  return gen::exec([id, name]() -> Command {
    const std::uint32_t def = *gen::elementOf(std::vector<std::uint32_t>{256u, 257u, 511u, 0x10000u});
    return Command{cmd::LayerCreate{id, name, static_cast<std::uint8_t>(LayerType::PolygonFaceUint8), def, 0.0}};
  });
}

// A polygon delete (either form), or a pick, after a polygon far past the
// others (polygons_sparse): the delete names an id near the highest live
// one, below or above it, that no polygon has; POLY-DELETE-1 refuses it.
// A node that took the ids its storage grew by for live polygons applies
// it. The pick (1 in 4) asks for the lowest free id (VERTEX-ID-PICK-1),
// which such a node may skip.
Gen<Command> delete_unused_polygon(const View& v) {
  const std::uint32_t h = highest(v.polygons).value_or(0);
  std::vector<std::uint32_t> unused;
  const std::uint32_t lo = h > 40 ? h - 40 : 0;
  // (in 64 bits: a magnitude id near 2^32 made h + 32 wrap, and the list
  // empty; 0xFFFFFFFF is "pick one", not an id)
  const std::uint64_t end = std::min<std::uint64_t>(std::uint64_t{h} + 32, kNone32);
  for (std::uint64_t id = lo; id < end; ++id)
    if (!std::binary_search(v.polygons.begin(), v.polygons.end(), static_cast<std::uint32_t>(id)))
      unused.push_back(static_cast<std::uint32_t>(id));
  if (unused.empty()) return set_polygon(v);
  return gen::exec([pv = std::make_shared<const View>(v), unused]() -> Command {
    if (*uniform(0, 4) == 0) {
      Command c = *set_polygon(*pv);
      std::get<cmd::PolygonSetCornerUint32>(c).polygon_id = kNone32;
      return c;
    }
    const std::uint32_t id = *gen::elementOf(unused);
    if (*uniform(0, 2) == 0) return Command{cmd::PolygonSetCornerUint32{Node::kPolygonLayer, id, {kNone32, 0, 0, 0}}};
    return Command{cmd::PolygonDelete{id}};
  });
}

// A vertex or polygon re-created at an id most likely deleted earlier in
// the case (dead_ids), with a finite position or three or four live
// corners: its slots in the other layers must hold their defaults
// (LAYER-DEFAULT-1, element.create.slot_default), not what the deleted
// element held there. r6 keeps the old values (its delete marks only the
// base layer) and sends them to a new subscriber (docs/verse_wire.md
// section 11). Before, a case rarely wrote a value, deleted its element
// and created one at the same id again.
Gen<Command> recreate_dead(const View& v) {
  const bool vertex_gap = has_gap(v.vertices), polygon_gap = has_gap(v.polygons) && v.vertices.size() >= 3;
  return gen::exec([pv = std::make_shared<const View>(v), vertex_gap, polygon_gap]() -> Command {
    const View& v = *pv;
    if (polygon_gap && (!vertex_gap || *uniform(0, 2) == 0)) {
      Command c = *set_polygon(v);
      std::get<cmd::PolygonSetCornerUint32>(c).polygon_id = *gen::elementOf(dead_ids(v.polygons));
      return c;
    }
    const std::uint32_t id = *gen::elementOf(dead_ids(v.vertices));
    const auto at = gen::map(uniform<int>(-16, 17), [](int i) { return i / 4.0; });
    return cmd::VertexSetXyzReal64{0, id, *at, *at, *at};
  });
}

// A delete of a live vertex or polygon that has values in a layer of
// another type (value_step wrote them: View::written_vertices, mostly),
// so that recreate_dead follows.
Gen<Command> delete_written(const View& v) {
  if (v.vertices.empty() && v.polygons.empty()) return set_vertex(v);
  const bool written = !v.written_vertices.empty() || !v.written_polygons.empty();
  const auto& vs = written ? v.written_vertices : v.vertices;
  const auto& ps = written ? v.written_polygons : v.polygons;
  const bool vertex_values =
      !vs.empty() &&
      (written || !v.vertex_uint_layers.empty() || !v.vertex_real_layers.empty() || !v.vertex_xyz_layers.empty());
  return gen::exec([vs, ps, vertex_values]() -> Command {
    if (ps.empty() || (vertex_values && *uniform(0, 2) == 0)) return cmd::VertexDelete{*gen::elementOf(vs)};
    return cmd::PolygonDelete{*gen::elementOf(ps)};
  });
}

Gen<Command> set_crease(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)]() -> Command {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    const bool vertex = *gen::arbitrary<bool>();
    // The names of existing layers a crease could read (of the right type
    // or not), so that settings and layers meet.
    std::vector<std::string> existing = vertex ? v.vertex_uint_names : v.corner_uint_names;
    const auto& wrong = vertex ? v.vertex_real_names : v.face_uint_names;
    existing.insert(existing.end(), wrong.begin(), wrong.end());
    std::string name = *gen::weightedOneOf<std::string>({
        {3, gen::just(std::string(""))},
        {5, gen::just(std::string(vertex ? "vcrease" : "ecrease"))},
        {existing.empty() ? 0u : 4u, existing.empty() ? gen::just(std::string()) : gen::elementOf(existing)},
        {2, layer_name(v)},
        // names at the limit: 15 bytes is a name, 16 is not (CREASE-NAME-1)
        {1, gen::elementOf(std::vector<std::string>{"fifteen_bytes_x", "sixteen_bytes_xx"})},
    });
    if (vertex) return cmd::CreaseSetVertex{name, *crease_value()};
    return cmd::CreaseSetEdge{name, *crease_value()};
  });
}

// A layer for creases to name: mostly of the right type, sometimes not, so
// that the fallback of CREASE-LAYER-MISSING-1 is exercised too.
Gen<Command> create_crease_layer(const View&) {
  return gen::exec([]() -> Command {
    const bool vertex = *gen::arbitrary<bool>();
    const bool right_type = *uniform(0, 4) != 0;
    cmd::LayerCreate c;
    c.layer_id = *uniform<std::uint16_t>(2, 7);
    c.name = vertex ? "vcrease" : "ecrease";
    const LayerType t = vertex ? (right_type ? LayerType::VertexUint32 : LayerType::VertexReal)
                               : (right_type ? LayerType::PolygonCornerUint32 : LayerType::PolygonFaceUint32);
    c.type = static_cast<std::uint8_t>(t);
    c.def_uint = *crease_value();
    c.def_real = *gen::elementOf(std::vector<double>{0.0, 7.0, 1e9});
    return c;
  });
}

// Values in whatever layers creases might name.
Gen<Command> write_crease_values(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)]() -> Command {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    const int kind = *uniform(0, 4);
    if (kind == 0 && !v.vertex_uint_layers.empty())
      return cmd::VertexSetUint32{*gen::elementOf(v.vertex_uint_layers), *live_id(v.vertices), *crease_value()};
    if (kind == 1 && !v.vertex_real_layers.empty())
      return cmd::VertexSetReal64{*gen::elementOf(v.vertex_real_layers), *live_id(v.vertices),
                                  double(*uniform(0, 1000))};
    if (kind == 2 && !v.face_u32_layers.empty())
      return cmd::PolygonSetFaceUint32{*gen::elementOf(v.face_u32_layers), *live_id(v.polygons), *crease_value()};
    // Corner values: mostly into the layer the edge setting names, and
    // mostly not all equal (an edge must differ from its neighbour for
    // the corner-to-edge rule to show).
    std::vector<std::uint16_t> named;
    for (std::size_t i = 0; i < v.corner_uint_layers.size(); ++i)
      if (v.corner_uint_names[i] == v.edge_crease_layer) named.push_back(v.corner_uint_layers[i]);
    const std::uint16_t layer = named.empty() ? *typed_layer(v.corner_uint_layers, v)
                                              : *pick<std::uint16_t>(named, typed_layer(v.corner_uint_layers, v));
    cmd::PolygonSetCornerUint32 c{layer, *live_id(v.polygons), {}};
    for (auto& x : c.v) x = *crease_value();
    if (c.v[0] == c.v[1] && c.v[1] == c.v[2] && *uniform(0, 4) != 0) c.v[*uniform(0, 3)] ^= 0xFFFFFFFFu;
    return c;
  });
}

Gen<double> unit_component() {
  return gen::map(uniform<int>(-4, 5), [](int i) { return i / 4.0; });
}

Gen<Command> create_bone(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)]() -> Command {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    cmd::BoneCreate c;
    c.bone_id = *pick<std::uint16_t>(v.bones, gen::weightedOneOf<std::uint16_t>(
                                                  {{8, uniform<std::uint16_t>(0, 6)},
                                                   {1, gen::just(std::uint16_t(kNone16))},
                                                   {2, magnitude<std::uint16_t>()}}));
    std::vector<std::string> weights = v.vertex_uint_names;
    weights.insert(weights.end(), v.vertex_real_names.begin(), v.vertex_real_names.end());
    c.weight = *gen::weightedOneOf<std::string>({
        {8, weights.empty() ? gen::just(std::string("weight")) : gen::elementOf(weights)},
        {1, layer_name(v)},
        {1, gen::just(std::string(""))},  // the wire's destroy
    });
    c.reference = *gen::weightedOneOf<std::string>({
        {6, gen::just(std::string(""))},
        {2, v.vertex_uint_names.empty() ? gen::just(std::string("ref")) : gen::elementOf(v.vertex_uint_names)},
        {1, layer_name(v)},
    });
    c.parent = *pick<std::uint16_t>(v.bones, gen::weightedOneOf<std::uint16_t>(
                                                 {{3, gen::elementOf(std::vector<std::uint16_t>{kNone16, 9, 0})},
                                                  {1, magnitude<std::uint16_t>()}}));
    for (auto& x : c.pos) x = *unit_component();
    // Labels at the limit: 15 bytes is a name, 16 is not (BONE-NAME-1).
    c.pos_label = *gen::elementOf(std::vector<std::string>{"", "curve_x", "fifteen_bytes_x", "sixteen_bytes_xx"});
    // Rotations: identity, quarter turns about an axis, or anything.
    c.rot = *gen::weightedOneOf<std::array<double, 4>>({
        {2, gen::just<std::array<double, 4>>({0, 0, 0, 1})},
        {3, gen::elementOf(std::vector<std::array<double, 4>>{{0, 0, std::sqrt(0.5), std::sqrt(0.5)},
                                                {std::sqrt(0.5), 0, 0, std::sqrt(0.5)}, {0, 1, 0, 0},
                                                {0, 0, 0, 2}})},
        {3, gen::exec([] {
           return std::array<double, 4>{*unit_component(), *unit_component(), *unit_component(), *unit_component()};
         })},
        {1, gen::elementOf(std::vector<std::array<double, 4>>{{0, 0, 0, 0},
                                                {std::numeric_limits<double>::quiet_NaN(), 0, 0, 1}})},
        // Norms that underflow or overflow, subnormals, signed zeros, scaled
        // quaternions: the pose's normalization is where an implementation
        // divides by zero or loses precision (docs/commands.md 4.8).
        {1, ::vgc::gen::gen_quaternion_extreme()},
    });
    c.rot_label = *gen::elementOf(std::vector<std::string>{"", "curve_r"});
    return c;
  });
}

Gen<Command> destroy_bone(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)]() -> Command {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    return cmd::BoneDestroy{*pick<std::uint16_t>(
        v.bones, gen::weightedOneOf<std::uint16_t>({{3, uniform<std::uint16_t>(0, 6)}, {1, magnitude<std::uint16_t>()}}))};
  });
}

// A well-formed bone create that asks for a free id (0xFFFF, BONE-ID-PICK-1):
// a weight layer that exists when there is one, no reference layer, a live
// parent or none, plain values; so that the pick itself is what is judged.
Gen<Command> pick_bone(const View& v) {
  return gen::exec([pv = std::make_shared<const View>(v)]() -> Command {
    const View& v = *pv;  // one copy, shared by the copies RapidCheck makes of this lambda
    cmd::BoneCreate c;
    c.bone_id = kNone16;
    std::vector<std::string> weights = v.vertex_uint_names;
    weights.insert(weights.end(), v.vertex_real_names.begin(), v.vertex_real_names.end());
    c.weight = weights.empty() ? std::string("weight") : *gen::elementOf(weights);
    c.parent = *pick<std::uint16_t>(v.bones, gen::just(std::uint16_t(kNone16)));
    for (auto& x : c.pos) x = *unit_component();
    c.rot = {0, 0, 0, 1};
    return c;
  });
}

// The corners of a fill's polygons: the three lowest live vertices, highest
// first (an order set_polygon seldom draws), as a triangle.
std::optional<std::array<std::uint32_t, 4>> fill_corners(const View& v) {
  if (v.vertices.size() < 3) return std::nullopt;
  return std::array<std::uint32_t, 4>{v.vertices[2], v.vertices[1], v.vertices[0], kNone32};
}

// Whether the node's polygons are a fill's (fill_polygon made them all):
// at least one, each the triangle of fill_corners.
bool filling(const View& v) {
  const auto corners = fill_corners(v);
  if (!corners || v.polygons.empty()) return false;
  const std::vector<std::uint32_t> tri{(*corners)[0], (*corners)[1], (*corners)[2]};
  for (const auto& c : v.polygon_corners)
    if (c != tri) return false;
  return true;
}

// A polygon at the id the node picks ("pick one for me", 0xFFFFFFFF), the
// triangle of fill_corners: one step of a fill, which makes ids 0, 1, 2, ...
// live one after the other until more than 32 are, past the first chunk of
// a node that grows its polygon storage in chunks of 32 (r6). Each pick is
// judged: the lowest free id (VERTEX-ID-PICK-1, the suite's reading). r6
// skips the ids its storage grew by, which it filled with corners 0 and so
// takes for live polygons, once ids 0 to 31 are live: the pick after 32
// gives 64, not 33. No other step fills a run of ids: a default certify
// draws a pick once in tens of polygon creates.
Gen<Command> fill_polygon(const View& v) {
  const auto corners = *fill_corners(v);
  return gen::just(Command{cmd::PolygonSetCornerUint32{Node::kPolygonLayer, kNone32, corners}});
}

// During a fill past 32 polygons (1 in 8 steps): a delete of a live polygon,
// mostly one of the lowest 32, so that the next pick must take the freed id
// (r6 does: its search starts again there) and the one after must skip the
// live ones again.
Gen<Command> fill_delete(const View& v) {
  std::vector<std::uint32_t> low;
  for (std::uint32_t id : v.polygons)
    if (id < 32) low.push_back(id);
  return gen::exec([low, all = v.polygons]() -> Command {
    const std::uint32_t id = low.empty() || *uniform(0, 4) == 0 ? *gen::elementOf(all) : *gen::elementOf(low);
    return Command{cmd::PolygonDelete{id}};
  });
}

Gen<Command> bone_layer(const View&) {
  return gen::exec([]() -> Command {
    cmd::LayerCreate c;
    c.layer_id = *uniform<std::uint16_t>(2, 6);
    c.name = *gen::elementOf(std::vector<std::string>{"weight", "ref", "w2"});
    c.type = *gen::elementOf(std::vector<std::uint8_t>{1, 2, 1, 128});
    return c;
  });
}

// `make`'s generator for the shared View, built only if drawn (gen::lazy).
Gen<Command> lazily(const std::shared_ptr<const View>& shared, Gen<Command> (*make)(const View&)) {
  return rc::gen::lazy([shared, make] { return make(*shared); });
}

// One step of ids.stateful (Focus::Ids). A fill (fill_polygon) once started
// takes every step until more than 32 polygons are live, then 7 in 8
// (fill_delete the rest), up to 36 polygons; the rest of the case draws as
// any other (at 48, BONE-ID-PICK-1 was unchecked against r6 at seed 4: the
// fills took the long cases' steps, and its few judged picks with them). A
// case draws up to size + 1 commands and a fill needs 3 vertices and 34
// picks, so it starts only in cases of size 36 or more (in a shorter one it
// could not get past 32 and would take the steps of the other pick rules):
// there, while the node has no polygon, new vertices (until 3) and then the
// fill's first pick take most steps, so that the fill's counterexample
// holds little else (a pick's difference is a choice note, kept as the
// shortest case that showed it, not shrunk).
Gen<Command> ids_step(const std::shared_ptr<const View>& shared) {
  const View& v = *shared;
  const auto L = [&shared](Gen<Command> (*make)(const View&)) { return lazily(shared, make); };
  using W = std::pair<std::size_t, Gen<Command>>;
  if (filling(v) && v.polygons.size() < 36)
    return rc::gen::weightedOneOf<Command>(
        {W{7, L(fill_polygon)}, W{v.polygons.size() > 32 ? 1u : 0u, L(fill_delete)}});
  const auto ids = [&](std::size_t grow, std::size_t fill) {
    // (pick_bone 4, not 2: the long cases the fills take held most of the
    // bone picks judged against r6, whose named bone ids diverge early;
    // BONE-ID-PICK-1 was judged 2 to 9 times a run before, and at seed 4
    // not at all with the fills)
    return rc::gen::weightedOneOf<Command>({W{3, L(create_layer)}, W{4, L(set_vertex)}, W{3, L(build_polygon)},
                                            W{2, L(create_bone)}, W{4, L(pick_bone)}, W{1, L(bone_layer)},
                                            W{2, L(delete_vertex)}, W{grow, L(grow_vertex)},
                                            W{fill, L(fill_polygon)}});
  };
  if (!v.polygons.empty()) return ids(0, 0);
  const bool three = v.vertices.size() >= 3;
  return rc::gen::withSize([plain = ids(0, 0), fill = ids(three ? 0 : 60, three ? 60 : 0)](int size) {
    return size >= 36 ? fill : plain;
  });
}

}  // namespace

Gen<Command> gen_command(const Node& model, Focus focus) {
  // One View, shared by the alternatives; each alternative is built only
  // if drawn (gen::lazy). The draws are the same as building all of them
  // first: weightedOneOf picks by weight, then runs the picked one with
  // the same random source. Building all, each copying what it needs of
  // the View, was most of a fuzz_property_* run (docs/fuzzing.md).
  const auto shared = std::make_shared<const View>(view_of(model));
  const View& v = *shared;
  const auto L = [&shared](Gen<Command> (*make)(const View&)) { return lazily(shared, make); };
  using W = std::pair<std::size_t, Gen<Command>>;
  switch (focus) {
    case Focus::Layers:
      return rc::gen::weightedOneOf<Command>({W{6, L(create_layer)}, W{3, L(destroy_layer)}, W{3, L(subscribe)},
                                          W{4, L(set_vertex)}, W{v.vertex_xyz_layers.empty() ? 2u : 5u, L(delete_vertex)},
                                          W{3, L(build_polygon)}, W{1, L(delete_polygon)}, W{2, L(value_step)},
                                          W{1, L(write_dead)}});
    case Focus::Polygons:
      return rc::gen::weightedOneOf<Command>({W{6, L(set_vertex)}, W{2, L(delete_vertex)}, W{7, L(build_polygon)},
                                          W{v.polygons.empty() ? 1u : 4u, L(delete_polygon)}, W{1, L(create_layer)},
                                          // (more once sparse: the share the grown-storage steps take)
                                          W{v.polygons.empty() ? 0u : polygons_sparse(v) ? 7u : 4u, L(value_step)},
                                          W{has_gap(v.polygons) || has_gap(v.vertices) ? 2u : 0u, L(write_dead)},
                                          W{v.polygons.empty() ? 0u : 2u, L(non_manifold_polygon)},
                                          W{v.vertices.size() >= 3 && !polygons_sparse(v) ? 2u : 0u, L(sparse_polygon)},
                                          W{polygons_sparse(v) ? 4u : 0u, L(delete_unused_polygon)},
                                          // after it, a layer that shows slots of grown ids to a
                                          // new subscriber; with delete_unused_polygon, both
                                          // shapes on every route (issue 27 item 4: before, the
                                          // wire route and the exec wrapper each reached the
                                          // behaviour through one clause, by chance, at seed 2)
                                          W{polygons_sparse(v) && !v.wide_u8_default ? 4u : 0u, L(grown_uint8_layer)}});
    case Focus::Creases: {
      // A crease rule is seen only in a state with all of: polygons, a
      // crease layer, a setting naming it, and unequal values in it (equal
      // ones hide an off-by-one corner). Weigh toward the missing piece, so
      // that short sequences get there too; a default value fills every
      // new slot alike, so writes weigh most once the rest is in place.
      const bool mesh = v.polygons.size() >= 1, named_edge = !v.edge_crease_layer.empty(),
                 named_vertex = !v.vertex_crease_layer.empty(),
                 crease_layers = !v.corner_uint_layers.empty() && !v.vertex_uint_layers.empty();
      const std::size_t write = mesh && (named_edge || named_vertex) ? 10 : 3;
      return rc::gen::weightedOneOf<Command>(
          {W{v.vertices.size() >= 4 ? 3u : 6u, L(set_vertex)}, W{mesh ? 3u : 6u, L(build_polygon)},
           W{named_edge && named_vertex ? 2u : 4u, L(set_crease)}, W{crease_layers ? 1u : 3u, L(create_crease_layer)},
           W{write, L(write_crease_values)}, W{1, L(destroy_layer)}, W{1, L(delete_vertex)},
           W{mesh ? 1u : 0u, L(value_step)}, W{mesh ? 2u : 0u, L(non_manifold_polygon)},
           W{has_gap(v.polygons) ? 2u : 0u, L(write_dead)}});
    }
    case Focus::Bones:
      return rc::gen::weightedOneOf<Command>({W{2, L(bone_layer)}, W{6, L(create_bone)}, W{2, L(destroy_bone)},
                                          W{1, L(destroy_layer)}, W{1, L(set_vertex)}});
    case Focus::Values: {
      // Cases are short (certify draws 1..size+1 commands, size up to 50):
      // weigh toward the missing piece of a landing write (vertices, a
      // polygon, a layer of each of the eight types), then toward writes.
      const std::size_t types = !v.vertex_xyz_layers.empty() + !v.vertex_uint_layers.empty() +
                                !v.vertex_real_layers.empty() + !v.corner_uint_layers.empty() +
                                !v.corner_real_layers.empty() + !v.face_u8_layers.empty() +
                                !v.face_u32_layers.empty() + !v.face_real_layers.empty();
      const bool mesh = !v.polygons.empty();
      const bool faces = !v.face_u8_layers.empty() || !v.face_u32_layers.empty() || !v.face_real_layers.empty();
      return rc::gen::weightedOneOf<Command>(
          {W{1, L(create_layer)}, W{types == 0 ? 2u : 1u, L(create_value_layer)}, W{1, L(set_vertex)},
           W{mesh ? 1u : 8u, L(build_polygon)},
           // (22, not 20: the share the two targeted steps below take)
           W{22, L(value_step)},
           // a polygon delete once there are face layers, then writes to
           // the deleted (the share of value_step grows to match)
           W{mesh && faces ? 1u : 0u, L(delete_polygon)},
           W{has_gap(v.polygons) || has_gap(v.vertices) ? 5u : 0u, L(write_dead)},
           // a delete of a written element, then its re-creation at the
           // same id (whose slots hold the defaults again)
           W{!v.written_vertices.empty() || !v.written_polygons.empty() ? 2u
             : types > 0 && (!v.vertices.empty() || !v.polygons.empty()) ? 1u
                                                                          : 0u,
             L(delete_written)},
           W{has_gap(v.vertices) || (has_gap(v.polygons) && v.vertices.size() >= 3) ? 4u : 0u, L(recreate_dead)},
           // a value equal to its layer's default only as a number
           W{signed_zero_ready(v) ? 2u : 0u, L(signed_zero_write)}});
    }
    case Focus::Ids:
      return ids_step(shared);
    case Focus::Anything:
      break;
  }
  return rc::gen::weightedOneOf<Command>(
      {W{2, L(create_layer)}, W{1, L(create_value_layer)}, W{2, L(destroy_layer)}, W{1, L(subscribe)}, W{4, L(set_vertex)},
       W{2, L(delete_vertex)}, W{4, L(build_polygon)}, W{2, L(delete_polygon)}, W{4, L(value_step)},
       W{2, L(set_crease)}, W{1, L(create_crease_layer)}, W{2, L(create_bone)}, W{1, L(destroy_bone)},
       W{1, L(bone_layer)}});
}

}  // namespace vgc
