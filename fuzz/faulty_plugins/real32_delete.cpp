// real32_delete.cpp — a plugin with one seeded fault, for tests/fuzz.
//
// Spec: README "x, y or z equal to FLT_MAX means g_vertex_delete_real32".
// This plugin is the reference behind vgc_plugin.h except that the real32
// delete form is reported APPLIED and ignored (PluginFault::IgnoreReal32Delete).
// fuzz_differential must find it as a snapshot difference.
#include "reference_plugin_table.h"

extern "C" __attribute__((visibility("default"))) const vgc_plugin_v1_table* vgc_plugin_v1(void) {
  return vgc::fuzz::reference_plugin_table(vgc::fuzz::PluginFault::IgnoreReal32Delete);
}
