// number_text.cpp — see number_text.h.
#include "number_text.h"

#include <charconv>
#include <cmath>
#include <cstring>

namespace vgc {
namespace {

constexpr std::uint64_t kDefaultNan64 = 0x7FF8000000000000ull;
constexpr std::uint32_t kDefaultNan32 = 0x7FC00000u;

template <class F> std::string format_finite(F v) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest round-trip form
  return std::string(buf, r.ptr);
}

char hex_digit(unsigned v) { return "0123456789ABCDEF"[v & 15]; }

std::string hex_bits(std::uint64_t bits, int nibbles) {
  std::string s = "0x";
  for (int i = nibbles - 1; i >= 0; --i) s += hex_digit(static_cast<unsigned>(bits >> (4 * i)));
  return s;
}

bool parse_hex_or_dec(std::string_view s, std::uint64_t* out) {
  if (s.empty()) return false;
  int base = 10;
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    s.remove_prefix(2);
    base = 16;
  }
  if (s.empty() || s[0] == '+' || s[0] == '-') return false;
  auto r = std::from_chars(s.data(), s.data() + s.size(), *out, base);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// "nan", "-nan", "nan(0x...)", "-nan(0x...)": the bits of the whole value.
template <class Bits> bool parse_nan(std::string_view s, Bits default_nan, Bits* bits) {
  bool neg = false;
  if (!s.empty() && s[0] == '-') {
    neg = true;
    s.remove_prefix(1);
  }
  if (s.substr(0, 3) != "nan") return false;
  s.remove_prefix(3);
  Bits b = default_nan;
  if (!s.empty()) {
    if (s.front() != '(' || s.back() != ')') return false;
    std::uint64_t v = 0;
    if (!parse_hex_or_dec(s.substr(1, s.size() - 2), &v)) return false;
    if (v > static_cast<Bits>(~Bits{0})) return false;
    b = static_cast<Bits>(v);
    // The bits named must be a NaN, and carry the sign themselves.
    constexpr int kBits = sizeof(Bits) * 8;
    const Bits sign = Bits{1} << (kBits - 1);
    if (neg && (b & sign)) return false;
    if (neg) b |= sign;
  } else if (neg) {
    b |= Bits{1} << (sizeof(Bits) * 8 - 1);
  }
  *bits = b;
  return true;
}

template <class F, class Bits> std::string format_float(F v, Bits default_nan) {
  if (std::isnan(v)) {
    Bits bits;
    std::memcpy(&bits, &v, sizeof bits);
    if (bits == default_nan) return "nan";
    return "nan(" + hex_bits(bits, sizeof(Bits) * 2) + ")";
  }
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  return format_finite(v);
}

template <class F, class Bits> bool parse_float(std::string_view s, Bits default_nan, F* out) {
  if (s.empty()) return false;
  if (s == "inf") {
    *out = INFINITY;
    return true;
  }
  if (s == "-inf") {
    *out = -INFINITY;
    return true;
  }
  Bits bits;
  if (parse_nan(s, default_nan, &bits)) {
    F v;
    std::memcpy(&v, &bits, sizeof v);
    if (!std::isnan(v)) return false;
    *out = v;
    return true;
  }
  // Finite decimal or hex-float text only; from_chars accepts "inf"/"nan"
  // spellings too, so insist on a digit-led (optionally signed) mantissa.
  std::string_view body = s[0] == '-' ? s.substr(1) : s;
  if (body.empty() || !(std::isdigit(static_cast<unsigned char>(body[0])) || body[0] == '.'))
    return false;
  F v{};
  auto fmt = std::chars_format::general;
  const char* begin = s.data();
  std::string tmp;
  if (body.size() > 2 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X')) {
    if (body[2] == '-' || body[2] == '+') return false;  // the sign goes before "0x" only
    fmt = std::chars_format::hex;  // from_chars wants hex floats without "0x"
    tmp = std::string(s[0] == '-' ? "-" : "") + std::string(body.substr(2));
    begin = tmp.data();
    s = tmp;
  }
  auto r = std::from_chars(begin, begin + s.size(), v, fmt);
  if (r.ec != std::errc() || r.ptr != begin + s.size()) return false;
  *out = v;
  return true;
}

}  // namespace

std::string format_f64(double v) { return format_float<double, std::uint64_t>(v, kDefaultNan64); }
std::string format_f32(float v) { return format_float<float, std::uint32_t>(v, kDefaultNan32); }

std::string format_uint(std::uint32_t v, int bits) {
  const std::uint32_t all = bits >= 32 ? 0xFFFFFFFFu : ((1u << bits) - 1u);
  if (v == all) return hex_bits(v, bits / 4);
  return std::to_string(v);
}

bool parse_f64(std::string_view s, double* out) {
  return parse_float<double, std::uint64_t>(s, kDefaultNan64, out);
}
bool parse_f32(std::string_view s, float* out) {
  return parse_float<float, std::uint32_t>(s, kDefaultNan32, out);
}

bool parse_uint(std::string_view s, int bits, std::uint32_t* out) {
  std::uint64_t v = 0;
  if (!parse_hex_or_dec(s, &v)) return false;
  const std::uint64_t max = bits >= 32 ? 0xFFFFFFFFull : ((1ull << bits) - 1ull);
  if (v > max) return false;
  *out = static_cast<std::uint32_t>(v);
  return true;
}

std::string format_quoted(std::string_view s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c >= 0x7F) {
      out += "\\x";
      out += hex_digit(c >> 4);
      out += hex_digit(c);
    } else {
      out += static_cast<char>(c);
    }
  }
  out += '"';
  return out;
}

bool parse_quoted(std::string_view s, std::string* out, std::size_t* used, std::size_t* error_at) {
  out->clear();
  if (s.empty() || s[0] != '"') {
    *error_at = 0;
    return false;
  }
  std::size_t i = 1;
  while (i < s.size()) {
    const char c = s[i];
    if (c == '"') {
      *used = i + 1;
      return true;
    }
    if (c == '\\') {
      if (i + 1 >= s.size()) break;
      const char e = s[i + 1];
      if (e == '"' || e == '\\') {
        *out += e;
        i += 2;
        continue;
      }
      if (e == 'x' && i + 3 < s.size() + 0 && std::isxdigit(static_cast<unsigned char>(s[i + 2])) &&
          std::isxdigit(static_cast<unsigned char>(s[i + 3]))) {
        auto nib = [](char h) {
          return static_cast<unsigned>(std::isdigit(static_cast<unsigned char>(h))
                                           ? h - '0'
                                           : (std::tolower(static_cast<unsigned char>(h)) - 'a' + 10));
        };
        *out += static_cast<char>(nib(s[i + 2]) * 16 + nib(s[i + 3]));
        i += 4;
        continue;
      }
      *error_at = i;
      return false;
    }
    if (static_cast<unsigned char>(c) < 0x20) {  // a raw control byte or newline inside quotes
      *error_at = i;
      return false;
    }
    *out += c;
    ++i;
  }
  *error_at = s.size();  // unterminated
  return false;
}

}  // namespace vgc
