// number_text.h — exact text forms of the numbers in commands and snapshots.
//
// Spec: docs/spec_facts.md (field widths: uint8/16/32, real32, real64).
//
// Rationale: the command language promises that every value round-trips
// bit-exactly, NaN payloads and -0.0 included. Finite values use the shortest
// decimal that reads back to the same bits (std::to_chars); non-finite ones
// use "inf", "-inf", "nan" (the default quiet NaN) and "nan(0x<bits>)" /
// "-nan(0x<bits>)" naming the full bit pattern of any other NaN. Integers are
// decimal, except the all-ones value of a field's width, printed 0xFF,
// 0xFFFF or 0xFFFFFFFF because it means "none", "pick one" or "maximum".
// Parsers return false on anything else and never throw.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace vgc {

std::string format_f64(double v);
std::string format_f32(float v);
// `bits` is the field width: 8, 16 or 32.
std::string format_uint(std::uint32_t v, int bits);

// Whole-token parsers. Integers: decimal or 0x-hex, no sign, within `bits`.
bool parse_f64(std::string_view s, double* out);
bool parse_f32(std::string_view s, float* out);
bool parse_uint(std::string_view s, int bits, std::uint32_t* out);

// Names and labels: always double-quoted; \" \\ and \xHH escapes, bytes
// outside printable ASCII always escaped. parse_quoted reads one quoted
// string at the start of `s`, sets *used to the bytes consumed, and on
// failure sets *error_at to the offset of the offending byte.
std::string format_quoted(std::string_view s);
bool parse_quoted(std::string_view s, std::string* out, std::size_t* used, std::size_t* error_at);

}  // namespace vgc
