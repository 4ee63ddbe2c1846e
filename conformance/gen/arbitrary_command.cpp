// arbitrary_command.cpp — the RapidCheck command generators declared in
// arbitrary_command.h, compiled once.
//
// Spec: docs/spec_facts.md "Command set of the geometry node" and 000
// section 2.6.1 Table 2-1, as arbitrary_command.h says.
#include "arbitrary_command.h"

namespace vgc {
namespace gen {

// ---- numbers ---------------------------------------------------------------


rc::Gen<double> gen_f64_any() {
  using L = std::numeric_limits<double>;
  return rc::gen::weightedOneOf<double>({
      {6, rc::gen::arbitrary<double>()},
      {2, rc::gen::map(rc::gen::inRange(-8, 9), [](int i) { return i * 0.5; })},
      {4, rc::gen::element(0.0, -0.0, L::infinity(), -L::infinity(), DBL_MAX, -DBL_MAX, DBL_MIN,
                           L::denorm_min(), -L::denorm_min(), L::quiet_NaN(), L::epsilon(),
                           double(FLT_MAX), 4294967295.0)},
      {3, rc::gen::map(rc::gen::pair(rc::gen::arbitrary<bool>(), rc::gen::arbitrary<std::uint64_t>()),
                       [](std::pair<bool, std::uint64_t> p) {  // NaN, random payload
                         std::uint64_t mant = p.second & 0x000FFFFFFFFFFFFFull;
                         if (mant == 0) mant = 1;
                         return bits_to<double>((p.first ? 0x8000000000000000ull : 0) |
                                                0x7FF0000000000000ull | mant);
                       })},
      {2, rc::gen::map(rc::gen::pair(rc::gen::arbitrary<bool>(), rc::gen::arbitrary<std::uint64_t>()),
                       [](std::pair<bool, std::uint64_t> p) {  // subnormal (or zero)
                         return bits_to<double>((p.first ? 0x8000000000000000ull : 0) |
                                                (p.second & 0x000FFFFFFFFFFFFFull));
                       })},
      {1, rc::gen::map(rc::gen::arbitrary<std::uint64_t>(),
                       [](std::uint64_t b) { return bits_to<double>(b); })},
  });
}

rc::Gen<float> gen_f32_any() {
  using L = std::numeric_limits<float>;
  return rc::gen::weightedOneOf<float>({
      {6, rc::gen::arbitrary<float>()},
      {2, rc::gen::map(rc::gen::inRange(-8, 9), [](int i) { return static_cast<float>(i) * 0.5f; })},
      {4, rc::gen::element(0.0f, -0.0f, L::infinity(), -L::infinity(), FLT_MAX, -FLT_MAX, FLT_MIN,
                           L::denorm_min(), -L::denorm_min(), L::quiet_NaN(), L::epsilon())},
      {3, rc::gen::map(rc::gen::pair(rc::gen::arbitrary<bool>(), rc::gen::arbitrary<std::uint32_t>()),
                       [](std::pair<bool, std::uint32_t> p) {
                         std::uint32_t mant = p.second & 0x007FFFFFu;
                         if (mant == 0) mant = 1;
                         return bits_to<float>((p.first ? 0x80000000u : 0u) | 0x7F800000u | mant);
                       })},
      {2, rc::gen::map(rc::gen::pair(rc::gen::arbitrary<bool>(), rc::gen::arbitrary<std::uint32_t>()),
                       [](std::pair<bool, std::uint32_t> p) {
                         return bits_to<float>((p.first ? 0x80000000u : 0u) | (p.second & 0x007FFFFFu));
                       })},
      {1, rc::gen::map(rc::gen::arbitrary<std::uint32_t>(), [](std::uint32_t b) { return bits_to<float>(b); })},
  });
}

rc::Gen<std::array<double, 4>> gen_quaternion_extreme() {
  using Q = std::array<double, 4>;
  using L = std::numeric_limits<double>;
  const rc::Gen<double> zero = rc::gen::element(0.0, -0.0);
  return rc::gen::weightedOneOf<Q>({
      {4, rc::gen::exec([zero] {  // one extreme component, the others zero
         Q q{*zero, *zero, *zero, *zero};
         q[static_cast<std::size_t>(*rc::gen::inRange(0, 4))] = *rc::gen::element(
             1e-300, -1e-300, 1e300, -1e300, L::denorm_min(), -L::denorm_min(), DBL_MIN, DBL_MAX, -DBL_MAX,
             1e-160, 1e-154, 1.5e-154, 1e154, 1.3e154, 1.4e154);
         return q;
       })},
      {3, rc::gen::exec([] {  // an ordinary quaternion scaled far up or down
         Q q;
         for (double& c : q) c = *rc::gen::inRange(-4, 5);
         if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) q[3] = 1;
         const int k = *rc::gen::weightedOneOf<int>(
             {{1, rc::gen::inRange(-1074, -500)}, {1, rc::gen::inRange(500, 1024)}, {1, rc::gen::inRange(-520, -505)}});
         for (double& c : q) c = std::ldexp(c, k);  // may round to 0 or overflow to infinity
         return q;
       })},
      {2, rc::gen::exec([] {  // four equal components: each square finite, their sum not
         const double c = *rc::gen::element(1e154, -1e154, 7e153, 1e-154, 5e-155, 1e-162);
         return Q{c, c, c, *rc::gen::element(c, -c)};
       })},
      {1, rc::gen::exec([zero] { return Q{*zero, *zero, *zero, *zero}; })},  // zero, rejected
      {1, rc::gen::exec([] {  // one non-finite component, rejected
         Q q{0, 0, 0, 1};
         q[static_cast<std::size_t>(*rc::gen::inRange(0, 4))] =
             *rc::gen::element(L::quiet_NaN(), -L::quiet_NaN(), L::infinity(), -L::infinity());
         return q;
       })},
  });
}

// Any class of an unsigned field of T (magnitude.h): 0, small, 2^k and its
// neighbours up to the field's top, the all-ones sentinel and its neighbour.
template <class T> rc::Gen<T> gen_magnitude() {
  constexpr int bits = static_cast<int>(sizeof(T) * 8);
  const std::size_t classes = magnitude_classes(bits).size();
  return rc::gen::exec([classes] {
    const auto k = *rc::gen::resize(rc::kNominalSize, rc::gen::inRange<std::size_t>(0, classes));
    return static_cast<T>(magnitude_value(bits, k, *rc::gen::inRange<std::uint64_t>(0, 16)));
  });
}

rc::Gen<std::uint32_t> gen_u32_any() {
  return rc::gen::weightedOneOf<std::uint32_t>({
      {5, rc::gen::inRange<std::uint32_t>(0, 16)},
      {2, rc::gen::element<std::uint32_t>(0xFFFFFFFFu, 0xFFFFFFFEu, 4000000000u, 0x80000000u, 4096u, 4097u)},
      {3, gen_magnitude<std::uint32_t>()},
      {3, rc::gen::arbitrary<std::uint32_t>()},
  });
}

rc::Gen<std::uint16_t> gen_u16_any() {
  return rc::gen::weightedOneOf<std::uint16_t>({
      {5, rc::gen::inRange<std::uint16_t>(0, 16)},
      {2, rc::gen::element<std::uint16_t>(0xFFFFu, 0xFFFEu, 0x8000u)},
      {3, gen_magnitude<std::uint16_t>()},
      {3, rc::gen::arbitrary<std::uint16_t>()},
  });
}

rc::Gen<std::uint8_t> gen_u8_any() {
  return rc::gen::weightedOneOf<std::uint8_t>({
      {3, rc::gen::inRange<std::uint8_t>(0, 16)},
      {1, rc::gen::element<std::uint8_t>(0xFF, 0x80, 0x7F)},
      {2, gen_magnitude<std::uint8_t>()},
      {2, rc::gen::arbitrary<std::uint8_t>()},
  });
}

rc::Gen<std::uint8_t> gen_layer_type_byte() {
  return rc::gen::weightedOneOf<std::uint8_t>({
      {6, rc::gen::element<std::uint8_t>(0, 1, 2, 128, 129, 130, 131, 132)},
      {1, rc::gen::element<std::uint8_t>(3, 127, 133, 255)},
      {1, rc::gen::arbitrary<std::uint8_t>()},
  });
}

rc::Gen<std::uint8_t> gen_real_format_byte() {
  return rc::gen::weightedOneOf<std::uint8_t>({
      {6, rc::gen::element<std::uint8_t>(0, 1)},
      {1, rc::gen::arbitrary<std::uint8_t>()},
  });
}

// ---- names -----------------------------------------------------------------

rc::Gen<char> gen_name_byte() {
  return rc::gen::weightedOneOf<char>({
      {6, rc::gen::element('a', 'b', 'c', 'u', 'v', 'x', 'y', 'z', '0', '1', '_', ' ')},
      {3, rc::gen::element('\0', '"', '\\', '\n', '\r', '\t', '#', '\x7F', '\x80', '\xFF', '\xC3', 'x')},
      {2, rc::gen::arbitrary<char>()},
  });
}

rc::Gen<std::string> gen_name() {
  return rc::gen::weightedOneOf<std::string>({
      {2, rc::gen::element<std::string>("", "vertex", "polygon", "uv", "weight", "crease", "ref",
                                        "abcdefghijklmno", "abcdefghijklmnop")},
      {5, rc::gen::mapcat(rc::gen::inRange(0, 41),
                          [](int n) { return rc::gen::container<std::string>(static_cast<std::size_t>(n),
                                                                             gen_name_byte()); })},
  });
}

// ---- whole commands --------------------------------------------------------

// The generator for one field, by its type and hint.
template <class T> rc::Gen<T> gen_field(FieldHint hint) {
  if constexpr (std::is_same_v<T, double>) {
    return gen_f64_any();
  } else if constexpr (std::is_same_v<T, float>) {
    return gen_f32_any();
  } else if constexpr (std::is_same_v<T, std::string>) {
    return gen_name();
  } else if constexpr (std::is_same_v<T, std::uint32_t>) {
    return gen_u32_any();
  } else if constexpr (std::is_same_v<T, std::uint16_t>) {
    return gen_u16_any();
  } else {
    static_assert(std::is_same_v<T, std::uint8_t>, "field types: u8/u16/u32/f32/f64/string");
    if (hint == FieldHint::LayerType) return gen_layer_type_byte();
    if (hint == FieldHint::RealFormat) return gen_real_format_byte();
    return gen_u8_any();
  }
}

// Fills every field of C (wire order, command_fields.h) with an
// independently shrinking value. Must be called inside a generator.
struct FieldFiller {
  template <class T> void operator()(const char*, T& v, FieldHint hint) {
    if constexpr (std::is_class_v<T> && !std::is_same_v<T, std::string>) {
      for (auto& e : v) e = *gen_field<std::decay_t<decltype(e)>>(hint);
    } else {
      v = *gen_field<T>(hint);
    }
  }
};

template <class C> rc::Gen<C> gen_command_of() {
  return rc::gen::exec([] {
    C c;
    visit_fields(c, FieldFiller{});
    return c;
  });
}

template <std::size_t I> rc::Gen<Command> gen_command_index() {
  return rc::gen::cast<Command>(gen_command_of<std::variant_alternative_t<I, Command>>());
}

template <std::size_t... I> rc::Gen<Command> gen_command_impl(std::index_sequence<I...>) {
  return rc::gen::oneOf(gen_command_index<I>()...);
}

rc::Gen<Command> gen_command() {
  return gen_command_impl(std::make_index_sequence<kCommandKinds>{});
}

// ---- state-aware commands --------------------------------------------------

rc::Gen<std::string> gen_small_name() {
  return rc::gen::weightedOneOf<std::string>({
      {8, rc::gen::element<std::string>("a", "b", "w", "ref", "crease", "uv")},
      {1, rc::gen::element<std::string>("", "vertex", "polygon")},
      {1, gen_name()},
  });
}

namespace detail {

template <class Map, class Id>
rc::Gen<Id> existing_or(const Map& m, rc::Gen<Id> otherwise) {
  std::vector<Id> ids;
  for (const auto& kv : m) ids.push_back(static_cast<Id>(kv.first));
  if (ids.empty()) return otherwise;
  return rc::gen::weightedOneOf<Id>({{4, rc::gen::elementOf(ids)}, {1, otherwise}});
}

}  // namespace detail

rc::Gen<Command> gen_command_for(const Node& node) {
  namespace rg = rc::gen;
  using rc::Gen;
  const Gen<std::uint16_t> layer = detail::existing_or(node.layers(), rg::inRange<std::uint16_t>(0, 6));
  std::vector<std::uint16_t> non_base;
  for (const auto& kv : node.layers())
    if (kv.first >= 2) non_base.push_back(kv.first);
  const Gen<std::uint16_t> new_layer = rg::weightedOneOf<std::uint16_t>({
      {6, rg::inRange<std::uint16_t>(2, 6)},
      {non_base.empty() ? 0u : 2u, non_base.empty() ? rg::just(std::uint16_t{2}) : rg::elementOf(non_base)},
      {1, rg::element<std::uint16_t>(0, 1)},
      {1, rg::just(kNone16)},
  });
  const Gen<std::uint32_t> vertex = detail::existing_or(
      node.vertices(), rg::weightedOneOf<std::uint32_t>({{8, rg::inRange<std::uint32_t>(0, 8)},
                                                          {1, rg::just(kNone32)}}));
  const Gen<std::uint32_t> polygon = detail::existing_or(
      node.polygons(), rg::weightedOneOf<std::uint32_t>({{8, rg::inRange<std::uint32_t>(0, 6)},
                                                          {1, rg::just(kNone32)}}));
  const Gen<std::uint16_t> bone = detail::existing_or(
      node.bones(), rg::weightedOneOf<std::uint16_t>({{8, rg::inRange<std::uint16_t>(0, 5)},
                                                       {1, rg::just(kNone16)}}));
  const Gen<double> real = rg::weightedOneOf<double>({{12, rg::map(rg::inRange(-4, 5), [](int i) { return i * 0.5; })},
                                                       {1, gen_f64_any()}});
  const Gen<float> real32 = rg::map(real, [](double d) { return static_cast<float>(d); });
  const Gen<std::uint32_t> value = rg::weightedOneOf<std::uint32_t>(
      {{4, rg::inRange<std::uint32_t>(0, 4)}, {1, rg::just(kNone32)}, {1, rg::arbitrary<std::uint32_t>()}});
  const Gen<std::uint8_t> type = rg::weightedOneOf<std::uint8_t>(
      {{12, rg::element<std::uint8_t>(0, 1, 2, 128, 129, 130, 131, 132)},
       {6, rg::element<std::uint8_t>(1, 2)},  // weight and crease layers
       {1, gen_layer_type_byte()}});
  const Gen<std::string> name = gen_small_name();
  // Bones need an existing VERTEX_UINT32 / VERTEX_REAL weight layer (and a
  // VERTEX_UINT32 reference layer): prefer the names of such layers.
  std::vector<std::string> weight_names, reference_names;
  for (const auto& [lid, l] : node.layers()) {
    if (l.type == LayerType::VertexUint32 || l.type == LayerType::VertexReal) weight_names.push_back(l.name);
    if (l.type == LayerType::VertexUint32) reference_names.push_back(l.name);
  }
  const Gen<std::string> weight =
      weight_names.empty() ? name : rg::weightedOneOf<std::string>({{6, rg::elementOf(weight_names)}, {1, name}});
  const Gen<std::string> reference =
      rg::weightedOneOf<std::string>({{3, rg::just(std::string())},
                                      {2, reference_names.empty() ? name : rg::elementOf(reference_names)},
                                      {1, name}});
  const Gen<std::array<std::uint32_t, 4>> corners = rg::exec([vertex] {
    std::array<std::uint32_t, 4> v{*vertex, *vertex, *vertex,
                                   *rg::weightedOneOf<std::uint32_t>({{1, rg::just(kNone32)}, {2, vertex}})};
    return v;
  });

  return rg::weightedOneOf<Command>({
      {1, gen_command()},
      {3, rg::exec([=] { return Command{cmd::LayerCreate{*new_layer, *name, *type, *value, *real}}; })},
      {1, rg::exec([=] { return Command{cmd::LayerDestroy{*layer}}; })},
      {1, rg::exec([=] { return Command{cmd::LayerSubscribe{*layer, *gen_real_format_byte()}}; })},
      {1, rg::exec([=] { return Command{cmd::LayerUnsubscribe{*layer}}; })},
      {4, rg::exec([=] { return Command{cmd::VertexSetXyzReal64{*layer, *vertex, *real, *real, *real}}; })},
      {2, rg::exec([=] { return Command{cmd::VertexSetXyzReal32{*layer, *vertex, *real32, *real32, *real32}}; })},
      // the vertex-delete alias, on whatever layer (VERTEX-DELETE-1)
      {1, rg::exec([=] { return Command{cmd::VertexSetXyzReal64{*layer, *vertex, *real, DBL_MAX, *real}}; })},
      {1, rg::exec([=] { return Command{cmd::VertexSetXyzReal32{*layer, *vertex, FLT_MAX, *real32, *real32}}; })},
      {1, rg::exec([=] { return Command{cmd::VertexDelete{*vertex}}; })},
      {2, rg::exec([=] { return Command{cmd::VertexSetUint32{*layer, *vertex, *value}}; })},
      {1, rg::exec([=] { return Command{cmd::VertexSetReal64{*layer, *vertex, *real}}; })},
      {1, rg::exec([=] { return Command{cmd::VertexSetReal32{*layer, *vertex, *real32}}; })},
      {4, rg::exec([=] { return Command{cmd::PolygonSetCornerUint32{*layer, *polygon, *corners}}; })},
      {1, rg::exec([=] { return Command{cmd::PolygonSetCornerReal64{*layer, *polygon, {*real, *real, *real, *real}}}; })},
      {1, rg::exec([=] {
         return Command{cmd::PolygonSetCornerReal32{*layer, *polygon, {*real32, *real32, *real32, *real32}}};
       })},
      {1, rg::exec([=] { return Command{cmd::PolygonDelete{*polygon}}; })},
      {1, rg::exec([=] { return Command{cmd::PolygonSetFaceUint8{*layer, *polygon, *rg::arbitrary<std::uint8_t>()}}; })},
      {1, rg::exec([=] { return Command{cmd::PolygonSetFaceUint32{*layer, *polygon, *value}}; })},
      {1, rg::exec([=] { return Command{cmd::PolygonSetFaceReal64{*layer, *polygon, *real}}; })},
      {1, rg::exec([=] { return Command{cmd::PolygonSetFaceReal32{*layer, *polygon, *real32}}; })},
      {1, rg::exec([=] { return Command{cmd::CreaseSetVertex{*name, *value}}; })},
      {1, rg::exec([=] { return Command{cmd::CreaseSetEdge{*name, *value}}; })},
      {3, rg::exec([=] {
         cmd::BoneCreate b;
         b.bone_id = *bone;
         b.weight = *weight;
         b.reference = *reference;
         b.parent = *bone;
         b.pos = {*real, *real, *real};
         b.rot = *rg::weightedOneOf<std::array<double, 4>>(
             {{9, rg::exec([=] { return std::array<double, 4>{*real, *real, *real, *real}; })},
              {1, gen_quaternion_extreme()}});
         return Command{b};
       })},
      {1, rg::exec([=] { return Command{cmd::BoneDestroy{*bone}}; })},
  });
}

rc::Gen<std::vector<Command>> gen_command_sequence(std::size_t n, NodeLimits limits) {
  return rc::gen::exec([n, limits] {
    Node node(limits);
    std::vector<Command> out;
    for (std::size_t i = 0; i < n; ++i) {
      out.push_back(*gen_command_for(node));
      node.apply(out.back());
    }
    return out;
  });
}

}  // namespace gen
}  // namespace vgc
