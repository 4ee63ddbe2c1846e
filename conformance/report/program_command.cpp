// program_command.cpp — the command printed lines use to name the vgc
// program (program_command.h).
#include "program_command.h"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "exec_implementation.h"  // shell_quote

namespace vgc {
namespace fs = std::filesystem;

namespace {
std::string& current() {
  static std::string command = "./vgc";
  return command;
}

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec) && !ec;
}

std::string quoted_if_needed(const std::string& path) {
  const bool plain = path.find_first_not_of(
                         "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789/._+-") == std::string::npos;
  return plain ? path : shell_quote(path);
}
}  // namespace

std::string program_command_for(const std::string& exe_path, const std::string& path_env) {
  const fs::path exe(exe_path);
  std::error_code ec;
  if (exe.parent_path().filename() == "cli" && fs::exists(exe.parent_path().parent_path() / "CMakeCache.txt", ec)) {
    // The checkout's ./vgc script, by its absolute path, so that the line
    // works from any directory (the default build tree is <checkout>/build).
    const fs::path script = exe.parent_path().parent_path().parent_path() / "vgc";
    if (fs::is_regular_file(script, ec) && ::access(script.c_str(), X_OK) == 0)
      return quoted_if_needed(script.lexically_normal().string());
    return quoted_if_needed(exe_path);
  }
  // The first vgc a shell would find on PATH (empty entries, the current
  // directory, are skipped: a printed command must not depend on it).
  std::string::size_type start = 0;
  while (start <= path_env.size()) {
    std::string::size_type end = path_env.find(':', start);
    if (end == std::string::npos) end = path_env.size();
    const std::string dir = path_env.substr(start, end - start);
    start = end + 1;
    if (dir.empty() || dir[0] != '/') continue;
    const fs::path candidate = fs::path(dir) / "vgc";
    if (::access(candidate.c_str(), X_OK) != 0 || fs::is_directory(candidate, ec)) continue;
    if (same_file(candidate, exe)) return "vgc";
    break;  // another vgc comes first: "vgc" would run that one
  }
  return quoted_if_needed(exe_path);
}

const std::string& program_command() { return current(); }

void set_program_command(const std::string& command) { current() = command; }

}  // namespace vgc
