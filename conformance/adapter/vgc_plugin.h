/* vgc_plugin.h — the C ABI of a vgc plugin (plugin:PATH), version 1.
 *
 * Spec: docs/adapters.md "plugin:PATH". A plugin is a shared library that
 * exports one function, vgc_plugin_v1(), returning a table of functions.
 * Commands and documents are the text forms of docs/commands.md, so a
 * plugin and an exec program answer alike. All strings are NUL-terminated
 * UTF-8/bytes; the plugin owns what it returns until the next call on the
 * same node. Plain C, no exceptions across the boundary.
 */
#ifndef VGC_PLUGIN_H
#define VGC_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define VGC_PLUGIN_ABI_VERSION 1u

typedef struct vgc_node vgc_node; /* opaque, the plugin's own */

/* Results of apply. */
#define VGC_APPLIED 1
#define VGC_REJECTED 0
#define VGC_MALFORMED (-1)
/* Processed, verdict not reported: the plugin does not say whether it
 * applied or dropped the command, as a host on the Verse wire, which sends
 * no acknowledgement and no error. vgc then judges from the snapshot
 * (docs/adapters.md "done answers"). Added in header revision 2 within ABI
 * version 1: a plugin that never returns it is unchanged, so the ABI
 * version stays 1; a vgc older than revision 2 reports it as a
 * protocol-error. */
#define VGC_DONE 2
#define VGC_PLUGIN_HEADER_REVISION 2u

typedef struct vgc_plugin_v1_table {
  uint32_t abi_version; /* VGC_PLUGIN_ABI_VERSION */
  const char* name;     /* e.g. "acme-host 2.3" */
  vgc_node* (*create)(void);
  void (*destroy)(vgc_node* node);
  /* One command line of the text language, without the newline. Returns
   * VGC_APPLIED, VGC_REJECTED (and sets *reason to a reason name such as
   * "NO_SUCH_LAYER"), VGC_DONE (verdict not reported; *reason unused), or
   * VGC_MALFORMED (and sets *reason to a message). */
  int (*apply)(vgc_node* node, const char* line, const char** reason);
  /* The snapshot and derived documents, each ending in "end\n". */
  const char* (*snapshot)(vgc_node* node);
  const char* (*derived)(vgc_node* node);
} vgc_plugin_v1_table;

/* Marks the entry point as exported even when the library is built with
 * -fvisibility=hidden:
 *   VGC_PLUGIN_EXPORT const vgc_plugin_v1_table* vgc_plugin_v1(void) { ... } */
#if defined(__GNUC__) || defined(__clang__)
#define VGC_PLUGIN_EXPORT __attribute__((visibility("default")))
#else
#define VGC_PLUGIN_EXPORT
#endif

/* The one symbol a plugin exports. */
typedef const vgc_plugin_v1_table* (*vgc_plugin_v1_fn)(void);
#define VGC_PLUGIN_ENTRY "vgc_plugin_v1"

/* Optional, ABI v1 stays valid without it: a plugin that offers the
 * optional capabilities (docs/adapters.md "Optional capabilities") also
 * exports
 *   VGC_PLUGIN_EXPORT const char* vgc_plugin_request_v1(vgc_node* node, const char* request_line);
 * answering "?capabilities", "?classify", "?subdivide <level>", "?normals"
 * (and the other requests of docs/adapters.md section 5) with the
 * whole document (ending in "end\n") or one line "error <message>\n".
 * Ownership as for snapshot. */
typedef const char* (*vgc_plugin_request_v1_fn)(vgc_node* node, const char* request_line);
#define VGC_PLUGIN_REQUEST_ENTRY "vgc_plugin_request_v1"

#ifdef __cplusplus
}
#endif

#endif /* VGC_PLUGIN_H */
