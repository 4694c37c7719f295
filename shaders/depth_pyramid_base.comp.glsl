#version 450 core
// Level 0 of the depth pyramid (DepthPyramidPass, docs/ssr.md "Depth pyramid"): per pixel the range
// of positive linear view depths that the pixel's surface covers. The surface is the plane through
// the G-buffer's world position with its normal (include/pixel_plane.glsl), cut by the view rays
// through the pixel's four corners; a plane seen edge-on would span everything, so its range is
// clamped to [d / 2, 2 d] around the centre depth d. Background pixels are infinitely far (both ends kBackgroundDepth).
// Everything is a ratio of view depths, so the pyramid does not depend on the scene's scale or
// position.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"
#include "include/pixel_plane.glsl"

layout(binding = 0, rgba32f) uniform readonly image2D world_position;
layout(binding = 1, rgba16f) uniform readonly image2D world_normal;
layout(binding = 2, rg32f) uniform writeonly image2D pyramid_base;

const float kBackgroundDepth = 3.0e38;

void main() {
  const ivec2 size = imageSize(world_position);
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  const vec4 position = imageLoad(world_position, pixel);
  if (position.w == 0.0) {
    imageStore(pyramid_base, pixel, vec4(kBackgroundDepth, kBackgroundDepth, 0.0, 0.0));
    return;
  }
  const vec3 p = view_from_world(position.xyz);
  const vec3 n = mat3(view) * imageLoad(world_normal, pixel).xyz;
  float lo = -p.z, hi = -p.z;
  for (int corner = 0; corner < 4; ++corner) {
    const float depth = pixel_plane_depth(p, n, vec2(pixel + ivec2(corner & 1, corner >> 1)), vec2(size));
    lo = min(lo, depth);
    hi = max(hi, depth);
  }
  imageStore(pyramid_base, pixel, vec4(lo, hi, 0.0, 0.0));
}
