#include "core/math.h"

namespace glint {

Aabb transform_aabb(const mat4& transform, const Aabb& box) {
  Aabb result;
  if (box.empty()) return result;
  for (int corner = 0; corner < 8; ++corner) {
    const vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                 (corner & 4) ? box.max.z : box.min.z);
    result.extend(vec3(transform * vec4(p, 1.0f)));
  }
  return result;
}

}  // namespace glint
