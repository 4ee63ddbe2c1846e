// baseline.cpp — see baseline.h. Errors name the line and column and the fix.
#include "baseline.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "bounded_text.h"
#include "clause.h"
#include "program_command.h"

namespace vgc {

bool parse_baseline(const std::string& text, Baseline* out, std::string* error) {
  std::istringstream in(text);
  std::string line;
  int number = 0;
  std::map<std::string, int> listed_on;  // id -> the line it is first listed on
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
      // The reason is copied into every report: kept to a few KiB (bounded_text.h).
      if (r != std::string::npos) reason = bounded_text(std::string_view(line).substr(r));
    }
    // "LINE:COLUMN: what is wrong; what to do" (columns count from 1).
    const std::string at = std::to_string(number) + ":" + std::to_string(first + 1) + ": ";
    if (!find_clause(id)) {
      *error = at + "unknown clause id '" + bounded_text(id, 100) + "': use an id that `" + program_command() +
               " clauses` lists (one clause id, then the reason, per line)";
      return false;
    }
    if (reason.empty()) {
      *error = std::to_string(number) + ":" + std::to_string(first + id.size() + 1) + ": clause " + id +
               " needs a reason after the id: write why it is a known deviation (`" + id +
               " our host stores ... (ticket 12)`)";
      return false;
    }
    if (!out->reasons.emplace(id, reason).second) {
      *error = at + "clause " + id + " is listed twice (first on line " + std::to_string(listed_on[id]) +
               "): keep one of the lines";
      return false;
    }
    listed_on[id] = number;
  }
  return true;
}

bool load_baseline(const std::string& path, Baseline* out, std::string* error) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {  // an ifstream opens one, and reads it as empty
    *error = path + ": is a directory, not a baseline file: give the path of a file of known deviations "
                    "(CLAUSE-ID reason, one per line)";
    return false;
  }
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    *error = path + ": cannot read the baseline file (" + std::strerror(errno) +
             "): give the path of a file of known deviations, relative to the directory vgc runs in";
    return false;
  }
  std::ostringstream ss;
  ss << f.rdbuf();
  if (f.bad()) {
    *error = path + ": cannot read the baseline file (" + std::strerror(errno) + ")";
    return false;
  }
  std::string e;
  if (!parse_baseline(ss.str(), out, &e)) {
    *error = path + ":" + e;
    return false;
  }
  return true;
}

}  // namespace vgc
