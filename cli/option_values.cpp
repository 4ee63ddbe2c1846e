// option_values.cpp — see option_values.h.
#include "option_values.h"

#include <fmt/core.h>

#include <charconv>
#include <cmath>
#include <utility>

namespace vgc::cli {
namespace {

// A value as the message quotes it: short, so a huge argument is not
// printed whole.
std::string shown_value(const std::string& s) {
  if (s.size() <= 60) return "'" + s + "'";
  return "'" + s.substr(0, 60) + "...' (" + std::to_string(s.size()) + " bytes)";
}

// The exact text CLI11 reads back as `v` (strtold reads hexadecimal floats exactly).
std::string exact_text(double v) { return fmt::format("{:a}", v); }

}  // namespace

bool parse_whole_number(std::string_view s, std::uint64_t* out) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string_view::npos) return false;
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v, 10);
  if (ec != std::errc() || end != s.data() + s.size()) return false;
  *out = v;
  return true;
}

bool parse_decimal(std::string_view s, double* out) {
  // from_chars (general format) takes "inf", "nan" and "-"; a leading '+'
  // it does not. Only digits, one point, an exponent and a sign are let in.
  if (s.empty() || s.find_first_not_of("0123456789.eE+-") != std::string_view::npos) return false;
  std::string_view body = s;
  if (body.front() == '+') body.remove_prefix(1);
  double v = 0;
  const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), v, std::chars_format::general);
  if (ec != std::errc() || end != body.data() + body.size() || !std::isfinite(v)) return false;
  *out = v;
  return true;
}

CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi, std::string what) {
  return CLI::Validator(
      [lo, hi, what](std::string& s) -> std::string {
        std::uint64_t v = 0;
        if (!parse_whole_number(s, &v) || v < lo || v > hi)
          return fmt::format("takes a whole number of {} from {} to {}, got {}", what, lo, hi, shown_value(s));
        s = std::to_string(v);  // no leading zeros: CLI11 reads "010" as octal
        return "";
      },
      fmt::format("UINT:{}..{}", lo, hi));
}

CLI::Validator decimal_in(double lo, double hi, std::string what) {
  return CLI::Validator(
      [lo, hi, what](std::string& s) -> std::string {
        double v = 0;
        if (!parse_decimal(s, &v) || v < lo || v > hi)
          return fmt::format("takes a number {} from {:g} to {:g}, got {}", what, lo, hi, shown_value(s));
        s = exact_text(v);
        return "";
      },
      fmt::format("NUMBER:{:g}..{:g}", lo, hi));
}

CLI::Validator seconds(std::string what) {
  return CLI::Validator(
      [what](std::string& s) -> std::string {
        double v = 0;
        if (!parse_decimal(s, &v) || !(v > 0) || v > kMaxSeconds)
          return fmt::format("takes a positive number of seconds {}, at most {:.0f} (a year), got {}", what,
                             kMaxSeconds, shown_value(s));
        s = exact_text(v);
        return "";
      },
      "SECONDS");
}

void refuse_empty_values(CLI::App& app) {
  const CLI::Validator non_empty(
      [](std::string& s) -> std::string { return s.empty() ? "is empty: give it a value (see --help)" : ""; }, "");
  for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    for (CLI::Option* opt : sub->get_options([](const CLI::Option* o) { return o->get_type_size_min() > 0; }))
      opt->check(non_empty);
    refuse_empty_values(*sub);
  }
}

}  // namespace vgc::cli
