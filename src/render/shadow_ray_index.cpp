#include "render/shadow_ray_index.h"

#include "core/math.h"

namespace glint::render {
namespace shader {

// shaders/include/shadow_ray_index.glsl is written in the subset of GLSL that glm also speaks.
using glm::ivec2;
using glm::min;
#include "../../shaders/include/shadow_ray_index.glsl"

}  // namespace shader

std::size_t shadow_ray_index(int x, int y, int width, int height) {
  return static_cast<std::size_t>(shader::shadow_ray_index(shader::ivec2(x, y), shader::ivec2(width, height)));
}

ShadowRayBlock shadow_ray_block() { return {shader::kShadowRayBlock.x, shader::kShadowRayBlock.y}; }

}  // namespace glint::render
