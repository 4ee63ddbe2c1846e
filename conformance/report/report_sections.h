// report_sections.h — the sections of a certify report, in the order
// summary.md and report.html show them, with their titles and the words
// that introduce them: one list both pages read, so the two never name a
// section differently.
//
// Spec: none (the report's layout: docs/certify.md "Looking at report.html").
//
// Rationale: a section a person looks for at 2 a.m. ("Profile
// differences", "Known deviations") must be found by the same title on
// either page and in the docs. The writers decide how a section is drawn
// (markdown or HTML); this file decides what it is called and which of the
// verdict's lists fills it. An intro may quote code between backticks:
// summary.md keeps them, report.html drops them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "verdict.h"

namespace vgc {

enum class ReportSection : std::uint8_t {
  CauseGroups,         // findings with one cause (finding_cause.h)
  Failures,            // Verdict::new_failures
  ProfileDifferences,  // Verdict::profile_differences
  KnownDeviations,     // Verdict::known_failures (the baseline)
  ShouldNotMet,        // Verdict::should_failures
  StaleBaseline,       // Verdict::stale_baseline
  Clauses,             // the clause table
  Properties,          // the property table
  CommandsJudged,      // summary.md only
  RulesUsed,           // summary.md only
};

// The section's title, as both pages print it.
const char* report_section_title(ReportSection s);
// The words under the title ("" for none); code between backticks.
const char* report_section_intro(ReportSection s);

// A section of findings, and the clause ids the verdict puts in it.
struct FindingSection {
  ReportSection section;
  const std::vector<std::string>* ids;
};
// The four sections of findings, in the pages' order: failures, profile
// differences, known deviations, SHOULD clauses not met.
std::vector<FindingSection> finding_sections(const Verdict& v);

}  // namespace vgc
