// report_finding.cpp — see report_finding.h.
#include "report_finding.h"

#include <cstdio>
#include <cstdlib>

#include "command_text.h"

namespace vgc::fuzz {

void report_finding(const char* target, const std::string& what, const std::vector<Command>& commands) {
  const std::string text = print_commands(commands);
  std::fprintf(stderr,
               "vgc-fuzz: FINDING in %s: %s\n"
               "vgc-fuzz: the %zu commands up to and including the failing one "
               "(save as FILE, run `vgc apply FILE`):\n"
               "----8<---- counterexample.vgc\n%s----8<----\n",
               target, what.c_str(), commands.size(), text.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace vgc::fuzz
