// transcript_values.h — how an r6 interop transcript writes bytes and real
// values (docs/verse_wire.md section 12): the recorder (r6_interop/r6_tap.cpp,
// what r6's library decoded) and the replay test (r6_replay_test.cpp, what
// vgc decoded) must write and read them alike for the two to be compared.
#pragma once

#include <cstdio>
#include <string>

namespace vgc_transcript {

inline std::string r32(float v) {  // a real32: the shortest text that reads back exactly
  char b[64];
  std::snprintf(b, sizeof b, "%.9g", static_cast<double>(v));
  return b;
}

inline std::string r64(double v) {  // a real64, likewise
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// Bytes as lower-case hex, two digits a byte (the transcript's key, raw and
// plain lines; also how the codec tests write expected bytes).
inline std::string hex(const std::string& bytes) {
  static const char* d = "0123456789abcdef";
  std::string out;
  for (unsigned char c : bytes) {
    out += d[c >> 4];
    out += d[c & 15];
  }
  return out;
}

// The bytes of hex() text.
inline std::string unhex(const std::string& h) {
  std::string out;
  for (std::size_t i = 0; i + 1 < h.size(); i += 2) out += static_cast<char>(std::stoi(h.substr(i, 2), nullptr, 16));
  return out;
}

}  // namespace vgc_transcript
