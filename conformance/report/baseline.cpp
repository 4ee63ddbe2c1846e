// baseline.cpp — see baseline.h.
#include "baseline.h"

#include <fstream>
#include <sstream>

#include "clause.h"
#include "program_command.h"

namespace vgc {

bool parse_baseline(const std::string& text, Baseline* out, std::string* error) {
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const auto end_id = line.find_first_of(" \t", first);
    const std::string id = line.substr(first, end_id == std::string::npos ? std::string::npos : end_id - first);
    std::string reason;
    if (end_id != std::string::npos) {
      const auto r = line.find_first_not_of(" \t", end_id);
      if (r != std::string::npos) reason = line.substr(r);
    }
    if (!find_clause(id)) {
      *error = std::to_string(number) + ": unknown clause id '" + id + "' (see " + program_command() + " clauses)";
      return false;
    }
    if (reason.empty()) {
      *error = std::to_string(number) + ": clause " + id + " needs a reason after the id";
      return false;
    }
    if (!out->reasons.emplace(id, reason).second) {
      *error = std::to_string(number) + ": clause " + id + " is listed twice";
      return false;
    }
  }
  return true;
}

bool load_baseline(const std::string& path, Baseline* out, std::string* error) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    *error = path + ": cannot read the baseline file";
    return false;
  }
  std::ostringstream ss;
  ss << f.rdbuf();
  std::string e;
  if (!parse_baseline(ss.str(), out, &e)) {
    *error = path + ":" + e;
    return false;
  }
  return true;
}

}  // namespace vgc
