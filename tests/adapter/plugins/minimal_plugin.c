/* minimal_plugin.c — the smallest plugin of the vgc plugin ABI v1 (the
 * example of docs/adapters.md, compiled and loaded by tests/adapter).
 *
 * A skeleton, not a conforming node: it stores nothing, so it rejects every
 * command with NO_SUCH_LAYER and its documents are those of a fresh node.
 * A real plugin parses the command line (docs/commands.md), applies it to
 * its host, and prints its state as the snapshot and derived documents.
 *
 * Build: cc -shared -fPIC -I<vgc>/conformance/adapter minimal_plugin.c -o libminimal.so
 * Run:   vgc certify --impl plugin:./libminimal.so
 */
#include <stdlib.h>
#include <string.h>

#include "vgc_plugin.h"

struct vgc_node {
  char reason[64]; /* the plugin owns what it returns: valid until the next call */
  unsigned long commands;
};

static vgc_node* create(void) { return calloc(1, sizeof(vgc_node)); }

static void destroy(vgc_node* node) { free(node); }

static int apply(vgc_node* node, const char* line, const char** reason) {
  node->commands++;
  if (line[0] == '\0') { /* not a command at all */
    strcpy(node->reason, "line 1, column 1: expected a command");
    *reason = node->reason;
    return VGC_MALFORMED;
  }
  strcpy(node->reason, "NO_SUCH_LAYER");
  *reason = node->reason;
  return VGC_REJECTED;
}

/* Static strings are fine too: they outlive every call. */
static const char* snapshot(vgc_node* node) {
  (void)node;
  return "vgc-snapshot 1\n"
         "layer 0 \"vertex\" VERTEX_XYZ - - -\n"
         "layer 1 \"polygon\" POLYGON_CORNER_UINT32 - - -\n"
         "crease_vertex \"\" 0\n"
         "crease_edge \"\" 0\n"
         "end\n";
}

static const char* derived(vgc_node* node) {
  (void)node;
  return "vgc-derived 1\nend\n";
}

static const vgc_plugin_v1_table table = {
    VGC_PLUGIN_ABI_VERSION, "minimal example plugin 1.0", create, destroy, apply, snapshot, derived,
};

VGC_PLUGIN_EXPORT const vgc_plugin_v1_table* vgc_plugin_v1(void) { return &table; }
