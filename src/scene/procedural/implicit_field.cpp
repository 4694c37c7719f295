#include "scene/procedural/implicit_field.h"

namespace glint::procedural {

void ImplicitField::values_near(const vec3&, float, const vec3* points, float* out, std::size_t count) const {
  for (std::size_t i = 0; i < count; ++i) out[i] = value(points[i]);
}

}  // namespace glint::procedural
