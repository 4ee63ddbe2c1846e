// bounded_text.cpp — see bounded_text.h.
#include "bounded_text.h"

namespace vgc {

std::string grouped_count(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string bounded_text(std::string_view s, std::size_t limit) {
  if (s.size() <= limit) return std::string(s);
  // s[cut] is the first byte left out: while it continues a UTF-8 sequence
  // (at most 3 bytes do), the cut moves back to where that sequence starts,
  // so what is kept never ends in half a character.
  std::size_t cut = limit;
  for (int i = 0; i < 3 && cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80; ++i) --cut;
  const std::string shown = limit % 1024 == 0 ? std::to_string(limit / 1024) + " KiB" : grouped_count(limit) + " bytes";
  return std::string(s.substr(0, cut)) + "\u2026 (" + grouped_count(s.size()) + " bytes, first " + shown + " shown)";
}

}  // namespace vgc
