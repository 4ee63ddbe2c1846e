// reference_plugin_table_test.cpp — the reference behind the plugin C ABI
// answers like the reference node; each seeded fault does what it says and
// nothing else; load_plugin refuses what is not a plugin.
#include "reference_plugin_table.h"

#include <gtest/gtest.h>

#include "plugin_node.h"

namespace vgc::fuzz {
namespace {

struct Session {
  const vgc_plugin_v1_table* t;
  vgc_node* n;
  explicit Session(PluginFault f) : t(reference_plugin_table(f)), n(t->create()) {}
  ~Session() { t->destroy(n); }
  int apply(const char* line) {
    const char* reason = nullptr;
    return t->apply(n, line, &reason);
  }
  std::string snapshot() { return t->snapshot(n); }
};

// Three vertices, then a triangle repeating a corner (README: corners
// pairwise distinct, so it must be rejected), then the real32 delete form of
// vertex 2 (README: FLT_MAX = 3.4028235e+38 means delete).
void run_script(Session& s, int* repeated, int* deleted) {
  EXPECT_EQ(s.apply("vertex_set_xyz_real64 0 0 0 0 0"), VGC_APPLIED);
  EXPECT_EQ(s.apply("vertex_set_xyz_real64 0 1 1 0 0"), VGC_APPLIED);
  EXPECT_EQ(s.apply("vertex_set_xyz_real64 0 2 0 1 0"), VGC_APPLIED);
  *repeated = s.apply("polygon_set_corner_uint32 1 0 0 1 1 0xFFFFFFFF");
  *deleted = s.apply("vertex_set_xyz_real32 0 2 3.4028235e+38 0 0");
}

TEST(ReferencePluginTable, NoFaultRejectsRepeatsAndDeletes) {
  Session s(PluginFault::None);
  int repeated = 0, deleted = 0;
  run_script(s, &repeated, &deleted);
  EXPECT_EQ(repeated, VGC_REJECTED);
  EXPECT_EQ(deleted, VGC_APPLIED);
  EXPECT_EQ(s.snapshot().find("vertex 2 "), std::string::npos);
  EXPECT_EQ(s.apply("no_such_verb 1"), VGC_MALFORMED);
}

TEST(ReferencePluginTable, RepeatedCornersFaultAcceptsTheRepeatOnly) {
  Session s(PluginFault::AcceptRepeatedCorners);
  int repeated = 0, deleted = 0;
  run_script(s, &repeated, &deleted);
  EXPECT_EQ(repeated, VGC_APPLIED);
  EXPECT_EQ(deleted, VGC_APPLIED);
  // A corner naming no vertex is still rejected.
  EXPECT_EQ(s.apply("polygon_set_corner_uint32 1 0 0 1 9 0xFFFFFFFF"), VGC_REJECTED);
}

TEST(ReferencePluginTable, Real32DeleteFaultKeepsTheVertex) {
  Session s(PluginFault::IgnoreReal32Delete);
  int repeated = 0, deleted = 0;
  run_script(s, &repeated, &deleted);
  EXPECT_EQ(repeated, VGC_REJECTED);
  EXPECT_EQ(deleted, VGC_APPLIED);
  EXPECT_NE(s.snapshot().find("vertex 2 "), std::string::npos);
}

TEST(LoadPlugin, RefusesWhatIsNotAPlugin) {
  std::string error;
  EXPECT_EQ(load_plugin("/nonexistent/libnothing.so", &error), nullptr);
  EXPECT_NE(error.find("cannot load"), std::string::npos) << error;
  error.clear();
  EXPECT_EQ(load_plugin("libc.so.6", &error), nullptr);  // loads, but exports no vgc_plugin_v1
  EXPECT_NE(error.find("does not export"), std::string::npos) << error;
}

}  // namespace
}  // namespace vgc::fuzz
