// reference_plugin_table.h — the reference node behind the plugin C ABI.
//
// Spec: conformance/adapter/vgc_plugin.h (ABI version 1: one text command
// line per apply; documents of reference/node/snapshot.h and
// reference/geometry/derived_document.h).
//
// Rationale: fuzz_differential talks to every implementation through this
// ABI. With no plugin given it uses this table, which exercises the same
// path (print_command, then parse in the "implementation"), and the faulty
// plugins of fuzz/faulty_plugins/ are this table with one seeded fault each,
// so that tests can show the differential target finds each fault.
#pragma once

#include "vgc_plugin.h"

namespace vgc::fuzz {

enum class PluginFault {
  None,
  // Polygon corners are not checked for repeats: a polygon on layer 1 whose
  // only fault is a repeated corner (all corners live vertices) is reported
  // APPLIED, and nothing is stored. Caught as applied-vs-rejected.
  AcceptRepeatedCorners,
  // vertex_set_xyz_real32 with a coordinate equal to FLT_MAX (the wire's
  // delete form) is reported APPLIED but the vertex stays. Caught as a
  // snapshot difference.
  IgnoreReal32Delete,
};

// A static table; create() makes reference nodes carrying `fault`.
const vgc_plugin_v1_table* reference_plugin_table(PluginFault fault);

}  // namespace vgc::fuzz
