// Checks reference/geometry/crease_sharpness.h: the two ends the spec fixes (000
// 2.6.2: "zero represents a smooth surface (no crease), while MAX_UINT32
// should give the maximum amount of crease"), monotonicity and linearity of
// the mapping in between, the shared-edge rule (maximum) and the boundary
// rule, and the Sdc::Crease rules as OpenSubdiv documents them.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>

#include "catmull_clark.h"
#include "crease_sharpness.h"
#include "subdivision_support.h"

namespace vgc {
namespace {

TEST(CreaseSharpness, EndsAreSmoothAndInfinite) {
  EXPECT_EQ(crease_to_sharpness(0), 0.0f);
  EXPECT_TRUE(is_smooth(crease_to_sharpness(0)));
  EXPECT_EQ(crease_to_sharpness(0xFFFFFFFFu), 10.0f);  // Sdc::Crease::SHARPNESS_INFINITE
  EXPECT_TRUE(is_infinite(crease_to_sharpness(0xFFFFFFFFu)));
  // Only the top value is infinite; every other non-zero value is semi-sharp.
  EXPECT_TRUE(is_semi_sharp(crease_to_sharpness(0xFFFFFFFEu)));
  EXPECT_TRUE(is_semi_sharp(crease_to_sharpness(0xFFFFFF00u)));
  EXPECT_TRUE(is_semi_sharp(crease_to_sharpness(1)));
  // Linear: half the range is sharpness 5 (within float rounding).
  EXPECT_NEAR(crease_to_sharpness(0x7FFFFFFFu), 5.0f, 1e-6);
  EXPECT_NEAR(crease_to_sharpness(429496730u), 1.0f, 1e-6);  // 1/10 of the range
}

RC_GTEST_PROP(CreaseSharpness, MonotoneNonDecreasing, (std::uint32_t a, std::uint32_t b)) {
  if (a > b) std::swap(a, b);
  RC_ASSERT(crease_to_sharpness(a) <= crease_to_sharpness(b));
}

RC_GTEST_PROP(CreaseSharpness, LinearRoundedDownBelowTop, (std::uint32_t c)) {
  RC_PRE(c != 0xFFFFFFFFu);
  const double exact = 10.0 * c / 4294967295.0;
  const float s = crease_to_sharpness(c);
  RC_ASSERT(static_cast<double>(s) <= exact);
  RC_ASSERT(exact - s <= 1e-6);  // one float ulp at 10 is ~9.5e-7
  RC_ASSERT(s < 10.0f);
  RC_ASSERT((c == 0) == (s == 0.0f));
}

RC_GTEST_PROP(CreaseSharpness, SharedEdgeIsMaximumWhateverTheOrder, (std::vector<std::uint32_t> stored)) {
  RC_PRE(!stored.empty());
  const std::uint32_t m = combine_edge_creases(stored);
  RC_ASSERT(std::find(stored.begin(), stored.end(), m) != stored.end());
  for (std::uint32_t s : stored) RC_ASSERT(s <= m);
  std::reverse(stored.begin(), stored.end());
  RC_ASSERT(combine_edge_creases(stored) == m);
}

TEST(CreaseSharpness, SharedEdgeTakesTheSharperSideInTheBaseLevel) {
  // Two quads sharing the edge 1-2; the left stores 0 for it, the right 0x7FFFFFFF.
  MeshArrays m = test::make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}},
                                 {{0, 1, 2, 3}, {1, 4, 5, 2}});
  m.corner_edge_creases = {0, 0, 0, 0, 0, 0, 0, 0x7FFFFFFFu};  // face 1 corner 3: edge 2 -> 1
  SubdivisionLevel l;
  ASSERT_TRUE(build_base_level(m, &l));
  int shared = -1;
  for (int e = 0; e < l.edge_count(); ++e)
    if (std::min(l.edges[e][0], l.edges[e][1]) == 1 && std::max(l.edges[e][0], l.edges[e][1]) == 2) shared = e;
  ASSERT_GE(shared, 0);
  EXPECT_EQ(l.edge_face_count[shared], 2);
  EXPECT_EQ(l.edge_sharpness[shared], crease_to_sharpness(0x7FFFFFFFu));
  // Swapping which side stores the crease changes nothing.
  m.corner_edge_creases = {0, 0x7FFFFFFFu, 0, 0, 0, 0, 0, 0};
  ASSERT_TRUE(build_base_level(m, &l));
  EXPECT_EQ(l.edge_sharpness[shared], crease_to_sharpness(0x7FFFFFFFu));
  // Every other edge is on the boundary: infinitely sharp though stored smooth.
  for (int e = 0; e < l.edge_count(); ++e)
    if (e != shared) {
      EXPECT_TRUE(is_infinite(l.edge_sharpness[e])) << e;
    }
}

TEST(CreaseSharpness, BoundaryEdgesAreInfiniteWhateverTheCrease) {
  for (std::uint32_t c : {0u, 1u, 0x12345678u, 0xFFFFFFFFu}) {
    EXPECT_TRUE(is_infinite(edge_sharpness_for(c, 1))) << c;
    EXPECT_TRUE(is_infinite(edge_sharpness_for(c, 3))) << c;  // non-manifold, as OpenSubdiv
    EXPECT_EQ(edge_sharpness_for(c, 2), crease_to_sharpness(c)) << c;
  }
}

TEST(CreaseSharpness, UniformSubdivisionOfSharpness) {  // Sdc::Crease::SubdivideUniformSharpness
  EXPECT_EQ(subdivide_sharpness(0.0f), 0.0f);
  EXPECT_EQ(subdivide_sharpness(0.5f), 0.0f);
  EXPECT_EQ(subdivide_sharpness(1.0f), 0.0f);
  EXPECT_EQ(subdivide_sharpness(2.5f), 1.5f);
  EXPECT_EQ(subdivide_sharpness(10.0f), 10.0f);
}

TEST(CreaseSharpness, VertexRules) {  // Sdc::Crease::DetermineVertexVertexRule
  EXPECT_EQ(determine_vertex_rule(0, {0, 0, 0, 0}), CreaseRule::Smooth);
  EXPECT_EQ(determine_vertex_rule(0, {0, 2, 0, 0}), CreaseRule::Dart);
  EXPECT_EQ(determine_vertex_rule(0, {0, 2, 0, 0.5f}), CreaseRule::Crease);
  EXPECT_EQ(determine_vertex_rule(0, {1, 2, 0, 0.5f}), CreaseRule::Corner);
  EXPECT_EQ(determine_vertex_rule(0.1f, {0, 0, 0, 0}), CreaseRule::Corner);
}

TEST(CreaseSharpness, FractionalWeightAveragesTheDecayingFeatures) {
  // Two edges decay (0.25 and 0.75) and one stays sharp (3): (0.25 + 0.75) / 2.
  EXPECT_EQ(fractional_weight_at_vertex(0, 0, {0.25f, 0.75f, 3.0f, 0}), 0.5f);
  // A vertex 0.5 -> 0 and one edge 1 -> 0: (0.5 + 1) / 2.
  EXPECT_EQ(fractional_weight_at_vertex(0.5f, 0, {1.0f, 0, 0}), 0.75f);
  // A vertex 1.5 decays to 0.5 (still sharp): only the edge counts.
  EXPECT_EQ(fractional_weight_at_vertex(1.5f, 0.5f, {0.5f, 0}), 0.5f);
  EXPECT_EQ(fractional_weight_at_vertex(0, 0, {0, 0}), 0.0f);
}

}  // namespace
}  // namespace vgc

namespace vgc {
namespace {

// The same rule driven through the node (000 2.6.2): a vertex crease layer
// and an edge crease layer where the two quads store different creases for
// their shared edge. Corner i of a polygon holds the crease of the edge from
// corner i to corner i+1.
TEST(CreaseSharpness, NodeCreaseLayersGiveTheDocumentedSharpness) {
  const char* script =
      "vertex_set_xyz_real64 0 0 0 0 0\n"
      "vertex_set_xyz_real64 0 1 1 0 0\n"
      "vertex_set_xyz_real64 0 2 1 1 0\n"
      "vertex_set_xyz_real64 0 3 0 1 0\n"
      "vertex_set_xyz_real64 0 4 2 0 0\n"
      "vertex_set_xyz_real64 0 5 2 1 0\n"
      "polygon_set_corner_uint32 1 0 0 1 2 3\n"
      "polygon_set_corner_uint32 1 1 1 4 5 2\n"
      "layer_create 2 \"vc\" VERTEX_UINT32 0 0\n"
      "layer_create 3 \"ec\" POLYGON_CORNER_UINT32 0 0\n"
      "vertex_set_uint32 2 1 0xFFFFFFFF\n"
      "polygon_set_corner_uint32 3 0 0 0x33333333 0 0\n"   // polygon 0, corner 1: edge 1 -> 2
      "polygon_set_corner_uint32 3 1 0 0 0 0x80000000\n"   // polygon 1, corner 3: edge 2 -> 1
      "crease_set_vertex \"vc\" 0\n"
      "crease_set_edge \"ec\" 0\n";
  std::vector<Command> commands;
  TextError error;
  ASSERT_TRUE(parse_commands(script, &commands, &error)) << error.to_string();
  Node node;
  for (const auto& c : commands) ASSERT_EQ(node.apply(c), Reason::Ok) << print_command(c);
  const MeshArrays m = extract_mesh(node);
  SubdivisionLevel l;
  ASSERT_TRUE(build_base_level(m, &l));
  EXPECT_TRUE(is_infinite(l.vertex_sharpness[1]));
  EXPECT_TRUE(is_smooth(l.vertex_sharpness[0]));
  int checked = 0;
  for (int e = 0; e < l.edge_count(); ++e) {
    const int a = std::min(l.edges[e][0], l.edges[e][1]), b = std::max(l.edges[e][0], l.edges[e][1]);
    if (a == 1 && b == 2) {
      EXPECT_EQ(l.edge_sharpness[e], crease_to_sharpness(0x80000000u));  // the larger of the two
      EXPECT_GT(l.edge_sharpness[e], crease_to_sharpness(0x33333333u));
      ++checked;
    }
  }
  EXPECT_EQ(checked, 1);
}

}  // namespace
}  // namespace vgc
