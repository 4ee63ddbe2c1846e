/* c_host_plugin.c — the c_host node behind the vgc plugin ABI v1
 * (vgc_plugin.h; vgc docs/adapters.md section 4): parse the command line,
 * apply it, answer VGC_APPLIED, VGC_REJECTED with the reason name
 * (commands.md section 5) or VGC_MALFORMED with a message; print the two
 * documents on request. It exports no vgc_plugin_request_v1, so it claims
 * none of the optional capabilities (adapters.md section 5): vgc reports
 * those clauses not-claimed.
 */
#include <stdlib.h>

#include "c_host.h"
#include "vgc_plugin.h"

struct vgc_node {
  ch_node* node;
  char error[256]; /* the last VGC_MALFORMED message, the plugin's until the next call */
};

static vgc_node* create(void) {
  vgc_node* n = calloc(1, sizeof *n);
  if (n == NULL) return NULL;
  n->node = ch_node_create();
  if (n->node == NULL) {
    free(n);
    return NULL;
  }
  return n;
}

static void destroy(vgc_node* n) {
  if (n == NULL) return;
  ch_node_destroy(n->node);
  free(n);
}

static int apply(vgc_node* n, const char* line, const char** reason) {
  ch_command command;
  if (!ch_parse_command(line, &command, n->error, sizeof n->error)) {
    *reason = n->error;
    return VGC_MALFORMED;
  }
  const char* rejected = ch_node_apply(n->node, &command);
  if (rejected == NULL) return VGC_APPLIED;
  *reason = rejected; /* a static string */
  return VGC_REJECTED;
}

static const char* snapshot(vgc_node* n) { return ch_node_snapshot(n->node); }

static const char* derived(vgc_node* n) { return ch_node_derived(n->node); }

#ifdef C_HOST_FAULT_UNROTATED_CHILDREN
#define C_HOST_NAME "c_host example node 1.0 (seeded fault: unrotated children)"
#else
#define C_HOST_NAME "c_host example node 1.0"
#endif

static const vgc_plugin_v1_table table = {
    VGC_PLUGIN_ABI_VERSION, C_HOST_NAME, create, destroy, apply, snapshot, derived,
};

VGC_PLUGIN_EXPORT const vgc_plugin_v1_table* vgc_plugin_v1(void) { return &table; }
