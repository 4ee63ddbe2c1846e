/* faulty_plugin.c — plugins with one deliberate fault each, for the tests of
 * the plugin route (tests/adapter/plugin_test.cpp). Built once per fault
 * with -DFAULT_<NAME>=1:
 *   FAULT_ABORT_ON_THIRD  abort() on the third command after create()
 *   FAULT_ABI_VERSION_2   the table says abi_version 2
 *   FAULT_NO_ENTRY        no vgc_plugin_v1 symbol is exported
 *   FAULT_BAD_REASON      rejects with the reason "NO SUCH LAYER" (not a token)
 *   FAULT_BAD_DOCUMENT    the snapshot does not end in a line "end"
 *   FAULT_ALL_DONE        not a fault: answers VGC_DONE (verdict not
 *                         reported) to every command, as a wire host would
 * Otherwise it behaves like minimal_plugin.c: every command is rejected
 * with NO_SUCH_LAYER; the documents are those of a fresh node.
 */
#include <stdlib.h>

#include "vgc_plugin.h"

struct vgc_node {
  int commands;
};

static vgc_node* create(void) { return calloc(1, sizeof(vgc_node)); }
static void destroy(vgc_node* node) { free(node); }

static int apply(vgc_node* node, const char* line, const char** reason) {
  (void)line;
  node->commands++;
#if FAULT_ABORT_ON_THIRD
  if (node->commands == 3) abort();
#endif
#if FAULT_ALL_DONE
  return VGC_DONE;
#endif
#if FAULT_BAD_REASON
  *reason = "NO SUCH LAYER";
#else
  *reason = "NO_SUCH_LAYER";
#endif
  return VGC_REJECTED;
}

static const char* snapshot(vgc_node* node) {
  (void)node;
#if FAULT_BAD_DOCUMENT
  return "vgc-snapshot 1\nlayer 0 \"vertex\" VERTEX_XYZ 0 0 -\n";
#else
  return "vgc-snapshot 1\n"
         "layer 0 \"vertex\" VERTEX_XYZ 0 0 -\n"
         "layer 1 \"polygon\" POLYGON_CORNER_UINT32 0 0 -\n"
         "crease_vertex \"\" 0\n"
         "crease_edge \"\" 0\n"
         "end\n";
#endif
}

static const char* derived(vgc_node* node) {
  (void)node;
  return "vgc-derived 1\nend\n";
}

static const vgc_plugin_v1_table table = {
#if FAULT_ABI_VERSION_2
    2u,
#else
    VGC_PLUGIN_ABI_VERSION,
#endif
    "faulty test plugin", create, destroy, apply, snapshot, derived,
};

#if FAULT_NO_ENTRY
VGC_PLUGIN_EXPORT const vgc_plugin_v1_table* vgc_plugin_v0(void) { return &table; }
#else
VGC_PLUGIN_EXPORT const vgc_plugin_v1_table* vgc_plugin_v1(void) { return &table; }
#endif
