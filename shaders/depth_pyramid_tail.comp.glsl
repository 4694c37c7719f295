#version 450 core
// Dispatch 2 of the depth pyramid (DepthPyramidPass, docs/ssr.md "Depth pyramid"): the levels past
// the tiles' level K, each from the one below (include/depth_pyramid.glsl), in one work group that
// waits for itself between levels instead of a dispatch and a barrier per level. Its invocations
// stride over each level's texels, so any size works (level K of an 8K image is 240 x 135).
// The levels are read back from the image (coherent, made visible by memoryBarrierImage), not
// kept in shared memory, which could not hold large ones.
layout(local_size_x = 256) in;

#include "include/depth_pyramid.glsl"

// Units 0..7: levels first - 1 .. first + 6 of this dispatch (bound to the last level past it).
// 8 is the number of image units GL guarantees a compute shader; more levels than 7 (images of
// 8192 pixels or more a side) take another dispatch.
layout(binding = 0, rg32f) coherent uniform image2D levels[8];

uniform int level_count;  // levels[1..level_count] are built, each from the one before

void main() {
  for (int level = 1; level <= level_count; ++level) {
    const ivec2 fine_size = imageSize(levels[level - 1]), coarse_size = imageSize(levels[level]);
    for (int i = int(gl_LocalInvocationIndex); i < coarse_size.x * coarse_size.y; i += int(gl_WorkGroupSize.x)) {
      const ivec2 texel = ivec2(i % coarse_size.x, i / coarse_size.x);
      const ivec2 last = depth_pyramid_last_finer(texel, coarse_size, fine_size);
      vec2 range = kPyramidEmptyRange;
      for (int y = 2 * texel.y; y <= last.y; ++y) {
        for (int x = 2 * texel.x; x <= last.x; ++x) {
          range = depth_pyramid_merge(range, imageLoad(levels[level - 1], ivec2(x, y)).rg);
        }
      }
      imageStore(levels[level], texel, vec4(range, 0.0, 0.0));
    }
    memoryBarrierImage();
    barrier();
  }
}
