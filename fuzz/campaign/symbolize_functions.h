// symbolize_functions.h — the implementation's functions, named: which of
// them some input of a campaign entered and which none did
// (`vgc fuzz differential --impl exec:CMD --coverage-report`).
//
// Spec: none of the Verse spec; docs/fuzzing.md "Coverage of the
// implementation" (issue 30, item 3: a team sees what no input reached).
//
// Rationale: the implementation's PC table (clang
// -fsanitize-coverage=...,pc-table) marks the counter at each function's
// entry; vgc's coverage runtime gives each entry's PC as an offset from its
// module's load address (runtime/vgc_coverage_shm.h, layout 2). An offset
// becomes an address of the module's file by adding the file's lowest
// loadable address (0 for a shared library or a PIE, 0x400000 for a
// classic executable), read from its ELF program headers here; the
// addresses are then named by llvm-symbolizer (LLVM's own symbolizer,
// Debian's llvm package: it reads the DWARF clang writes), one process per
// module, every address on its standard input. A module that cannot be read
// or a missing symbolizer leaves its functions as "module+0xOFFSET", and
// the note says why: the list is still right, only less readable.
#pragma once

#include <string>
#include <vector>

#include "coverage_record.h"

namespace vgc::fuzz {

struct NamedFunction {
  std::string name;      // "node_apply" (demangled), or "MODULE+0xOFFSET" when it cannot be named
  std::string location;  // "c_host_node.c:120", or "" when unknown
  bool entered = false;
};

// The functions named, in `functions`' order; *note says what could not be
// named and why (empty when every one was).
std::vector<NamedFunction> symbolize_functions(const std::vector<ImplementationFunction>& functions,
                                               std::string* note);

// Sorted by place: file, line (as a number), name.
bool place_before(const NamedFunction& a, const NamedFunction& b);

// The text of implementation_functions.md: how many were entered, then the
// ones never entered and the ones entered, each sorted by location.
std::string format_function_report(const std::vector<NamedFunction>& named, const std::string& note);

}  // namespace vgc::fuzz
