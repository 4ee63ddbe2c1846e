// run_result.cpp — the names of the statuses (run_result.h).
#include "run_result.h"

#include <ostream>

namespace vgc {

const char* clause_status_name(ClauseStatus s) {
  switch (s) {
    case ClauseStatus::Pass: return "pass";
    case ClauseStatus::Fail: return "fail";
    case ClauseStatus::Crash: return "crash";
    case ClauseStatus::Timeout: return "timeout";
    case ClauseStatus::Unchecked: return "unchecked";
    case ClauseStatus::NotClaimed: return "not-claimed";
    case ClauseStatus::NotApplicable: return "not-applicable";
    case ClauseStatus::Skipped: return "skipped";
  }
  return "unchecked";
}

std::optional<ClauseStatus> clause_status_named(std::string_view name) {
  for (ClauseStatus s : {ClauseStatus::Pass, ClauseStatus::Fail, ClauseStatus::Crash, ClauseStatus::Timeout,
                         ClauseStatus::Unchecked, ClauseStatus::NotClaimed, ClauseStatus::NotApplicable,
                         ClauseStatus::Skipped})
    if (name == clause_status_name(s)) return s;
  return std::nullopt;
}

ClauseStatus clause_status_of(FindingStatus s) {
  switch (s) {
    case FindingStatus::Crash: return ClauseStatus::Crash;
    case FindingStatus::Timeout: return ClauseStatus::Timeout;
    case FindingStatus::Fail:
    case FindingStatus::NotJudged: break;  // NotJudged is no finding: never a clause's finding
  }
  return ClauseStatus::Fail;
}

bool is_deviation(ClauseStatus s) {
  return s == ClauseStatus::Fail || s == ClauseStatus::Crash || s == ClauseStatus::Timeout;
}

const char* property_status_name(PropertyStatus s) {
  switch (s) {
    case PropertyStatus::Pass: return "pass";
    case PropertyStatus::Fail: return "fail";
    case PropertyStatus::Stopped: return "stopped";
    case PropertyStatus::Skipped: return "skipped";
  }
  return "skipped";
}

std::optional<PropertyStatus> property_status_named(std::string_view name) {
  for (PropertyStatus s : {PropertyStatus::Pass, PropertyStatus::Fail, PropertyStatus::Stopped, PropertyStatus::Skipped})
    if (name == property_status_name(s)) return s;
  return std::nullopt;
}

std::ostream& operator<<(std::ostream& out, ClauseStatus s) { return out << clause_status_name(s); }
std::ostream& operator<<(std::ostream& out, PropertyStatus s) { return out << property_status_name(s); }

}  // namespace vgc
