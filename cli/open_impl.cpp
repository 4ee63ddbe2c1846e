// open_impl.cpp — see open_impl.h.
#include "open_impl.h"
#include "terminal_text.h"

#include <fmt/core.h>

#include <filesystem>

#if __has_include("capability_checks.h")
#include "capability_checks.h"
#define VGC_HAVE_CAPABILITY_CHECKS 1
#endif

namespace vgc::cli {

namespace {

// What to do when `spec` could not be opened with `error`: a line for the
// newcomer, after the adapter's own account of what happened.
std::string what_to_do(const std::string& spec, const std::string& error) {
  if (spec.rfind("exec:", 0) == 0) {
    const std::string command = spec.substr(5);
    if (error.find("status 127") != std::string::npos)
      return "the shell found no such program: check the command; a relative path is relative to the directory "
             "vgc runs in";
    if (error.find("status 126") != std::string::npos)
      return "the program is not executable: chmod +x it, or name its interpreter (exec:'python3 my_host.py')";
    if (error.find("names no command") != std::string::npos) return "";
    return "check that the program speaks the exec protocol (docs/adapters.md section 1): printf '?hello\\n?quit\\n' "
           "| " + command + " must answer `vgc-exec 1 NAME`";
  }
  if (spec.rfind("plugin:", 0) == 0 && error.find("names no library") == std::string::npos)
    return "the plugin must be a shared library exporting the C function vgc_plugin_v1 (docs/adapters.md section 4); "
           "`nm -D PATH | grep vgc_plugin_v1` shows whether it does";
  return "";
}

}  // namespace

std::unique_ptr<Implementation> open_impl_or_report(const char* subcommand, const std::string& spec,
                                                    TimeLimits limits, const std::string& verse_bone_form) {
  // A plugin file that is not there: said plainly, not as a child process
  // that failed to answer.
  if (spec.rfind("plugin:", 0) == 0 && spec.size() > 7) {
    const std::filesystem::path path = spec.substr(7);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
      say(stderr,
                 "vgc {}: {}: {} is {}: give the path of your plugin's shared library (relative to the directory vgc "
                 "runs in, {}), e.g. plugin:./build/libmy_node.so\n",
                 subcommand, spec, path.string(),
                 std::filesystem::exists(path, ec) ? "not a regular file" : "not there", 
                 std::filesystem::current_path(ec).string());
      return nullptr;
    }
  }
  OpenOptions open;
  open.timeout_seconds = limits.timeout_seconds;
  open.start_timeout_seconds = limits.start_timeout_seconds;
  open.verse_bone_form = verse_bone_form;
  std::string error;
  auto sut = open_implementation(spec, open, &error);
  if (!sut) {
    say(stderr, "vgc {}: {}\n", subcommand, error);
    if (const std::string fix = what_to_do(spec, error); !fix.empty())
      say(stderr, "vgc {}: what to do: {}\n", subcommand, fix);
  }
  return sut;
}

bool register_oracle_checks() {
#ifdef VGC_HAVE_CAPABILITY_CHECKS
  register_capability_checks();  // the oracles judge the optional capabilities
  return true;
#else
  return false;
#endif
}

}  // namespace vgc::cli
