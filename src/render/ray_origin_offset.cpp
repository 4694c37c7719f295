#include "render/ray_origin_offset.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint::render {

float ray_origin_offset(float fraction, const Aabb& world_bounds) {
  const float diagonal = world_bounds.empty() ? 0.0f : glm::length(world_bounds.extent());
  const float by_size = fraction * (diagonal > 0.0f ? diagonal : 1.0f);
  if (world_bounds.empty() || !(fraction > 0.0f)) return by_size;
  return std::max(by_size,
                  kRayOriginOffsetSteps * std::numeric_limits<float>::epsilon() * world_bounds.largest_abs_coordinate());
}

}  // namespace glint::render
