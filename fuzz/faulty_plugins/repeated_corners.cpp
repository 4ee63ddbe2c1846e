// repeated_corners.cpp — a plugin with one seeded fault, for tests/fuzz.
//
// Spec: README "Polygon corners must be pairwise distinct". This plugin is
// the reference behind vgc_plugin.h except that a polygon whose only fault
// is a repeated corner is reported APPLIED (PluginFault::AcceptRepeatedCorners).
// fuzz_differential must find it (tests/fuzz, docs/fuzzing.md).
#include "reference_plugin_table.h"

extern "C" __attribute__((visibility("default"))) const vgc_plugin_v1_table* vgc_plugin_v1(void) {
  return vgc::fuzz::reference_plugin_table(vgc::fuzz::PluginFault::AcceptRepeatedCorners);
}
