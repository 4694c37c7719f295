#include "scene/specular_roughness.h"

#include <algorithm>
#include <cmath>

namespace glint {

float specular_exponent_from_roughness(float roughness) {
  const float alpha = std::max(roughness * roughness, 1e-3f);  // avoids dividing by zero at roughness 0
  return std::clamp(2.0f / (alpha * alpha) - 2.0f, 1.0f, 2048.0f);
}

float roughness_from_specular_exponent(float exponent) {
  if (!(exponent >= 0.0f) || !std::isfinite(exponent)) return 1.0f;
  return std::sqrt(std::sqrt(2.0f / (exponent + 2.0f)));
}

}  // namespace glint
