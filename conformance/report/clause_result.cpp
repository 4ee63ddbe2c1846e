// clause_result.cpp — see clause_result.h.
#include "clause_result.h"

#include <algorithm>
#include <optional>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "run_result.h"

namespace vgc {

ClauseResult clause_result(const std::string& run_dir, const std::string& clause_id) {
  ClauseResult r;
  const std::string path = (std::filesystem::path(run_dir) / "report.json").string();
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    r.text = "cannot read " + path + ": did the certify run write its report?\n";
    return r;
  }
  std::stringstream ss;
  ss << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(ss.str(), nullptr, false);
  if (j.is_discarded() || !j.contains("clauses")) {
    r.text = path + " is not a vgc report.json\n";
    return r;
  }
  const std::string head = "run: " + j.value("rerun", std::string()) + "\nverdict of the run: " +
                           j.value("verdict", std::string()) + "\n";
  for (const auto& c : j["clauses"]) {
    if (c.value("id", std::string()) != clause_id) continue;
    const std::string status = c.value("status", std::string());
    r.text = clause_id + " (" + c.value("level", std::string()) + "): " + status + "\n";
    if (c.contains("message")) r.text += c["message"].get<std::string>() + "\n";
    if (c.contains("note")) r.text += "note: " + c["note"].get<std::string>() + "\n";
    if (c.contains("replay")) r.text += "replay: " + c["replay"].get<std::string>() + "\n";
    r.text += head;
    const auto gating = j.value("new_failures", std::vector<std::string>{});
    if (std::find(gating.begin(), gating.end(), clause_id) != gating.end()) r.exit_code = 1;
    else {
      // A status this vgc does not know (a damaged report) is not judged: exit 2.
      const std::optional<ClauseStatus> s = clause_status_named(status);
      r.exit_code = !s || *s == ClauseStatus::Unchecked ? 2 : *s == ClauseStatus::Skipped ? 77 : 0;
    }
    return r;
  }
  r.exit_code = 77;
  r.text = clause_id + ": not judged in this run (not selected by its --clauses)\n" + head;
  return r;
}

}  // namespace vgc
