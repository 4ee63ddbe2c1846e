// clause_selection.cpp — see clause_selection.h.
#include "clause_selection.h"

#include <fnmatch.h>

#include <sstream>

namespace vgc {

bool clause_selected(const std::string& glob, std::string_view id) {
  const std::string name(id);
  std::stringstream ss(glob.empty() ? "*" : glob);
  std::string pattern;
  while (std::getline(ss, pattern, ','))
    if (!pattern.empty() && fnmatch(pattern.c_str(), name.c_str(), 0) == 0) return true;
  return false;
}

}  // namespace vgc
