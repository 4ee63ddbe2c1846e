// version.h — the versions vgc states (`vgc --version`): the program's own,
// the clause catalog's and the report format's.
//
// VGC_VERSION comes from project(vgc VERSION ...) in the top CMakeLists.txt
// through the configured vgc_project_version.h (from
// conformance/vgc_project_version.h.in, written into the build tree).
#pragma once

#include "vgc_project_version.h"

namespace vgc {

// The program: "major.minor" as in project(vgc VERSION ...).
inline constexpr const char kVgcVersion[] = VGC_VERSION;

// The clause catalog (clause_catalog.cpp): raised when a clause is added,
// removed, renamed or its reading changes what passes.
inline constexpr int kClauseCatalogVersion = 2;

// report.json's "vgc_report_version" (conformance/report/report_json.cpp).
inline constexpr int kReportFormatVersion = 5;

}  // namespace vgc
