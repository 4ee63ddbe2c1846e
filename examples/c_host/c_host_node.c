/* c_host_node.c — the geometry node: Verse spec section 2.6 as vgc
 * docs/commands.md sections 4 (node semantics: 4.1 names, 4.2 the wire
 * aliases, 4.3 picking ids, 4.4 layers, 4.5 vertices and polygons, 4.6
 * defaults, 4.7 creases, 4.8 bones, 4.9 the storage limit) and 5
 * (rejection reasons, first failing rule wins) state it, and the snapshot
 * and derived documents of section 6.
 *
 * Storage. Each stack (vertex, polygon) keeps its live element ids sorted,
 * each with a slot number; every layer of the stack is an array of slots
 * indexed by that number, so creating an element costs one slot per layer
 * and an id of four billion costs no more than id 0. Layers 0 and 1 are
 * layers like the others: layer 0's slots are the positions, layer 1's the
 * corners. Layers and bones are arrays sorted by id.
 *
 * Seeded fault (for the example's own test, off by default): compiled with
 * C_HOST_FAULT_UNROTATED_CHILDREN, a child bone's world position ignores its
 * parent's rotation (world_pos = parent's world_pos + pos), which breaks
 * clause BONE-DOWNSTREAM-1 (000 2.6.3: "all bones 'downstream' of it will
 * rotate, too"). With C_HOST_FAULT_SLOT_TAG_WRAP, an element created in a
 * slot whose 2-bit reuse tag wraps (the same slot reused a fourth time:
 * delete and create on it four times over) is never listed, so the vertex
 * or polygon just set is missing (VERTEX-SET-1, ...). The reference keeps
 * its elements in maps and has no slots, tags or branch for this; the node
 * has one per tag value (its reuse statistics): a fault that coverage of
 * this node, not of the reference, leads to (docs/fuzzing.md "Coverage of
 * the implementation"). With C_HOST_FAULT_COMBINE_FLUSH, the node's
 * write-combining buffer of vertex positions (a run of up to five writes in
 * a row to one vertex) loses the write that finds it full and flushes it:
 * the sixth write in a row to one vertex is not applied (VERTEX-SET-1). The
 * reference has no buffer and no run: nothing of its own coverage grows
 * along the run, while the node has a branch per run length 1..5 (its run
 * statistics), so guidance by the node's coverage leads there step by step
 * (docs/fuzzing.md "Does it pay? The C example host").
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c_host.h"

enum {
  VERTEX_XYZ = 0, VERTEX_UINT32 = 1, VERTEX_REAL = 2,
  POLYGON_CORNER_UINT32 = 128, POLYGON_CORNER_REAL = 129, POLYGON_FACE_UINT8 = 130,
  POLYGON_FACE_UINT32 = 131, POLYGON_FACE_REAL = 132
};
enum { VERTEX_STACK = 0, POLYGON_STACK = 1 };

#define NONE32 0xFFFFFFFFu /* "pick an id" / an unused corner / the maximum */
#define NONE16 0xFFFFu
#define FLT_MAX_BITS 0x7F7FFFFFull
#define DBL_MAX_BITS 0x7FEFFFFFFFFFFFFFull
#define MAX_CELLS_PER_STACK (1u << 22) /* 4.9 */
#define COMBINE_CAPACITY 5 /* writes in a row to one vertex the write-combining buffer holds */

/* ---- small helpers ----------------------------------------------------- */

static void* grow(void* p, size_t count, size_t size) {
  void* q = realloc(p, count * size);
  if (q == NULL && count != 0) {
    fputs("c_host: out of memory\n", stderr);
    abort();
  }
  return q;
}

static int is_finite_bits(uint64_t bits) { return (bits & 0x7FF0000000000000ull) != 0x7FF0000000000000ull; }

static double to_double(uint64_t bits) {
  double d;
  memcpy(&d, &bits, sizeof d);
  return d;
}

static uint64_t to_bits(double d) {
  uint64_t b;
  memcpy(&b, &d, sizeof b);
  return b;
}

static int layer_type_known(uint64_t t) { return t <= VERTEX_REAL || (t >= POLYGON_CORNER_UINT32 && t <= POLYGON_FACE_REAL); }
static int stack_of(uint8_t type) { return type < 128 ? VERTEX_STACK : POLYGON_STACK; }
static int is_real_type(uint8_t t) {
  return t == VERTEX_XYZ || t == VERTEX_REAL || t == POLYGON_CORNER_REAL || t == POLYGON_FACE_REAL;
}
static size_t components(uint8_t t) {
  return t == VERTEX_XYZ ? 3 : (t == POLYGON_CORNER_UINT32 || t == POLYGON_CORNER_REAL) ? 4 : 1;
}
static const char* type_name(uint8_t t) {
  switch (t) {
    case VERTEX_XYZ: return "VERTEX_XYZ";
    case VERTEX_UINT32: return "VERTEX_UINT32";
    case VERTEX_REAL: return "VERTEX_REAL";
    case POLYGON_CORNER_UINT32: return "POLYGON_CORNER_UINT32";
    case POLYGON_CORNER_REAL: return "POLYGON_CORNER_REAL";
    case POLYGON_FACE_UINT8: return "POLYGON_FACE_UINT8";
    case POLYGON_FACE_UINT32: return "POLYGON_FACE_UINT32";
    default: return "POLYGON_FACE_REAL";
  }
}

/* 4.1: at most 15 bytes, no NUL. */
static int name_valid(const ch_name* n) {
  return n->len <= 15 && memchr(n->bytes, '\0', n->len) == NULL;
}
static int name_equal(const ch_name* a, const ch_name* b) {
  return a->len == b->len && memcmp(a->bytes, b->bytes, a->len) == 0;
}

/* The lowest id from lo to hi that is not in the ascending ids[0..n), or
 * -1 (4.3). */
static int64_t lowest_free(const uint32_t* ids, size_t n, uint32_t lo, uint32_t hi) {
  uint64_t candidate = lo;
  for (size_t i = 0; i < n && ids[i] <= candidate; ++i)
    if (ids[i] == candidate) ++candidate;
  return candidate <= hi ? (int64_t)candidate : -1;
}

/* ---- the node's state -------------------------------------------------- */

typedef struct {
  uint16_t id;
  uint8_t type;
  ch_name name;
  uint32_t def_uint;
  uint64_t def_real;
  int subscription; /* -1 none, 0 REAL32, 1 REAL64 */
  uint64_t* slots;  /* components(type) values per slot; reals as bits */
  size_t capacity;  /* in slots */
} layer;

typedef struct {
  uint32_t* ids;   /* live element ids, ascending */
  uint32_t* slot;  /* slot[i]: the slot number of ids[i] */
  size_t count, capacity;
  uint32_t* free_slots; /* slot numbers of deleted elements, for reuse */
  size_t free_count, free_capacity;
  uint32_t slots_used; /* slot numbers handed out so far: 0 .. slots_used-1 */
  uint8_t* tag;        /* tag[slot]: the slot's reuses, 2 bits (the tag of the handles it gives out) */
  size_t tag_capacity;
  uint32_t reused[3];  /* reuses that gave a slot tag 1, 2, 3 (statistics) */
} stack;

typedef struct {
  uint16_t id, parent;
  ch_name weight, reference, pos_label, rot_label;
  uint64_t pos[3], rot[4];
} bone;

typedef struct {
  ch_name layer;
  uint32_t def_crease;
} crease_setting;

struct ch_node {
  layer* layers; /* ascending id; layers 0 and 1 always present */
  size_t layer_count, layer_capacity;
  stack stacks[2];
  crease_setting crease_vertex, crease_edge;
  bone* bones; /* ascending id */
  size_t bone_count, bone_capacity;
  /* The write-combining buffer of vertex positions: a run of writes in a
   * row to one vertex (combine_slot) is combined, combine_run of them so far
   * (0: the buffer is empty); combine_at is the command that wrote last
   * (commands counts the commands applied). Statistics: writes combined at
   * each run length 1..COMBINE_CAPACITY (a case per length), flushes.
   * (This example stores every write at once and only counts the runs, as
   * a host that defers the store to the end of a run would count them.) */
  uint64_t commands, combine_at;
  uint32_t combine_slot;
  unsigned combine_run;
  uint32_t run1, run2, run3, run4, run5, flushes;
  char* text; /* the last document printed */
  size_t text_len, text_capacity;
};

/* ---- layers ------------------------------------------------------------ */

static layer* find_layer(ch_node* node, uint32_t id) {
  size_t lo = 0, hi = node->layer_count;
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    if (node->layers[mid].id < id)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < node->layer_count && node->layers[lo].id == id ? &node->layers[lo] : NULL;
}

static layer* find_layer_by_name(ch_node* node, const ch_name* name) {
  for (size_t i = 0; i < node->layer_count; ++i)
    if (name_equal(&node->layers[i].name, name)) return &node->layers[i];
  return NULL;
}

static size_t layers_in_stack(const ch_node* node, int s) {
  size_t n = 0;
  for (size_t i = 0; i < node->layer_count; ++i) n += stack_of(node->layers[i].type) == s;
  return n;
}

/* 4.6: every uint component takes def_uint (a FACE_UINT8 layer its low 8
 * bits), every real component def_real. */
static void set_default(layer* l, uint32_t slot) {
  const size_t c = components(l->type);
  const uint64_t value = is_real_type(l->type) ? l->def_real
                         : l->type == POLYGON_FACE_UINT8 ? (l->def_uint & 0xFFu)
                                                         : l->def_uint;
  for (size_t k = 0; k < c; ++k) l->slots[slot * c + k] = value;
}

static void reserve_slots(layer* l, size_t slots) {
  if (l->capacity >= slots) return;
  size_t capacity = l->capacity ? l->capacity * 2 : 16;
  if (capacity < slots) capacity = slots;
  l->slots = grow(l->slots, capacity * components(l->type), sizeof(uint64_t));
  l->capacity = capacity;
}

/* Gives l one slot, holding its default, for every live element of its stack. */
static void fill_layer(ch_node* node, layer* l) {
  const stack* s = &node->stacks[stack_of(l->type)];
  reserve_slots(l, s->slots_used);
  for (size_t i = 0; i < s->count; ++i) set_default(l, s->slot[i]);
}

static layer* insert_layer(ch_node* node, uint16_t id) {
  if (node->layer_count == node->layer_capacity) {
    node->layer_capacity = node->layer_capacity ? node->layer_capacity * 2 : 8;
    node->layers = grow(node->layers, node->layer_capacity, sizeof(layer));
  }
  size_t at = 0;
  while (at < node->layer_count && node->layers[at].id < id) ++at;
  memmove(&node->layers[at + 1], &node->layers[at], (node->layer_count - at) * sizeof(layer));
  node->layer_count++;
  layer* l = &node->layers[at];
  memset(l, 0, sizeof *l);
  l->id = id;
  l->subscription = -1;
  return l;
}

/* ---- elements ---------------------------------------------------------- */

/* Index of id in the stack's ids, or -1; *at is where it would go. */
static int64_t find_element(const stack* s, uint32_t id, size_t* at) {
  size_t lo = 0, hi = s->count;
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    if (s->ids[mid] < id)
      lo = mid + 1;
    else
      hi = mid;
  }
  if (at) *at = lo;
  return lo < s->count && s->ids[lo] == id ? (int64_t)lo : -1;
}

static uint64_t* element_slot(ch_node* node, layer* l, uint32_t element) {
  const stack* s = &node->stacks[stack_of(l->type)];
  const int64_t i = find_element(s, element, NULL);
  return i < 0 ? NULL : &l->slots[s->slot[i] * components(l->type)];
}

/* Creates element id in stack sn: a slot with its default in every layer. */
static uint32_t add_element(ch_node* node, int sn, uint32_t id) {
  stack* s = &node->stacks[sn];
  size_t at;
  find_element(s, id, &at);
  if (s->count == s->capacity) {
    s->capacity = s->capacity ? s->capacity * 2 : 16;
    s->ids = grow(s->ids, s->capacity, sizeof(uint32_t));
    s->slot = grow(s->slot, s->capacity, sizeof(uint32_t));
  }
  uint32_t slot;
  if (s->free_count) { /* the slot of the element deleted last; its tag counts the reuse */
    slot = s->free_slots[--s->free_count];
    const uint8_t tag = (uint8_t)((s->tag[slot] + 1) & 3);
    s->tag[slot] = tag;
    if (tag == 1)
      s->reused[0]++;
    else if (tag == 2)
      s->reused[1]++;
    else if (tag == 3)
      s->reused[2]++;
    else { /* the tag wrapped: the slot's fourth reuse */
#ifdef C_HOST_FAULT_SLOT_TAG_WRAP
      return slot; /* the seeded fault: a handle of tag 0 reads as dead, the element is never listed */
#endif
    }
  } else {
    slot = s->slots_used++;
    if (slot >= s->tag_capacity) {
      s->tag_capacity = s->tag_capacity ? s->tag_capacity * 2 : 16;
      s->tag = grow(s->tag, s->tag_capacity, 1);
    }
    s->tag[slot] = 0;
  }
  memmove(&s->ids[at + 1], &s->ids[at], (s->count - at) * sizeof(uint32_t));
  memmove(&s->slot[at + 1], &s->slot[at], (s->count - at) * sizeof(uint32_t));
  s->ids[at] = id;
  s->slot[at] = slot;
  s->count++;
  for (size_t i = 0; i < node->layer_count; ++i) {
    layer* l = &node->layers[i];
    if (stack_of(l->type) != sn) continue;
    reserve_slots(l, s->slots_used);
    set_default(l, slot);
  }
  return slot;
}

static void remove_element(ch_node* node, int sn, size_t index) {
  stack* s = &node->stacks[sn];
  if (s->free_count == s->free_capacity) {
    s->free_capacity = s->free_capacity ? s->free_capacity * 2 : 16;
    s->free_slots = grow(s->free_slots, s->free_capacity, sizeof(uint32_t));
  }
  s->free_slots[s->free_count++] = s->slot[index];
  memmove(&s->ids[index], &s->ids[index + 1], (s->count - index - 1) * sizeof(uint32_t));
  memmove(&s->slot[index], &s->slot[index + 1], (s->count - index - 1) * sizeof(uint32_t));
  s->count--;
}

/* ---- bones ------------------------------------------------------------- */

static bone* find_bone(ch_node* node, uint32_t id) {
  for (size_t i = 0; i < node->bone_count; ++i)
    if (node->bones[i].id == id) return &node->bones[i];
  return NULL;
}

/* ---- commands (4.4 to 4.8) --------------------------------------------- */

static const char* layer_destroy(ch_node* node, uint64_t id) {
  if (id == 0 || id == 1) return "BASE_LAYER";
  layer* l = find_layer(node, (uint32_t)id);
  if (l == NULL) return "NO_SUCH_LAYER";
  free(l->slots);
  const size_t at = (size_t)(l - node->layers);
  memmove(l, l + 1, (node->layer_count - at - 1) * sizeof(layer));
  node->layer_count--;
  return NULL;
}

static const char* layer_create(ch_node* node, const ch_command* c) {
  uint64_t id = c->value[0];
  const ch_name* name = &c->name[1];
  const uint64_t type = c->value[2];
  if (name->len == 0) return layer_destroy(node, id); /* 4.2 */
  if (id == 0 || id == 1) return "BASE_LAYER";
  if (!layer_type_known(type)) return "BAD_LAYER_TYPE";
  if (!name_valid(name)) return "BAD_NAME";
  const layer* same_name = find_layer_by_name(node, name);
  if (same_name && same_name->id != id) return "NAME_IN_USE";
  if (id == NONE16) { /* 4.3: the lowest free id from 2 */
    id = 2;
    for (size_t i = 0; i < node->layer_count && node->layers[i].id <= id; ++i)
      if (node->layers[i].id == id) ++id;
    if (id > 0xFFFE) return "NO_FREE_ID";
  }
  layer* l = find_layer(node, (uint32_t)id);
  const int target = stack_of((uint8_t)type);
  if (l == NULL || stack_of(l->type) != target) { /* 4.9 */
    const size_t elements = node->stacks[target].count ? node->stacks[target].count : 1;
    if ((layers_in_stack(node, target) + 1) * elements > MAX_CELLS_PER_STACK) return "LIMIT";
  }
  const int retype = l == NULL || l->type != type;
  if (l == NULL) l = insert_layer(node, (uint16_t)id);
  l->name = *name;
  l->def_uint = (uint32_t)c->value[3];
  l->def_real = c->value[4];
  if (retype) { /* new, or re-typed: every slot takes the new default */
    free(l->slots);
    l->slots = NULL;
    l->capacity = 0;
    l->type = (uint8_t)type;
    l->subscription = -1;
    fill_layer(node, l);
  }
  return NULL;
}

static const char* layer_subscribe(ch_node* node, uint64_t id, int64_t format) {
  layer* l = find_layer(node, (uint32_t)id);
  if (l == NULL) return "NO_SUCH_LAYER";
  l->subscription = format > 1 ? -1 : (int)format; /* 4.2: above REAL64 unsubscribes */
  return NULL;
}

/* A write to one slot of a non-base layer (4.5, "Slot writes"). */
static const char* write_slot(ch_node* node, uint64_t layer_id, uint64_t element, uint8_t type,
                              const uint64_t* values) {
  layer* l = find_layer(node, (uint32_t)layer_id);
  if (l == NULL) return "NO_SUCH_LAYER";
  if (l->type != type) return "WRONG_LAYER_TYPE";
  uint64_t* slot = element_slot(node, l, (uint32_t)element);
  if (slot == NULL) return stack_of(type) == VERTEX_STACK ? "NO_SUCH_VERTEX" : "NO_SUCH_POLYGON";
  memcpy(slot, values, components(type) * sizeof(uint64_t));
  return NULL;
}

static const char* polygon_delete(ch_node* node, uint64_t id) {
  const int64_t i = find_element(&node->stacks[POLYGON_STACK], (uint32_t)id, NULL);
  if (i < 0) return "NO_SUCH_POLYGON";
  remove_element(node, POLYGON_STACK, (size_t)i);
  return NULL;
}

static const char* vertex_delete(ch_node* node, uint64_t id) {
  stack* vertices = &node->stacks[VERTEX_STACK];
  const int64_t i = find_element(vertices, (uint32_t)id, NULL);
  if (i < 0) return "NO_SUCH_VERTEX";
  /* every polygon using the vertex goes first, so live polygons always
   * name live vertices */
  stack* polygons = &node->stacks[POLYGON_STACK];
  const layer* corners = find_layer(node, 1);
  for (size_t p = polygons->count; p-- > 0;) {
    const uint64_t* v = &corners->slots[polygons->slot[p] * 4];
    if (v[0] == id || v[1] == id || v[2] == id || v[3] == id) remove_element(node, POLYGON_STACK, p);
  }
  remove_element(node, VERTEX_STACK, (size_t)i);
  return NULL;
}

/* Creating an element (4.5 step "a new vertex/polygon"): LIMIT, then a slot
 * in every layer of the stack; returns the base layer's slot values. */
static uint64_t* new_element(ch_node* node, int sn, uint32_t id, const char** reason) {
  if ((node->stacks[sn].count + 1) * layers_in_stack(node, sn) > MAX_CELLS_PER_STACK) {
    *reason = "LIMIT";
    return NULL;
  }
  const uint32_t slot = add_element(node, sn, id);
  layer* base = find_layer(node, (uint32_t)sn);
  return &base->slots[slot * components(base->type)];
}

/* Combines a write to the position in `slot` with the writes to it just
 * before it (no other command between) and says whether it is applied. The
 * buffer combines up to COMBINE_CAPACITY writes; the next write in the run
 * finds it full, flushes it and starts the next run. With
 * C_HOST_FAULT_COMBINE_FLUSH the flush loses the write that made it (the
 * sixth write in a row to one vertex: the seeded fault). */
static int combine_write(ch_node* node, uint32_t slot) {
  if (node->combine_at + 1 != node->commands || node->combine_slot != slot) node->combine_run = 0;
  node->combine_at = node->commands;
  node->combine_slot = slot;
  const unsigned run = ++node->combine_run;
  if (run == 1)
    node->run1++;
  else if (run == 2)
    node->run2 += 2;
  else if (run == 3)
    node->run3 += 3;
  else if (run == 4)
    node->run4 += 4;
  else if (run == COMBINE_CAPACITY)
    node->run5 += COMBINE_CAPACITY;
  else { /* full: flushed; this write starts the next run */
    node->combine_run = 0;
    node->flushes++;
#ifdef C_HOST_FAULT_COMBINE_FLUSH
    return 0;
#endif
  }
  return 1;
}

static const char* vertex_set_xyz(ch_node* node, uint64_t layer_id, uint64_t id, const uint64_t xyz[3]) {
  if (layer_id != 0) return write_slot(node, layer_id, id, VERTEX_XYZ, xyz);
  for (int k = 0; k < 3; ++k)
    if (!is_finite_bits(xyz[k])) return "BAD_VALUE";
  stack* s = &node->stacks[VERTEX_STACK];
  if (id == NONE32) {
    const int64_t picked = lowest_free(s->ids, s->count, 0, 0xFFFFFFFE);
    if (picked < 0) return "NO_FREE_ID";
    id = (uint64_t)picked;
  }
  uint64_t* position = element_slot(node, find_layer(node, 0), (uint32_t)id);
  const char* reason = NULL;
  if (position == NULL)
    position = new_element(node, VERTEX_STACK, (uint32_t)id, &reason);
  else if (!combine_write(node, s->slot[find_element(s, (uint32_t)id, NULL)]))
    return NULL;
  if (reason) return reason;
  memcpy(position, xyz, 3 * sizeof(uint64_t));
  return NULL;
}

static const char* polygon_set_corners(ch_node* node, const ch_command* c) {
  const uint64_t layer_id = c->value[0];
  uint64_t id = c->value[1];
  const uint64_t* v = &c->value[2];
  if (layer_id != 1) return write_slot(node, layer_id, id, POLYGON_CORNER_UINT32, v);
  if (v[0] == NONE32) return polygon_delete(node, id); /* 4.2 */
  if (v[1] == NONE32 || v[2] == NONE32) return "BAD_POLYGON";
  const int n = v[3] == NONE32 ? 3 : 4;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      if (v[a] == v[b]) return "BAD_POLYGON";
  for (int a = 0; a < n; ++a)
    if (find_element(&node->stacks[VERTEX_STACK], (uint32_t)v[a], NULL) < 0) return "NO_SUCH_VERTEX";
  stack* s = &node->stacks[POLYGON_STACK];
  if (id == NONE32) {
    const int64_t picked = lowest_free(s->ids, s->count, 0, 0xFFFFFFFE);
    if (picked < 0) return "NO_FREE_ID";
    id = (uint64_t)picked;
  }
  uint64_t* corners = element_slot(node, find_layer(node, 1), (uint32_t)id);
  const char* reason = NULL;
  if (corners == NULL) corners = new_element(node, POLYGON_STACK, (uint32_t)id, &reason);
  if (reason) return reason;
  memcpy(corners, v, 4 * sizeof(uint64_t));
  return NULL;
}

static const char* bone_destroy(ch_node* node, uint64_t id) {
  bone* b = find_bone(node, (uint32_t)id);
  if (b == NULL) return "NO_SUCH_BONE";
  const size_t at = (size_t)(b - node->bones);
  memmove(b, b + 1, (node->bone_count - at - 1) * sizeof(bone));
  node->bone_count--;
  return NULL;
}

static const char* bone_create(ch_node* node, const ch_command* c) {
  uint64_t id = c->value[0];
  const ch_name *weight = &c->name[1], *reference = &c->name[2], *pos_label = &c->name[7],
                *rot_label = &c->name[12];
  if (weight->len == 0) return bone_destroy(node, id); /* 4.2 */
  if (!name_valid(weight) || !name_valid(reference) || !name_valid(pos_label) || !name_valid(rot_label))
    return "BAD_NAME";
  const uint64_t pos[3] = {c->value[4], c->value[5], c->value[6]};
  const uint64_t rot[4] = {c->value[8], c->value[9], c->value[10], c->value[11]};
  int all_zero = 1;
  for (int k = 0; k < 3; ++k)
    if (!is_finite_bits(pos[k])) return "BAD_VALUE";
  for (int k = 0; k < 4; ++k) {
    if (!is_finite_bits(rot[k])) return "BAD_VALUE";
    if ((rot[k] << 1) != 0) all_zero = 0; /* +0 and -0 are zero */
  }
  if (all_zero) return "BAD_VALUE";
  const layer* w = find_layer_by_name(node, weight);
  if (w == NULL || (w->type != VERTEX_UINT32 && w->type != VERTEX_REAL)) return "BAD_WEIGHT_LAYER";
  if (reference->len != 0) {
    const layer* r = find_layer_by_name(node, reference);
    if (r == NULL || r->type != VERTEX_UINT32) return "BAD_REFERENCE_LAYER";
  }
  if (id == NONE16) { /* 4.3: the lowest free id from 0 */
    id = 0;
    for (size_t i = 0; i < node->bone_count && node->bones[i].id <= id; ++i)
      if (node->bones[i].id == id) ++id;
    if (id > 0xFFFE) return "NO_FREE_ID";
  }
  /* BONE_CYCLE: walk up from the new parent through existing bones */
  uint32_t walk = (uint32_t)c->value[3];
  for (size_t steps = 0; steps <= node->bone_count; ++steps) {
    if (walk == id) return "BONE_CYCLE";
    const bone* up = find_bone(node, walk);
    if (up == NULL) break;
    walk = up->parent;
  }
  bone* b = find_bone(node, (uint32_t)id);
  if (b == NULL) {
    if (node->bone_count == node->bone_capacity) {
      node->bone_capacity = node->bone_capacity ? node->bone_capacity * 2 : 8;
      node->bones = grow(node->bones, node->bone_capacity, sizeof(bone));
    }
    size_t at = 0;
    while (at < node->bone_count && node->bones[at].id < id) ++at;
    memmove(&node->bones[at + 1], &node->bones[at], (node->bone_count - at) * sizeof(bone));
    node->bone_count++;
    b = &node->bones[at];
  }
  b->id = (uint16_t)id;
  b->parent = (uint16_t)c->value[3];
  b->weight = *weight;
  b->reference = *reference;
  b->pos_label = *pos_label;
  b->rot_label = *rot_label;
  memcpy(b->pos, pos, sizeof pos);
  memcpy(b->rot, rot, sizeof rot);
  return NULL;
}

static const char* crease_set(crease_setting* setting, const ch_command* c) {
  if (!name_valid(&c->name[0])) return "BAD_NAME";
  setting->layer = c->name[0];
  setting->def_crease = (uint32_t)c->value[1];
  return NULL;
}

const char* ch_node_apply(ch_node* node, const ch_command* c) {
  const uint64_t* v = c->value;
  uint64_t widened[4];
  node->commands++;
  switch (c->verb) {
    case CH_LAYER_CREATE: return layer_create(node, c);
    case CH_LAYER_DESTROY: return layer_destroy(node, v[0]);
    case CH_LAYER_SUBSCRIBE: return layer_subscribe(node, v[0], (int64_t)v[1]);
    case CH_LAYER_UNSUBSCRIBE: return layer_subscribe(node, v[0], 2);
    case CH_VERTEX_SET_XYZ_REAL32:
      if (v[2] == FLT_MAX_BITS || v[3] == FLT_MAX_BITS || v[4] == FLT_MAX_BITS) return vertex_delete(node, v[1]);
      for (int k = 0; k < 3; ++k) widened[k] = ch_widen_real32((uint32_t)v[2 + k]);
      return vertex_set_xyz(node, v[0], v[1], widened);
    case CH_VERTEX_SET_XYZ_REAL64:
      if (v[2] == DBL_MAX_BITS || v[3] == DBL_MAX_BITS || v[4] == DBL_MAX_BITS) return vertex_delete(node, v[1]);
      return vertex_set_xyz(node, v[0], v[1], &v[2]);
    case CH_VERTEX_DELETE: return vertex_delete(node, v[0]);
    case CH_VERTEX_SET_UINT32: return write_slot(node, v[0], v[1], VERTEX_UINT32, &v[2]);
    case CH_VERTEX_SET_REAL64: return write_slot(node, v[0], v[1], VERTEX_REAL, &v[2]);
    case CH_VERTEX_SET_REAL32:
      widened[0] = ch_widen_real32((uint32_t)v[2]);
      return write_slot(node, v[0], v[1], VERTEX_REAL, widened);
    case CH_POLYGON_SET_CORNER_UINT32: return polygon_set_corners(node, c);
    case CH_POLYGON_SET_CORNER_REAL64: return write_slot(node, v[0], v[1], POLYGON_CORNER_REAL, &v[2]);
    case CH_POLYGON_SET_CORNER_REAL32:
      for (int k = 0; k < 4; ++k) widened[k] = ch_widen_real32((uint32_t)v[2 + k]);
      return write_slot(node, v[0], v[1], POLYGON_CORNER_REAL, widened);
    case CH_POLYGON_DELETE: return polygon_delete(node, v[0]);
    case CH_POLYGON_SET_FACE_UINT8: return write_slot(node, v[0], v[1], POLYGON_FACE_UINT8, &v[2]);
    case CH_POLYGON_SET_FACE_UINT32: return write_slot(node, v[0], v[1], POLYGON_FACE_UINT32, &v[2]);
    case CH_POLYGON_SET_FACE_REAL64: return write_slot(node, v[0], v[1], POLYGON_FACE_REAL, &v[2]);
    case CH_POLYGON_SET_FACE_REAL32:
      widened[0] = ch_widen_real32((uint32_t)v[2]);
      return write_slot(node, v[0], v[1], POLYGON_FACE_REAL, widened);
    case CH_CREASE_SET_VERTEX: return crease_set(&node->crease_vertex, c);
    case CH_CREASE_SET_EDGE: return crease_set(&node->crease_edge, c);
    case CH_BONE_CREATE: return bone_create(node, c);
    case CH_BONE_DESTROY: return bone_destroy(node, v[0]);
    default: return "NOT_A_COMMAND";
  }
}

/* ---- the node's life --------------------------------------------------- */

ch_node* ch_node_create(void) {
  ch_node* node = calloc(1, sizeof *node);
  if (node == NULL) return NULL;
  /* 4: layer 0 "vertex" VERTEX_XYZ and layer 1 "polygon"
   * POLYGON_CORNER_UINT32, always present; creases ("", 0) (4.7) */
  layer* l = insert_layer(node, 0);
  l->type = VERTEX_XYZ;
  l->name.len = 6;
  memcpy(l->name.bytes, "vertex", 6);
  l = insert_layer(node, 1);
  l->type = POLYGON_CORNER_UINT32;
  l->name.len = 7;
  memcpy(l->name.bytes, "polygon", 7);
  return node;
}

void ch_node_destroy(ch_node* node) {
  if (node == NULL) return;
  for (size_t i = 0; i < node->layer_count; ++i) free(node->layers[i].slots);
  free(node->layers);
  for (int s = 0; s < 2; ++s) {
    free(node->stacks[s].ids);
    free(node->stacks[s].slot);
    free(node->stacks[s].free_slots);
    free(node->stacks[s].tag);
  }
  free(node->bones);
  free(node->text);
  free(node);
}

/* ---- documents (section 6) --------------------------------------------- */

static void put(ch_node* node, const char* format, ...) {
  for (;;) {
    va_list args;
    va_start(args, format);
    const size_t room = node->text_capacity - node->text_len;
    const int n = vsnprintf(node->text + node->text_len, room, format, args);
    va_end(args);
    if (n >= 0 && (size_t)n < room) {
      node->text_len += (size_t)n;
      return;
    }
    node->text_capacity = node->text_capacity * 2 + (size_t)n + 256;
    node->text = grow(node->text, node->text_capacity, 1);
  }
}

static void start_document(ch_node* node, const char* header) {
  node->text_len = 0;
  if (node->text_capacity == 0) {
    node->text_capacity = 4096;
    node->text = grow(NULL, node->text_capacity, 1);
  }
  put(node, "%s\n", header);
}

/* Appends " <value>" for each component of one slot of l. */
static void put_slot_values(ch_node* node, const layer* l, const uint64_t* values) {
  char text[64];
  for (size_t k = 0; k < components(l->type); ++k) {
    if (is_real_type(l->type))
      ch_format_real64(values[k], text);
    else
      ch_format_uint(values[k], l->type == POLYGON_FACE_UINT8 ? 0xFF : NONE32, text);
    put(node, " %s", text);
  }
}

const char* ch_node_snapshot(ch_node* node) {
  char a[40], b[40], id[40], name[80];
  start_document(node, "vgc-snapshot 1");
  for (size_t i = 0; i < node->layer_count; ++i) {
    const layer* l = &node->layers[i];
    /* only the default the type uses; none for the base layers (6.1) */
    strcpy(a, "-");
    strcpy(b, "-");
    if (l->id > 1) {
      if (is_real_type(l->type))
        ch_format_real64(l->def_real, b);
      else
        ch_format_uint(l->type == POLYGON_FACE_UINT8 ? (l->def_uint & 0xFFu) : l->def_uint, NONE32, a);
    }
    ch_format_name(&l->name, name);
    ch_format_uint(l->id, NONE16, id);
    put(node, "layer %s %s %s %s %s %s\n", id, name, type_name(l->type), a, b,
        l->subscription < 0 ? "-" : l->subscription == 0 ? "REAL32" : "REAL64");
  }
  ch_format_name(&node->crease_vertex.layer, name);
  ch_format_uint(node->crease_vertex.def_crease, NONE32, a);
  put(node, "crease_vertex %s %s\n", name, a);
  ch_format_name(&node->crease_edge.layer, name);
  ch_format_uint(node->crease_edge.def_crease, NONE32, a);
  put(node, "crease_edge %s %s\n", name, a);
  /* vertex lines, polygon lines, then slot lines of every other layer */
  for (int pass = 0; pass < 2; ++pass) {
    const layer* base = find_layer(node, (uint32_t)pass);
    const stack* s = &node->stacks[pass];
    for (size_t e = 0; e < s->count; ++e) {
      ch_format_uint(s->ids[e], NONE32, a);
      put(node, "%s %s", pass == 0 ? "vertex" : "polygon", a);
      put_slot_values(node, base, &base->slots[s->slot[e] * components(base->type)]);
      put(node, "\n");
    }
  }
  for (size_t i = 0; i < node->layer_count; ++i) {
    const layer* l = &node->layers[i];
    if (l->id <= 1) continue;
    const stack* s = &node->stacks[stack_of(l->type)];
    ch_format_uint(l->id, NONE16, b);
    for (size_t e = 0; e < s->count; ++e) {
      ch_format_uint(s->ids[e], NONE32, a);
      put(node, "slot %s %s", b, a);
      put_slot_values(node, l, &l->slots[s->slot[e] * components(l->type)]);
      put(node, "\n");
    }
  }
  for (size_t i = 0; i < node->bone_count; ++i) {
    const bone* bn = &node->bones[i];
    char reals[7][32];
    for (int k = 0; k < 3; ++k) ch_format_real64(bn->pos[k], reals[k]);
    for (int k = 0; k < 4; ++k) ch_format_real64(bn->rot[k], reals[3 + k]);
    ch_format_uint(bn->id, NONE16, a);
    ch_format_uint(bn->parent, NONE16, b);
    ch_format_name(&bn->weight, name);
    put(node, "bone %s %s", a, name);
    ch_format_name(&bn->reference, name);
    put(node, " %s %s %s %s %s", name, b, reals[0], reals[1], reals[2]);
    ch_format_name(&bn->pos_label, name);
    put(node, " %s %s %s %s %s", name, reals[3], reals[4], reals[5], reals[6]);
    ch_format_name(&bn->rot_label, name);
    put(node, " %s\n", name);
  }
  put(node, "end\n");
  return node->text;
}

/* ---- bone poses (4.8): quaternions (x, y, z, w), Hamilton product ------ */

typedef struct {
  double x, y, z, w;
} quat;

static quat quat_mul(quat a, quat b) {
  return (quat){a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
                a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

/* Scaled as hypot scales: by the largest |component| first, so tiny and
 * huge quaternions are the rotations they are; w made >= 0. */
static quat quat_normalize(quat q) {
  double m = fabs(q.x);
  if (fabs(q.y) > m) m = fabs(q.y);
  if (fabs(q.z) > m) m = fabs(q.z);
  if (fabs(q.w) > m) m = fabs(q.w);
  if (!(m > 0) || !isfinite(m)) return (quat){0, 0, 0, 1};
  quat r = {q.x / m, q.y / m, q.z / m, q.w / m};
  const double n = sqrt(r.x * r.x + r.y * r.y + r.z * r.z + r.w * r.w);
  r = (quat){r.x / n, r.y / n, r.z / n, r.w / n};
  if (q.w < 0) r = (quat){-r.x, -r.y, -r.z, -r.w};
  return r;
}

static void quat_rotate(quat q, const double v[3], double out[3]) {
  const quat p = quat_mul(quat_mul(q, (quat){v[0], v[1], v[2], 0}), (quat){-q.x, -q.y, -q.z, q.w});
  out[0] = p.x;
  out[1] = p.y;
  out[2] = p.z;
}

typedef struct {
  int done;
  double pos[3];
  quat rot;
} pose;

/* World pose of bone i: parent's first (the bones form a forest). */
static void compute_pose(ch_node* node, size_t i, pose* poses) {
  size_t chain_len = 0;
  size_t* chain = grow(NULL, node->bone_count + 1, sizeof(size_t));
  size_t cur = i;
  for (;;) { /* up to the first bone whose pose is known or a root */
    chain[chain_len++] = cur;
    const bone* parent = find_bone(node, node->bones[cur].parent);
    if (parent == NULL || parent == &node->bones[cur] || poses[parent - node->bones].done ||
        chain_len > node->bone_count)
      break;
    cur = (size_t)(parent - node->bones);
  }
  while (chain_len > 0) {
    const size_t k = chain[--chain_len];
    const bone* b = &node->bones[k];
    const double local[3] = {to_double(b->pos[0]), to_double(b->pos[1]), to_double(b->pos[2])};
    const quat rot = quat_normalize(
        (quat){to_double(b->rot[0]), to_double(b->rot[1]), to_double(b->rot[2]), to_double(b->rot[3])});
    const bone* parent = find_bone(node, b->parent);
    pose* p = &poses[k];
    if (parent != NULL && parent != b && poses[parent - node->bones].done) {
      const pose* pp = &poses[parent - node->bones];
      double d[3];
#ifdef C_HOST_FAULT_UNROTATED_CHILDREN
      const quat frame = {0, 0, 0, 1}; /* the seeded fault: the parent's rotation forgotten */
#else
      const quat frame = pp->rot;
#endif
      quat_rotate(frame, local, d);
      for (int a = 0; a < 3; ++a) p->pos[a] = pp->pos[a] + d[a];
      p->rot = quat_normalize(quat_mul(pp->rot, rot));
    } else {
      memcpy(p->pos, local, sizeof local);
      p->rot = rot;
    }
    p->done = 1;
  }
  free(chain);
}

/* 4.7: the layer a crease setting names, when it has the type it needs. */
static const layer* crease_layer(ch_node* node, const crease_setting* s, uint8_t type) {
  if (s->layer.len == 0) return NULL;
  const layer* l = find_layer_by_name(node, &s->layer);
  return l != NULL && l->type == type ? l : NULL;
}

const char* ch_node_derived(ch_node* node) {
  char a[40], b[40];
  start_document(node, "vgc-derived 1");
  const stack* vertices = &node->stacks[VERTEX_STACK];
  const layer* vl = crease_layer(node, &node->crease_vertex, VERTEX_UINT32);
  for (size_t e = 0; e < vertices->count; ++e) {
    ch_format_uint(vertices->ids[e], NONE32, a);
    ch_format_uint(vl ? vl->slots[vertices->slot[e]] : node->crease_vertex.def_crease, NONE32, b);
    put(node, "vertex_crease %s %s\n", a, b);
  }
  const stack* polygons = &node->stacks[POLYGON_STACK];
  const layer* corners = find_layer(node, 1);
  const layer* el = crease_layer(node, &node->crease_edge, POLYGON_CORNER_UINT32);
  for (size_t e = 0; e < polygons->count; ++e) {
    const uint32_t slot = polygons->slot[e];
    const int n = corners->slots[slot * 4 + 3] == NONE32 ? 3 : 4;
    ch_format_uint(polygons->ids[e], NONE32, a);
    for (int k = 0; k < n; ++k) { /* corner k: the edge from corner k to k+1 */
      ch_format_uint(el ? el->slots[slot * 4 + (size_t)k] : node->crease_edge.def_crease, NONE32, b);
      put(node, "edge_crease %s %d %s\n", a, k, b);
    }
  }
  if (node->bone_count > 0) {
    pose* poses = grow(NULL, node->bone_count, sizeof(pose));
    memset(poses, 0, node->bone_count * sizeof(pose));
    for (size_t i = 0; i < node->bone_count; ++i) {
      if (!poses[i].done) compute_pose(node, i, poses);
      const pose* p = &poses[i];
      const double numbers[7] = {p->pos[0], p->pos[1], p->pos[2], p->rot.x, p->rot.y, p->rot.z, p->rot.w};
      ch_format_uint(node->bones[i].id, NONE16, a);
      put(node, "bone_pose %s", a);
      for (int k = 0; k < 7; ++k) {
        ch_format_real64(to_bits(numbers[k]), b);
        put(node, " %s", b);
      }
      put(node, "\n");
    }
    free(poses);
  }
  put(node, "end\n");
  return node->text;
}
