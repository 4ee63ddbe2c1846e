// report_sections.cpp — see report_sections.h.
#include "report_sections.h"

namespace vgc {

const char* report_section_title(ReportSection s) {
  switch (s) {
    case ReportSection::CauseGroups: return "Findings with one cause";
    case ReportSection::Failures: return "Failures";
    case ReportSection::ProfileDifferences: return "Profile differences (IMPLEMENTATION-DEFINED: the spec is silent)";
    case ReportSection::KnownDeviations: return "Known deviations (in the baseline)";
    case ReportSection::ShouldNotMet: return "SHOULD clauses not met (the verdict stands)";
    case ReportSection::StaleBaseline: return "Baseline entries no case diverged on — remove them";
    case ReportSection::Clauses: return "Clauses";
    case ReportSection::Properties: return "Properties";
    case ReportSection::CommandsJudged: return "Commands judged";
    case ReportSection::RulesUsed: return "Rules used";
  }
  return "";
}

const char* report_section_intro(ReportSection s) {
  switch (s) {
    case ReportSection::ProfileDifferences:
      return "The implementation chose differently from the suite's reading of a point the spec leaves open. "
             "Reported, tolerated (so it hides nothing else), and not gating; `--strict` makes them gate.";
    case ReportSection::CauseGroups:
    case ReportSection::Failures:
    case ReportSection::KnownDeviations:
    case ReportSection::ShouldNotMet:
    case ReportSection::StaleBaseline:
    case ReportSection::Clauses:
    case ReportSection::Properties:
    case ReportSection::CommandsJudged:
    case ReportSection::RulesUsed:
      return "";
  }
  return "";
}

std::vector<FindingSection> finding_sections(const Verdict& v) {
  return {{ReportSection::Failures, &v.new_failures},
          {ReportSection::ProfileDifferences, &v.profile_differences},
          {ReportSection::KnownDeviations, &v.known_failures},
          {ReportSection::ShouldNotMet, &v.should_failures}};
}

}  // namespace vgc
