// plugin_node.h — loading an implementation under test as a plugin, in process.
//
// Spec: conformance/adapter/vgc_plugin.h (the one exported symbol
// vgc_plugin_v1, ABI version 1).
//
// Rationale: fuzz_differential needs hundreds of thousands of commands per
// second through the implementation, so it calls the plugin in process
// (dlopen) rather than through a child process. A crash of the plugin is
// then a crash of the fuzzer, which is what a fuzzer should report.
#pragma once

#include <string>

#include "vgc_plugin.h"

namespace vgc::fuzz {

// dlopens `path` and returns its table. On failure (no such file, no
// vgc_plugin_v1, other ABI version, null functions) returns nullptr and sets
// *error. The library stays loaded for the life of the process.
const vgc_plugin_v1_table* load_plugin(const std::string& path, std::string* error);

}  // namespace vgc::fuzz
