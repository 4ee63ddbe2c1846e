// verse_node_mirror_test.cpp — the node the verse: route rebuilds from what
// a host sends to a subscriber (conformance/adapter/verse_node_mirror.h).
//
// Spec: 000 2.6.1 (a new slot takes its layer's default; layers 0 and 1);
// docs/spec_facts.md section 4 (the aliases a host sends).
#include <gtest/gtest.h>

#include <string>

#include "adapter_test_util.h"
#include "command_text.h"
#include "node.h"
#include "snapshot.h"
#include "verse_node_mirror.h"

namespace vgc {
namespace {

Command C(const std::string& line) {
  std::vector<Command> cs;
  TextError e;
  EXPECT_TRUE(parse_commands(line + "\n", &cs, &e)) << e.to_string();
  return cs.empty() ? Command{} : cs[0];
}

// What every host sends first on subscribing: the two base layers and the
// crease settings (r6 vs_g_subscribe).
void announce_fresh_node(VerseNodeMirror* m) {
  std::string error;
  for (const char* line : {"layer_create 0 \"vertex\" VERTEX_XYZ 0 0", "layer_create 1 \"polygon\" POLYGON_CORNER_UINT32 0 0",
                           "crease_set_vertex \"\" 0", "crease_set_edge \"\" 0"})
    ASSERT_TRUE(m->apply(C(line), &error)) << error;
}

TEST(VerseNodeMirror, AFreshNodeAsAnnouncedPrintsTheReferenceFreshSnapshot) {
  VerseNodeMirror m;
  announce_fresh_node(&m);
  EXPECT_EQ(m.snapshot(), print_snapshot(Node{}));
}

TEST(VerseNodeMirror, NothingAnnouncedPrintsNoLayers) {
  VerseNodeMirror m;
  EXPECT_EQ(m.snapshot().find("layer "), std::string::npos) << m.snapshot();
}

// The cube example, every command of which the reference applies and a
// host therefore sends on as it is: the mirror equals the reference.
TEST(VerseNodeMirror, TheCubeAsSentEqualsTheReference) {
  VerseNodeMirror m;
  announce_fresh_node(&m);
  Node reference;
  std::string error;
  for (const Command& c : test::cube_commands()) {
    ASSERT_EQ(reference.apply(c), Reason::Ok) << print_command(c);
    ASSERT_TRUE(m.apply(c, &error)) << error;
  }
  EXPECT_EQ(m.snapshot(), print_snapshot(reference));
}

TEST(VerseNodeMirror, NewSlotsTakeTheLayerDefaultUntilAValueArrives) {
  VerseNodeMirror m;
  announce_fresh_node(&m);
  std::string error;
  ASSERT_TRUE(m.apply(C("vertex_set_xyz_real64 0 3 1 2 3"), &error)) << error;
  ASSERT_TRUE(m.apply(C("layer_create 2 \"w\" VERTEX_UINT32 7 0"), &error)) << error;  // after the vertex
  ASSERT_TRUE(m.apply(C("vertex_set_xyz_real64 0 4 0 0 0"), &error)) << error;         // before its value
  EXPECT_NE(m.snapshot().find("slot 2 3 7\nslot 2 4 7\n"), std::string::npos) << m.snapshot();
  ASSERT_TRUE(m.apply(C("vertex_set_uint32 2 4 9"), &error)) << error;
  EXPECT_NE(m.snapshot().find("slot 2 3 7\nslot 2 4 9\n"), std::string::npos) << m.snapshot();
}

TEST(VerseNodeMirror, AVertexDeleteRemovesTheVertexOnlyAsSent) {
  VerseNodeMirror m;
  announce_fresh_node(&m);
  std::string error;
  for (const char* line : {"vertex_set_xyz_real64 0 0 0 0 0", "vertex_set_xyz_real64 0 1 1 0 0",
                           "vertex_set_xyz_real64 0 2 0 1 0", "polygon_set_corner_uint32 1 0 0 1 2 4294967295",
                           "vertex_delete 2"})
    ASSERT_TRUE(m.apply(C(line), &error)) << error;
  const std::string s = m.snapshot();
  EXPECT_EQ(s.find("vertex 2 "), std::string::npos) << s;
  // The polygon stays until the host sends its delete (a host that deletes
  // it says so): the mirror shows what was sent, the suite judges it.
  EXPECT_NE(s.find("polygon 0 0 1 2 0xFFFFFFFF"), std::string::npos) << s;
  ASSERT_TRUE(m.apply(C("polygon_set_corner_uint32 1 0 4294967295 0 0 0"), &error)) << error;  // the delete alias
  EXPECT_EQ(m.snapshot().find("polygon 0 "), std::string::npos) << m.snapshot();
}

TEST(VerseNodeMirror, ARetypedLayerStartsOverFromItsDefault) {
  VerseNodeMirror m;
  announce_fresh_node(&m);
  std::string error;
  ASSERT_TRUE(m.apply(C("vertex_set_xyz_real64 0 0 0 0 0"), &error)) << error;
  ASSERT_TRUE(m.apply(C("layer_create 2 \"w\" VERTEX_UINT32 7 0"), &error)) << error;
  ASSERT_TRUE(m.apply(C("vertex_set_uint32 2 0 9"), &error)) << error;
  ASSERT_TRUE(m.apply(C("layer_create 2 \"w\" VERTEX_REAL 0 0.5"), &error)) << error;
  EXPECT_NE(m.snapshot().find("slot 2 0 0.5\n"), std::string::npos) << m.snapshot();
  ASSERT_TRUE(m.apply(C("layer_create 2 \"\" VERTEX_REAL 0 0"), &error)) << error;  // the destroy alias
  EXPECT_EQ(m.snapshot().find("layer 2 "), std::string::npos) << m.snapshot();
}

TEST(VerseNodeMirror, WhatAHostCannotMeanIsAnErrorNamingIt) {
  VerseNodeMirror m;
  announce_fresh_node(&m);
  std::string error;
  EXPECT_FALSE(m.apply(C("vertex_set_uint32 5 0 1"), &error));
  EXPECT_NE(error.find("layer 5, which it never announced"), std::string::npos) << error;
  EXPECT_FALSE(m.apply(C("vertex_set_uint32 0 0 1"), &error));
  EXPECT_NE(error.find("which it announced as VERTEX_XYZ"), std::string::npos) << error;
}

TEST(VerseNodeMirror, AHostCannotMakeItGrowPastItsBound) {
  VerseNodeMirror m(/*max_cells=*/10);
  announce_fresh_node(&m);
  std::string error;
  bool refused = false;
  for (int i = 0; i < 20 && !refused; ++i)
    refused = !m.apply(C("vertex_set_xyz_real64 0 " + std::to_string(i) + " 0 0 0"), &error);
  EXPECT_TRUE(refused);
  EXPECT_NE(error.find("more state than vgc keeps"), std::string::npos) << error;
}

// The late view (verse_implementation.h): a REAL32 subscriber's view taken
// where it differs from the REAL64 one other than by rounding; a vertex
// whose REAL32 form is the delete alias (a coordinate of FLT_MAX) cannot be
// sent to a REAL32 subscriber and keeps the REAL64 view's.
TEST(VerseNodeMirror, AReal32ViewCountsOnlyWhereItDiffersBeyondRounding) {
  VerseNodeMirror v64, v32;
  announce_fresh_node(&v64);
  announce_fresh_node(&v32);
  std::string error;
  for (const char* c : {"layer_create 2 \"r\" VERTEX_REAL 0 0", "layer_create 3 \"x\" VERTEX_XYZ 0 0"}) {
    ASSERT_TRUE(v64.apply(C(c), &error)) << error;
    ASSERT_TRUE(v32.apply(C(c), &error)) << error;
  }
  ASSERT_TRUE(v64.apply(C("vertex_set_xyz_real64 0 0 0.1 0.2 0.3"), &error)) << error;
  ASSERT_TRUE(v32.apply(C("vertex_set_xyz_real32 0 0 0.1 0.2 0.3"), &error)) << error;
  ASSERT_TRUE(v64.apply(C("vertex_set_real64 2 0 0.1"), &error)) << error;
  ASSERT_TRUE(v32.apply(C("vertex_set_real32 2 0 0.1"), &error)) << error;
  VerseNodeMirror same = v64;
  same.take_real32_differences(v32);
  EXPECT_EQ(same.snapshot(), v64.snapshot());  // only rounding
  ASSERT_TRUE(v32.apply(C("vertex_set_real32 2 0 0.5"), &error)) << error;  // a REAL32 subscriber told otherwise
  VerseNodeMirror merged = v64;
  merged.take_real32_differences(v32);
  EXPECT_NE(merged.snapshot().find("slot 2 0 0.5\n"), std::string::npos) << merged.snapshot();
  // FLT_MAX in layer 3: the REAL32 subscriber reads the delete alias.
  ASSERT_TRUE(v64.apply(C("vertex_set_xyz_real64 3 0 1 3.4028234663852886e+38 1"), &error)) << error;
  ASSERT_TRUE(v32.apply(C("vertex_delete 0"), &error)) << error;
  VerseNodeMirror kept = v64;
  kept.take_real32_differences(v32);
  EXPECT_EQ(kept.snapshot(), v64.snapshot());
}

}  // namespace
}  // namespace vgc
