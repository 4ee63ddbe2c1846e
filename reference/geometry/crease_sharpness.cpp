// crease_sharpness.cpp — see crease_sharpness.h.
#include "crease_sharpness.h"

#include <algorithm>
#include <cmath>

namespace vgc {

float crease_to_sharpness(std::uint32_t crease) {
  if (crease == 0xFFFFFFFFu) return kSharpnessInfinite;
  if (crease == 0) return kSharpnessSmooth;
  const double exact = 10.0 * static_cast<double>(crease) / 4294967295.0;
  float f = static_cast<float>(exact);
  if (static_cast<double>(f) > exact) f = std::nextafter(f, 0.0f);  // round down
  return f;
}

std::uint32_t combine_edge_creases(const std::vector<std::uint32_t>& stored) {
  if (stored.empty()) return 0;
  return *std::max_element(stored.begin(), stored.end());
}

float edge_sharpness_for(std::uint32_t crease, int face_count) {
  if (face_count != 2) return kSharpnessInfinite;
  return crease_to_sharpness(crease);
}

float subdivide_sharpness(float s) {
  if (is_smooth(s)) return kSharpnessSmooth;
  if (is_infinite(s)) return kSharpnessInfinite;
  if (s > 1.0f) return s - 1.0f;
  return kSharpnessSmooth;
}

CreaseRule determine_vertex_rule(float vertex_sharpness, const std::vector<float>& edge_sharpness) {
  if (is_sharp(vertex_sharpness)) return CreaseRule::Corner;
  int sharp = 0;
  for (float s : edge_sharpness) sharp += is_sharp(s) ? 1 : 0;
  switch (sharp) {
    case 0: return CreaseRule::Smooth;
    case 1: return CreaseRule::Dart;
    case 2: return CreaseRule::Crease;
    default: return CreaseRule::Corner;
  }
}

float fractional_weight_at_vertex(float vertex_sharpness, float child_vertex_sharpness,
                                  const std::vector<float>& edge_sharpness) {
  int count = 0;
  float sum = 0.0f;
  if (is_sharp(vertex_sharpness) && is_smooth(child_vertex_sharpness)) {
    count = 1;
    sum = vertex_sharpness;
  }
  for (float s : edge_sharpness) {
    if (is_sharp(s) && s <= 1.0f) {
      sum += s;
      ++count;
    }
  }
  if (count == 0) return 0.0f;
  const float w = sum / static_cast<float>(count);
  return w > 1.0f ? 1.0f : w;
}

}  // namespace vgc
