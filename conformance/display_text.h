// display_text.h — the one escaping function for bytes that are not vgc's
// (a file's, an argument's, an implementation's) on their way to a
// terminal, summary.md, junit.xml, report.html or a counterexample file.
//
// Spec: none (CI practice; issue 19: a parse error must not set the
// terminal's title or colour a CI log, and junit.xml must stay XML).
//
// Rationale: newlines and tabs are kept (messages have lines), valid UTF-8
// text is kept (names, the spec's own punctuation); every other control
// byte (C0, DEL, C1), and every byte that is not part of valid UTF-8, is
// written \xHH. Text that is already escaped passes unchanged, so escaping
// twice is harmless.
#pragma once

#include <string>
#include <string_view>

namespace vgc {

std::string escape_unprintable(std::string_view s);

}  // namespace vgc
