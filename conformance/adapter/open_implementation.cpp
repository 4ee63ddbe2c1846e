// open_implementation.cpp — "reference", "exec:CMD", "plugin:PATH",
// "verse:HOST[:PORT]" to an Implementation.
//
// Spec: docs/adapters.md. An isolated plugin is `<vgc> serve --impl
// plugin:PATH` behind the exec adapter, so a plugin that crashes or hangs
// is a Crash or Timeout result like any exec program's.
#include <unistd.h>

#include <climits>

#include "exec_implementation.h"
#include "implementation.h"
#include "plugin_implementation.h"
#include "reference_implementation.h"
#include "verse_implementation.h"

namespace vgc {
namespace {

const char kForms[] = "expected reference, exec:CMD (a program speaking the exec protocol, run with /bin/sh -c), "
                      "plugin:PATH (a shared library exporting vgc_plugin_v1) or verse:[NAME@]HOST[:PORT] (a "
                      "Verse host, port 4950 by default)";

std::string self_executable() {
  char buf[PATH_MAX + 1];
  const ssize_t n = readlink("/proc/self/exe", buf, PATH_MAX);
  if (n <= 0) return {};
  return std::string(buf, static_cast<std::size_t>(n));
}

std::unique_ptr<Implementation> open_exec(const std::string& command, const std::string& display_name,
                                          const OpenOptions& options, std::string* error) {
  auto impl = std::make_unique<ExecImplementation>(command, options, display_name);
  const Answer a = impl->start();
  if (a.status != CallStatus::Ok) {
    *error = impl->name() + ": cannot start it (" + call_status_name(a.status) + "): " + a.detail;
    return nullptr;
  }
  return impl;
}

}  // namespace

std::unique_ptr<Implementation> open_implementation(const std::string& spec, const OpenOptions& options,
                                                    std::string* error) {
  if (spec == "reference") return std::make_unique<ReferenceImplementation>();
  if (spec.rfind("exec:", 0) == 0) {
    const std::string command = spec.substr(5);
    if (command.find_first_not_of(" \t") == std::string::npos) {
      *error = "'" + spec + "' names no command; " + kForms;
      return nullptr;
    }
    return open_exec(command, spec, options, error);
  }
  if (spec.rfind("plugin:", 0) == 0) {
    const std::string path = spec.substr(7);
    if (path.empty()) {
      *error = "'" + spec + "' names no library; " + kForms;
      return nullptr;
    }
    if (!options.isolate_plugin) {
      std::unique_ptr<Implementation> impl = PluginImplementation::load(path, error);
      return impl;
    }
    const std::string vgc = options.vgc_binary.empty() ? self_executable() : options.vgc_binary;
    if (vgc.empty()) {
      *error = spec + ": cannot find the vgc program to isolate the plugin in (set OpenOptions::vgc_binary)";
      return nullptr;
    }
    return open_exec(shell_quote(vgc) + " serve --impl " + shell_quote(spec), spec, options, error);
  }
  if (spec.rfind("verse:", 0) == 0) {
    std::string login, host, why;
    std::uint16_t port = 0;
    if (!parse_verse_address(spec.substr(6), &login, &host, &port, &why)) {
      *error = "'" + spec + "': " + why + "; " + kForms;
      return nullptr;
    }
    auto impl = std::make_unique<VerseImplementation>(spec, login, host, port, options);
    const Answer a = impl->start();
    if (a.status != CallStatus::Ok) {
      *error = spec + ": cannot certify this host (" + call_status_name(a.status) + "): " + a.detail +
               ". Is a Verse host listening there (UDP), and does it accept the login? (docs/adapters.md, "
               "\"The Verse wire route\")";
      return nullptr;
    }
    return impl;
  }
  *error = "unknown implementation '" + spec + "': " + kForms;
  return nullptr;
}

}  // namespace vgc
