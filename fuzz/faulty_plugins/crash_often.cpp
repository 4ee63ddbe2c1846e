// crash_often.cpp — a plugin that crashes on most inputs, for testing that
// `vgc fuzz --time` is a wall-clock limit when almost every input is a
// crash (fork mode restarting crashed jobs overran it before).
//
// Spec: conformance/adapter/vgc_plugin.h. The reference behind the C ABI,
// except that apply() aborts on every vertex_set_xyz_* line (the spec's
// cube and nearly every corpus input holds one).
#include <cstdlib>
#include <cstring>

#include "reference_plugin_table.h"

namespace {

const vgc_plugin_v1_table* g_reference = nullptr;

int crashing_apply(vgc_node* node, const char* line, const char** reason) {
  if (line && std::strncmp(line, "vertex_set_xyz_", 15) == 0) std::abort();
  return g_reference->apply(node, line, reason);
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const vgc_plugin_v1_table* vgc_plugin_v1(void) {
  static vgc_plugin_v1_table table;
  if (!g_reference) {
    g_reference = vgc::fuzz::reference_plugin_table(vgc::fuzz::PluginFault::None);
    table = *g_reference;
    table.name = "crashes on every vertex_set_xyz line";
    table.apply = crashing_apply;
  }
  return &table;
}
