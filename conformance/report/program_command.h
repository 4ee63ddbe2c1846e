// program_command.h — how a printed command names the vgc program: the
// replay line of every counterexample (summary.md, report.json, junit.xml,
// the .vgc file, the terminal) and certify's re-run line. A line must work
// wherever it is read, from any directory: the repository's vgc script by
// its absolute path (it builds and runs the build tree's program), or an
// installed vgc (docs/ci.md).
#pragma once

#include <string>

namespace vgc {

// The command that runs the program at exe_path (an absolute path), for a
// shell whose PATH is path_env:
//   "/path/to/checkout/vgc"  when the program is in a vgc build tree
//            (<build>/cli/vgc, with <build>/CMakeCache.txt) whose parent
//            holds the vgc script; the program itself when it does not;
//   "vgc"    when the first vgc on path_env is this very file;
//   otherwise exe_path itself, shell-quoted when it needs it.
std::string program_command_for(const std::string& exe_path, const std::string& path_env);

// What printed commands start with: "./vgc" unless set (the vgc program sets
// it at start from /proc/self/exe and $PATH, see vgc_main.cpp).
const std::string& program_command();
void set_program_command(const std::string& command);

}  // namespace vgc
