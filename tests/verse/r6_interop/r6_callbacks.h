// r6_callbacks.h — the r6 client library callbacks (verse_callback_set) that
// both programs linked against a user's libverse.a register: r6_client
// (what r6's library decodes, recorded) and r6_exec (the exec protocol in
// front of an r6 host). One list, so the two cannot drift apart: each
// program defines a callback of every name below with the signature r6's
// verse.h gives the matching verse_send_* function.
//
// Spec: docs/verse_wire.md (the commands the wire carries; section 12, the
// exec wrapper).
#pragma once

#include "verse.h"

// X(send function, callback): connection and node commands both programs take.
#define VGC_R6_NODE_CALLBACKS(X)                  \
  X(verse_send_connect_accept, cb_accept)         \
  X(verse_send_connect_terminate, cb_terminate)   \
  X(verse_send_node_create, cb_node_create)       \
  X(verse_send_node_name_set, cb_node_name_set)

// X(send function, callback): every geometry command (section 2.6).
#define VGC_R6_GEOMETRY_CALLBACKS(X)                                   \
  X(verse_send_g_layer_create, cb_layer_create)                        \
  X(verse_send_g_layer_destroy, cb_layer_destroy)                      \
  X(verse_send_g_vertex_set_xyz_real32, cb_xyz32)                      \
  X(verse_send_g_vertex_delete_real32, cb_vdel32)                      \
  X(verse_send_g_vertex_set_xyz_real64, cb_xyz64)                      \
  X(verse_send_g_vertex_delete_real64, cb_vdel64)                      \
  X(verse_send_g_vertex_set_uint32, cb_vuint)                          \
  X(verse_send_g_vertex_set_real64, cb_vreal64)                        \
  X(verse_send_g_vertex_set_real32, cb_vreal32)                        \
  X(verse_send_g_polygon_set_corner_uint32, cb_corner_uint)            \
  X(verse_send_g_polygon_delete, cb_pdel)                              \
  X(verse_send_g_polygon_set_corner_real64, cb_corner64)               \
  X(verse_send_g_polygon_set_corner_real32, cb_corner32)               \
  X(verse_send_g_polygon_set_face_uint8, cb_face_u8)                   \
  X(verse_send_g_polygon_set_face_uint32, cb_face_u32)                 \
  X(verse_send_g_polygon_set_face_real64, cb_face64)                   \
  X(verse_send_g_polygon_set_face_real32, cb_face32)                   \
  X(verse_send_g_crease_set_vertex, cb_crease_vertex)                  \
  X(verse_send_g_crease_set_edge, cb_crease_edge)                      \
  X(verse_send_g_bone_create, cb_bone_create)                          \
  X(verse_send_g_bone_destroy, cb_bone_destroy)

// Registers one callback (r6 takes both as void*).
#define VGC_R6_REGISTER(send, cb) \
  verse_callback_set(reinterpret_cast<void*>(send), reinterpret_cast<void*>(cb), nullptr);
