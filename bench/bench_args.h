// bench_args.h — the bench programs' numeric arguments, read exactly.
//
// Spec: none (a tool's command line). Rationale: a bench run that reads
// "--repeats 2x" as 2 or "--levels x" as 0 measures something nobody
// asked for; the project's rule is std::from_chars for every number and
// exit 2 naming the argument for a value that is not one.
#pragma once

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace vgc::bench {

// `text` as a whole number in [lo, hi]; otherwise says so on stderr,
// naming `program` and `what` (the option or the argument), and exits 2.
inline long long count_argument(const char* program, const char* what, std::string_view text, long long lo,
                                long long hi) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || v < lo || v > hi) {
    std::fprintf(stderr, "%s: %s: expected a whole number from %lld to %lld, got '%.*s'\n", program, what, lo, hi,
                 static_cast<int>(text.size() > 40 ? 40 : text.size()), text.data());
    std::exit(2);
  }
  return v;
}

}  // namespace vgc::bench
