// plugin_implementation.cpp — see plugin_implementation.h.
#include "plugin_implementation.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstring>

#include "command_text.h"
#include "number_text.h"

namespace vgc {
namespace {

bool is_token(const char* s) {
  if (!s || !*s) return false;
  for (; *s; ++s) {
    const unsigned char ch = static_cast<unsigned char>(*s);
    if (ch <= ' ' || ch == 0x7f) return false;
  }
  return true;
}

std::string quote_c(const char* s) {
  if (!s) return "NULL";
  const std::size_t n = strnlen(s, 201);
  return format_quoted(std::string(s, n)) + (n > 200 ? "..." : "");
}

}  // namespace

std::unique_ptr<PluginImplementation> PluginImplementation::load(const std::string& path, std::string* error) {
  const std::string what = "plugin " + path + ": ";
  dlerror();
  // A bare file name is a file in the current directory, as everywhere else
  // in vgc (dlopen would search the system's library path instead).
  const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* e = dlerror();
    *error = what + "cannot load the library: " + (e ? e : "dlopen failed");
    return nullptr;
  }
  dlerror();
  void* sym = dlsym(handle, VGC_PLUGIN_ENTRY);
  if (!sym) {
    *error = what + "the library does not export the function " VGC_PLUGIN_ENTRY
                    " (declare it extern \"C\" with default visibility; see docs/adapters.md)";
    dlclose(handle);
    return nullptr;
  }
  vgc_plugin_v1_fn entry = nullptr;
  static_assert(sizeof entry == sizeof sym, "function and object pointers differ in size");
  std::memcpy(&entry, &sym, sizeof entry);
  const vgc_plugin_v1_table* table = entry();
  std::string problem;
  if (!table) {
    problem = VGC_PLUGIN_ENTRY "() returned NULL";
  } else if (table->abi_version != VGC_PLUGIN_ABI_VERSION) {
    problem = "it has plugin ABI version " + std::to_string(table->abi_version) +
              "; this suite loads ABI version " + std::to_string(VGC_PLUGIN_ABI_VERSION);
  } else if (!table->create || !table->destroy || !table->apply || !table->snapshot || !table->derived) {
    problem = "its function table has a NULL function";
  }
  if (!problem.empty()) {
    *error = what + problem;
    dlclose(handle);
    return nullptr;
  }
  vgc_node* node = table->create();
  if (!node) {
    *error = what + "create() returned NULL";
    dlclose(handle);
    return nullptr;
  }
  std::unique_ptr<PluginImplementation> impl(new PluginImplementation());
  impl->path_ = path;
  impl->handle_ = handle;
  impl->table_ = table;
  impl->node_ = node;
  if (void* req = dlsym(handle, VGC_PLUGIN_REQUEST_ENTRY)) std::memcpy(&impl->request_, &req, sizeof impl->request_);
  return impl;
}

std::unique_ptr<PluginImplementation> PluginImplementation::wrap(const vgc_plugin_v1_table* table,
                                                                const std::string& label, std::string* error) {
  const std::string what = "plugin " + label + ": ";
  if (!table || table->abi_version != VGC_PLUGIN_ABI_VERSION || !table->create || !table->destroy ||
      !table->apply || !table->snapshot || !table->derived) {
    *error = what + "no table, another ABI version, or a NULL function";
    return nullptr;
  }
  vgc_node* node = table->create();
  if (!node) {
    *error = what + "create() returned NULL";
    return nullptr;
  }
  std::unique_ptr<PluginImplementation> impl(new PluginImplementation());
  impl->path_ = label;
  impl->table_ = table;
  impl->node_ = node;
  return impl;
}

PluginImplementation::~PluginImplementation() {
  if (node_) table_->destroy(node_);
  if (handle_) dlclose(handle_);
}

std::string PluginImplementation::identity() const {
  return table_->name ? std::string(table_->name) : name();
}

Answer PluginImplementation::fail(std::string detail) {
  failed_ = CallStatus::ProtocolError;
  failed_detail_ = std::move(detail);
  Answer a;
  a.status = failed_;
  a.detail = failed_detail_;
  return a;
}

Answer PluginImplementation::reset() {
  if (node_) table_->destroy(node_);
  node_ = table_->create();
  if (!node_) return fail("create() returned NULL");
  failed_ = CallStatus::Ok;
  failed_detail_.clear();
  Answer a;
  a.applied = true;
  return a;
}

Answer PluginImplementation::apply_line(const std::string& line) {
  Answer a;
  if (failed_ != CallStatus::Ok) {
    a.status = failed_;
    a.detail = "not sent: an earlier call failed and reset() has not been called; that failure: " + failed_detail_;
    return a;
  }
  const char* reason = nullptr;
  const int r = table_->apply(node_, line.c_str(), &reason);
  switch (r) {
    case VGC_APPLIED:
      a.applied = true;
      return a;
    case VGC_REJECTED:
      if (!is_token(reason))
        return fail("apply() rejected " + format_quoted(line) + " with reason " + quote_c(reason) +
                    "; a reason is one word such as \"NO_SUCH_LAYER\"");
      a.reason = reason;
      return a;
    case VGC_DONE:  // processed, verdict not reported (docs/adapters.md)
      a.verdict_reported = false;
      return a;
    case VGC_MALFORMED:
      a.malformed = true;
      a.detail = reason ? reason : "";
      return a;
    default:
      return fail("apply() returned " + std::to_string(r) + " for " + format_quoted(line) +
                  "; expected VGC_APPLIED (1), VGC_REJECTED (0), VGC_DONE (2) or VGC_MALFORMED (-1)");
  }
}

Answer PluginImplementation::apply(const Command& c) { return apply_line(print_command(c)); }

Document PluginImplementation::document(const char* (*get)(vgc_node*), const char* what,
                                        const char* header) {
  Document d;
  if (failed_ != CallStatus::Ok) {
    d.status = failed_;
    d.detail = "not asked: an earlier call failed and reset() has not been called; that failure: " + failed_detail_;
    return d;
  }
  const char* text = get(node_);
  if (!text) {
    const Answer a = fail(std::string(what) + "() returned NULL");
    d.status = a.status;
    d.detail = a.detail;
    return d;
  }
  d.text = text;
  const std::size_t n = d.text.size();
  const std::string head = std::string(header) + " ";
  std::string problem;
  if (d.text.rfind(head, 0) != 0)
    problem = "does not start with \"" + head + "1\"";
  else if (n < 5 || d.text.compare(n - 5, 5, "\nend\n") != 0)
    problem = "does not end in a line \"end\"";
  else if (d.text.find("\nend\n") != n - 5)
    problem = "has a line \"end\" before its last line";
  if (!problem.empty()) {
    const Answer a = fail(std::string(what) + "() returned a document that " + problem);
    d.status = a.status;
    d.detail = a.detail;
    d.text.clear();
  }
  return d;
}

Document PluginImplementation::snapshot() { return document(table_->snapshot, "snapshot", "vgc-snapshot"); }
Document PluginImplementation::derived() { return document(table_->derived, "derived", "vgc-derived"); }

Document PluginImplementation::request(const std::string& line) {
  Document d;
  if (!request_) {
    d.text = "error not supported\n";
    return d;
  }
  if (failed_ != CallStatus::Ok) {
    d.status = failed_;
    d.detail = "not asked: an earlier call failed and reset() has not been called; that failure: " + failed_detail_;
    return d;
  }
  const char* text = request_(node_, line.c_str());
  std::string problem;
  if (!text) {
    problem = "returned NULL";
  } else {
    d.text = text;
    const std::size_t n = d.text.size();
    const bool error = d.text.rfind("error", 0) == 0 && d.text.find('\n') == n - 1;
    if (!error && (n < 5 || d.text.compare(n - 5, 5, "\nend\n") != 0 || d.text.find("\nend\n") != n - 5))
      problem = "returned a document that does not end in its only line \"end\"";
  }
  if (!problem.empty()) {
    const Answer a = fail(std::string(VGC_PLUGIN_REQUEST_ENTRY "(") + format_quoted(line) + ") " + problem);
    d.status = a.status;
    d.detail = a.detail;
    d.text.clear();
  }
  return d;
}

}  // namespace vgc
