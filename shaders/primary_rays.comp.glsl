#version 450 core
// Primary rays (PrimaryRayPass, docs/render.md "Ray-traced primary visibility"): one camera ray per
// pixel, dense (ray index = y * width + x, GL rows: bottom first), through the pixel centre, which is
// where the rasteriser samples coverage and where the visibility resolve computes its barycentrics.
// The ray runs from the near plane's point to the far plane's point of the pixel centre, t in
// [0, 1]: the tracer sees exactly the depth range the rasteriser keeps after clipping.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"

struct Ray { vec3 origin; float t_min; vec3 direction; float t_max; };  // accel::Ray
layout(std430, binding = 10) writeonly buffer PrimaryRays { Ray rays[]; };

// The point of the pixel ray at NDC depth z, relative to the camera (camera-relative: the direction
// stays exact far from the origin; only the origin is rounded to world coordinates).
vec3 unproject_relative(vec2 ndc, float z) {
  const vec4 view_point = inverse_projection * vec4(ndc, z, 1.0);
  return mat3(inverse_view) * (view_point.xyz / view_point.w);
}

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, viewport.xy))) return;
  const vec2 ndc = (vec2(pixel) + 0.5) / vec2(viewport.xy) * 2.0 - 1.0;
  const vec3 near_point = unproject_relative(ndc, -1.0);
  const vec3 far_point = unproject_relative(ndc, 1.0);
  rays[pixel.y * viewport.x + pixel.x] = Ray(camera_position.xyz + near_point, 0.0, far_point - near_point, 1.0);
}
