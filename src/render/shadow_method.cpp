#include "render/shadow_method.h"

#include "core/error.h"

#include <cmath>

namespace glint::render {

std::string_view shadow_method_name(ShadowMethod method) {
  switch (method) {
    case ShadowMethod::cube: return "cube";
    case ShadowMethod::rt: return "rt";
    case ShadowMethod::hybrid: return "hybrid";
  }
  return "unknown";
}

ShadowMethod parse_shadow_method(std::string_view name) {
  for (const ShadowMethod method : {ShadowMethod::cube, ShadowMethod::rt, ShadowMethod::hybrid})
    if (shadow_method_name(method) == name) return method;
  fail("shadow settings: unknown shadow method '{}' (known: cube, rt, hybrid)", name);
}

void ShadowSettings::validate() const {
  if (hybrid_cube_divisor < 1)
    fail("shadow settings: hybrid_cube_divisor = {} must be at least 1", hybrid_cube_divisor);
  if (!(std::isfinite(hybrid_depth_edge_fraction) && hybrid_depth_edge_fraction > 0.0f))
    fail("shadow settings: hybrid_depth_edge_fraction = {} must be finite and > 0", hybrid_depth_edge_fraction);
}

}  // namespace glint::render
