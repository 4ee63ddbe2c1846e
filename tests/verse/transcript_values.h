// transcript_values.h — how an r6 interop transcript writes a real value
// (docs/verse_wire.md section 12): the recorder (r6_interop/r6_tap.cpp,
// what r6's library decoded) and the replay test (r6_replay_test.cpp, what
// vgc decoded) must write them alike for the two to be compared as text.
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

}  // namespace vgc_transcript
