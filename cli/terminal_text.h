// terminal_text.h — say(): fmt::print for the command line, through the
// one escaping function (display_text.h), so that a file's, an argument's
// or an implementation's bytes never reach a terminal or a CI log raw.
//
// Spec: none (CI practice; issue 19).
//
// Rationale: every message of a subcommand may carry foreign bytes (a file
// name, a parse error quoting the file, an implementation's stderr), so
// every message goes through say(); only the progress line, which draws
// with its own control sequences, and `vgc serve`'s protocol output do not.
#pragma once

#include <fmt/core.h>

#include <cstdio>
#include <utility>

#include "display_text.h"

namespace vgc::cli {

template <typename... T>
void say(std::FILE* f, fmt::format_string<T...> format, T&&... args) {
  std::fputs(escape_unprintable(fmt::format(format, std::forward<T>(args)...)).c_str(), f);
}

template <typename... T>
void say(fmt::format_string<T...> format, T&&... args) {
  say(stdout, format, std::forward<T>(args)...);
}

}  // namespace vgc::cli
