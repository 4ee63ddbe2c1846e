// catalog_markdown.h — the clause catalog as `vgc clauses` prints it: one
// line per clause, or the whole catalog as Markdown (docs/clauses.md is
// this, generated: `./vgc clauses --markdown > docs/clauses.md`).
//
// Spec: the clause levels of clause.h and what each does to the verdict
// (report/verdict.h): the header says so in the verdict's own terms.
#pragma once

#include <string>
#include <string_view>

namespace vgc {

// "ID LEVEL GROUP PROPERTIES" per clause matching `glob` (runner.h's
// clause_selected), catalog order.
std::string clause_catalog_list(std::string_view glob = "*");

// The catalog as Markdown: a header with the levels, then per group each
// clause matching `glob` with its source, text, reading and properties.
std::string clause_catalog_markdown(std::string_view glob = "*");

}  // namespace vgc
