// program_text.h — the text form of a Program (runner.h): a counterexample
// file. Its commands in the command text form (reference/node/command_text.h),
// then, for a finding of an optional capability, one directive line naming
// the capability check to repeat on the final state:
//
//   vertex_set_xyz_real64 0 0 0 0 0
//   ...
//   #! capability subdivision variant 2
//   #! capability edits variant 3 draw 2718281828   (a check_drawn check)
//
// and, before it, "#! history KIND" (a finding that depends on the
// implementation's history, confirm_finding.h) or "#! mesh" (a user's mesh
// as `certify --mesh` judged it, mesh_certification.h).
//
// Spec: docs/certify.md "Replaying a failure", docs/commands.md 1
// (comments); capabilities as in docs/adapters.md section 5.
//
// Rationale: a capability finding (MESH-CLASSIFY-1, SUBD-CATMARK-1, ...) is
// shown by a request after the commands, not by a command, so a file of
// commands alone would replay as "agrees". The directive is a comment to
// the command grammar, so `vgc apply`, the parsers of other implementations
// and anything else reading command files see the same commands as before;
// only `vgc replay` (parse_program) reads it. The capability is a name
// looked up in the registry (capability.h), never a fixed list.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "command_text.h"
#include "program.h"

namespace vgc {

// "#! capability <name> variant <n>[ draw <d>]\n" for `request`.
std::string print_capability_directive(const CapabilityRequest& request);

// program.commands one per line (print_commands), then the directive when
// program.request is set. parse_program(print_program(p)) gives p back.
std::string print_program(const Program& program);

// Parses a command file with an optional capability directive. A line that
// starts with "#!" followed by the word "capability" (blanks between
// allowed) is a directive; it must read "#! capability NAME variant N",
// optionally followed by "draw D" (NAME: letters, digits, '-' and '_';
// N: 1 to 9 decimal digits; D: 0 to 4294967295, the value a check_drawn
// check drew for the case), come after
// the last command and appear at most once. Any other comment, "#!" ones
// included, is an ordinary comment. On an error returns false with *error
// naming line and column (as parse_commands); `lines`, when given, receives
// each command's 1-based line number, and `directive_line` the directive's
// (0 without one). Never throws.
bool parse_program(std::string_view text, Program* out, TextError* error, std::vector<std::size_t>* lines = nullptr,
                   std::size_t* directive_line = nullptr);

}  // namespace vgc
