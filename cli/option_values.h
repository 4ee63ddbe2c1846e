// option_values.h — how vgc checks the values of its command-line options
// before any work: numbers read with std::from_chars and held to a range,
// and no option given an empty value.
//
// Spec: docs/certify.md (every option of `vgc certify`), and the --help of
// each subcommand. Issue 31, item 7.
//
// Rationale: a value that is empty (`--reports "$DIR"` with DIR unset),
// out of range (`--seed 18446744073709551616`) or meaningless
// (`--budget inf`) must stop vgc at once with exit 2 and a message naming
// the option, never abort after the run, be clamped or be ignored. CLI11
// 2.1's own number conversion reads with strtoull/strtold in base 0
// ("010" is 8, an overflow is clamped, "inf" is a number), so every
// numeric option is checked here first with std::from_chars, decimal only,
// and its text is rewritten to a form CLI11 converts back exactly (plain
// decimal digits for whole numbers, a hexadecimal float for seconds).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <string_view>

namespace vgc::cli {

// The longest time any seconds option takes: a year. Longer overflows the
// clocks' arithmetic and means nothing for a run.
inline constexpr double kMaxSeconds = 365.0 * 24 * 3600;

// `s` as a whole decimal number (digits only: no sign, space, base prefix
// or fraction) that fits a uint64_t.
bool parse_whole_number(std::string_view s, std::uint64_t* out);
// `s` as a finite decimal number (no inf, nan or hexadecimal float).
bool parse_decimal(std::string_view s, double* out);

// A validator (Option::transform) for a whole number in [lo, hi]; `what`
// says what the number counts, for the message ("cases per property").
CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi, std::string what);
// A validator for a number of seconds: finite, above 0, at most kMaxSeconds.
// `what` says what the seconds are for ("for the whole run").
CLI::Validator seconds(std::string what);
// A validator for a finite number in [lo, hi].
CLI::Validator decimal_in(double lo, double hi, std::string what);

// Gives every option of every subcommand of `app` that takes a value
// (positional arguments included) a check that refuses an empty value.
// Call after the subcommands are added.
void refuse_empty_values(CLI::App& app);

}  // namespace vgc::cli
