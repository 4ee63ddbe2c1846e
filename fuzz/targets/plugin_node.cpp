// plugin_node.cpp — see plugin_node.h.
#include "plugin_node.h"

#include <dlfcn.h>

namespace vgc::fuzz {

const vgc_plugin_v1_table* load_plugin(const std::string& path, std::string* error) {
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* e = dlerror();
    *error = "cannot load " + path + ": " + (e ? e : "unknown error");
    return nullptr;
  }
  auto entry = reinterpret_cast<vgc_plugin_v1_fn>(dlsym(handle, VGC_PLUGIN_ENTRY));
  if (!entry) {
    *error = path + " does not export " VGC_PLUGIN_ENTRY;
    return nullptr;
  }
  const vgc_plugin_v1_table* t = entry();
  if (!t) {
    *error = path + ": " VGC_PLUGIN_ENTRY "() returned null";
    return nullptr;
  }
  if (t->abi_version != VGC_PLUGIN_ABI_VERSION) {
    *error = path + ": ABI version " + std::to_string(t->abi_version) + ", expected 1";
    return nullptr;
  }
  if (!t->create || !t->destroy || !t->apply || !t->snapshot || !t->derived) {
    *error = path + ": the function table has a null entry";
    return nullptr;
  }
  return t;
}

}  // namespace vgc::fuzz
