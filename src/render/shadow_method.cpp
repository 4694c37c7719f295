#include "render/shadow_method.h"

#include "core/error.h"

#include <cmath>

namespace glint::render {

void ShadowSettings::validate() const {
  if (hybrid_cube_divisor < 1)
    fail("shadow settings: hybrid_cube_divisor = {} must be at least 1", hybrid_cube_divisor);
  if (!(std::isfinite(hybrid_depth_edge_fraction) && hybrid_depth_edge_fraction > 0.0f))
    fail("shadow settings: hybrid_depth_edge_fraction = {} must be finite and > 0", hybrid_depth_edge_fraction);
}

}  // namespace glint::render
