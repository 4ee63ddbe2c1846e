// clause_selection.h — which clauses a run selects (--clauses GLOB).
//
// Spec: docs/certify.md "--clauses": comma-separated fnmatch patterns over
// the catalog's clause ids (clause.h).
//
// Rationale: vocabulary at the bottom (issue 29): the runner, the mesh path,
// `vgc merge` and the catalog listing all ask the same question, and none
// of them should include the others to ask it.
#pragma once

#include <string>
#include <string_view>

namespace vgc {

// True when `id` matches the comma-separated fnmatch patterns in `glob`
// (an empty glob selects everything).
bool clause_selected(const std::string& glob, std::string_view id);

}  // namespace vgc
