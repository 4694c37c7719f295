#pragma once
// The dense shadow-ray list's order (shaders/include/shadow_ray_index.glsl, compiled here as C++):
// pixel (x, y) of a width x height image (GL's rows, row 0 at the bottom) has its shadow ray at
// shadow_ray_index(...), a unique index below width * height; the rays go in blocks of 8 x 4 pixels.
#include <cstddef>

namespace glint::render {

std::size_t shadow_ray_index(int x, int y, int width, int height);

// The block of pixels whose rays go one after the other (the GLSL's kShadowRayBlock, 8 x 4: one warp),
// also the work group of the gl backend's inline shadow pass (shadow_rays_inline.comp.glsl).
struct ShadowRayBlock {
  int width, height;
};
ShadowRayBlock shadow_ray_block();

}  // namespace glint::render
