// plugin_implementation.h — an implementation loaded in process from a
// shared library through the C ABI of vgc_plugin.h (plugin:PATH).
//
// Spec: docs/adapters.md "plugin:PATH"; commands and documents are the text
// forms of docs/commands.md (command_text.h, snapshot.h,
// derived_document.h).
//
// Rationale: in process is fast (the fuzzer uses it), but a plugin that
// crashes takes the process with it. The suite therefore runs plugins in a
// child process by default (open_implementation with isolate_plugin: `vgc
// serve --impl plugin:PATH` behind the exec adapter); this class is what
// that child, and the fuzzer, use. Everything the plugin hands back is
// checked (NULL, reason not a token, document not ending in "end\n"), and a
// bad answer is a ProtocolError that sticks until reset(), as in exec.
#pragma once

#include <memory>
#include <string>

#include "implementation.h"
#include "route.h"
#include "vgc_plugin.h"

namespace vgc {

class PluginImplementation final : public Implementation {
 public:
  // Loads `path` (dlopen), finds vgc_plugin_v1, checks the ABI version and
  // the table, and creates a node. Returns nullptr with *error naming what
  // went wrong: the file cannot be loaded, the symbol is missing, the ABI
  // version differs, a function is NULL, or create() returned NULL.
  static std::unique_ptr<PluginImplementation> load(const std::string& path, std::string* error);
  // The same around a table already in this program (no dlopen; `label`
  // stands for the path in names and messages): the fuzzer's reference
  // behind the C ABI. nullptr with *error as load().
  static std::unique_ptr<PluginImplementation> wrap(const vgc_plugin_v1_table* table, const std::string& label,
                                                    std::string* error);
  ~PluginImplementation() override;  // destroys the node, then dlclose
  PluginImplementation(const PluginImplementation&) = delete;
  PluginImplementation& operator=(const PluginImplementation&) = delete;

  std::string name() const override { return route_spec(RouteKind::Plugin, path_); }
  std::string identity() const override;
  Answer reset() override;
  Answer apply(const Command& c) override;
  Document snapshot() override;
  Document derived() override;
  // Calls the optional vgc_plugin_request_v1; without it, Ok with
  // "error not supported\n" (the plugin claims no capability).
  Document request(const std::string& line) override;

  // Applies one raw line of text (for `vgc serve`, which already parsed it).
  Answer apply_line(const std::string& line);

 private:
  PluginImplementation() = default;
  Document document(const char* (*get)(vgc_node*), const char* what, const char* header);
  Answer fail(std::string detail);

  std::string path_;
  void* handle_ = nullptr;
  const vgc_plugin_v1_table* table_ = nullptr;
  vgc_node* node_ = nullptr;
  vgc_plugin_request_v1_fn request_ = nullptr;  // optional symbol
  CallStatus failed_ = CallStatus::Ok;  // sticky ProtocolError until reset()
  std::string failed_detail_;
};

}  // namespace vgc
