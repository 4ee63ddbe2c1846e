/* c_host.h — a Verse geometry node in C (Verse spec section 2.6), the
 * internal interface between its three files:
 *
 *   c_host_text.c    the text of one command line and of numbers and names
 *                    (vgc docs/commands.md sections 1 to 3)
 *   c_host_node.c    the node: layers, vertices, polygons, creases, bones
 *                    (commands.md sections 4 and 5) and its two documents
 *                    (commands.md section 6)
 *   c_host_plugin.c  the vgc plugin ABI v1 around it (vgc_plugin.h,
 *                    docs/adapters.md section 4)
 *
 * Reals are kept as their 64-bit IEEE-754 bit patterns (uint64_t), never
 * as computed doubles, so NaN payloads and -0 survive as sent.
 */
#ifndef C_HOST_H
#define C_HOST_H

#include <stddef.h>
#include <stdint.h>

/* ---- command lines (c_host_text.c) ---------------------------------- */

enum ch_verb {
  CH_LAYER_CREATE, CH_LAYER_DESTROY, CH_LAYER_SUBSCRIBE, CH_LAYER_UNSUBSCRIBE,
  CH_VERTEX_SET_XYZ_REAL32, CH_VERTEX_SET_XYZ_REAL64, CH_VERTEX_DELETE,
  CH_VERTEX_SET_UINT32, CH_VERTEX_SET_REAL64, CH_VERTEX_SET_REAL32,
  CH_POLYGON_SET_CORNER_UINT32, CH_POLYGON_SET_CORNER_REAL64, CH_POLYGON_SET_CORNER_REAL32,
  CH_POLYGON_DELETE, CH_POLYGON_SET_FACE_UINT8, CH_POLYGON_SET_FACE_UINT32,
  CH_POLYGON_SET_FACE_REAL64, CH_POLYGON_SET_FACE_REAL32,
  CH_CREASE_SET_VERTEX, CH_CREASE_SET_EDGE, CH_BONE_CREATE, CH_BONE_DESTROY,
  CH_VERB_COUNT
};

/* A name as sent: its length and up to 16 of its bytes. Only names of at
 * most 15 bytes without a NUL are valid (commands.md 4.1), so the rest is
 * never needed. */
typedef struct {
  size_t len;
  unsigned char bytes[16];
} ch_name;

#define CH_MAX_FIELDS 16

/* One parsed command: its verb and its fields in the order of commands.md
 * section 2. Integers are in value[i]; a real64 field holds its bit
 * pattern, a real32 field its 32-bit pattern (widened by the node); name
 * fields are in name[i]. */
typedef struct {
  enum ch_verb verb;
  uint64_t value[CH_MAX_FIELDS];
  ch_name name[CH_MAX_FIELDS];
} ch_command;

/* Parses one command line. Returns 1 and fills *cmd, or 0 and writes
 * "line 1, column N: <what was expected>" into error[error_size]. */
int ch_parse_command(const char* line, ch_command* cmd, char* error, size_t error_size);

/* Text of values (commands.md section 3). out must hold 32 bytes for a
 * real, 12 for an integer; a name needs 4 * len + 3. */
void ch_format_real64(uint64_t bits, char* out);
void ch_format_uint(uint64_t value, uint64_t all_ones, char* out);
void ch_format_name(const ch_name* name, char* out);

/* f32 bits to f64 bits as C's (double)f: exact, a signalling NaN quietened
 * with its payload kept (commands.md 4.5). */
uint64_t ch_widen_real32(uint32_t bits);

/* ---- the node (c_host_node.c) --------------------------------------- */

typedef struct ch_node ch_node;

ch_node* ch_node_create(void);
void ch_node_destroy(ch_node* node);
/* Applies one parsed command: returns NULL when applied, otherwise the
 * reason name of commands.md section 5 ("NO_SUCH_LAYER", ...). */
const char* ch_node_apply(ch_node* node, const ch_command* cmd);
/* The snapshot and derived documents (commands.md 6.1, 6.2), each ending in
 * "end\n"; the text is the node's until the next call on it. */
const char* ch_node_snapshot(ch_node* node);
const char* ch_node_derived(ch_node* node);

#endif /* C_HOST_H */
