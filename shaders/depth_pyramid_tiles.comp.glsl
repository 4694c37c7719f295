#version 450 core
// Dispatch 1 of the depth pyramid (DepthPyramidPass, docs/ssr.md "Depth pyramid"): levels 0 to
// tile_level (K = 5, fewer on images with fewer levels). Each work group owns one texel of level K
// and builds everything under it: since a finer texel j belongs to coarser texel min(j / 2,
// coarse_size - 1), the texels of level L under level-K texel g are g << (K - L) onwards, 2^(K - L)
// of them, except that the last group of a row or column takes the rest of the level (up to
// 2^(K - L + 1) - 1 texels). Level 0 (include/depth_pyramid.glsl) is computed per pixel and merged
// straight into level 1 in registers; levels 2..K are merged in shared memory. No group reads
// another's texels, so one dispatch needs no barrier but the group's own.
//
// 16 x 16 invocations per 32 x 32 pixels: one level-1 texel (2 x 2 pixels) each, except in the
// last groups of a row or column, which loop. K = 5 also fills the 8 image units GL guarantees a
// compute shader: the two inputs and levels 0..5 (texture fetches would not see this dispatch's
// own writes).
layout(local_size_x = 16, local_size_y = 16) in;

#include "include/depth_pyramid.glsl"

const int kMaxTileLevel = 5;  // DepthPyramidPass's kTileLevel

layout(binding = 0, rgba32f) uniform readonly image2D world_position;
layout(binding = 1, rgba16f) uniform readonly image2D world_normal;
// Units 2..7: levels 0..kMaxTileLevel (levels past the last are bound to it and not written).
layout(binding = 2, rg32f) uniform writeonly image2D levels[kMaxTileLevel + 1];

uniform int tile_level;  // K: min(kMaxTileLevel, the pyramid's last level)

// The group's texels of levels 1..K, a level's rows one after another: odd levels from 0, even
// levels from kEvenLevels, so that each level reads the one below while writing the other half.
const int kOddTexels = 31 * 31;   // level 1: at most 2^K - 1 texels a side
const int kEvenTexels = 15 * 15;  // level 2: at most 2^(K-1) - 1
shared vec2 group_texels[kOddTexels + kEvenTexels];

int level_offset(int level) { return (level & 1) == 1 ? 0 : kOddTexels; }

// The group's texels of `level`, first and last per axis.
void group_range(int level, out ivec2 first, out ivec2 last) {
  const ivec2 group = ivec2(gl_WorkGroupID.xy);
  const bvec2 edge = equal(group, imageSize(levels[tile_level]) - 1);
  first = group << (tile_level - level);
  const ivec2 interior_last = first + (1 << (tile_level - level)) - 1;
  const ivec2 level_last = imageSize(levels[level]) - 1;
  last = ivec2(edge.x ? level_last.x : interior_last.x, edge.y ? level_last.y : interior_last.y);
}

vec2 base_texel(ivec2 pixel) {
  return depth_pyramid_base(pixel, imageSize(world_position), imageLoad(world_position, pixel),
                            imageLoad(world_normal, pixel).xyz);
}

void main() {
  const ivec2 invocation = ivec2(gl_LocalInvocationID.xy);
  const ivec2 stride = ivec2(gl_WorkGroupSize.xy);
  if (tile_level == 0) {  // a 1 x 1 image: level 0 is the whole pyramid
    if (invocation == ivec2(0)) imageStore(levels[0], ivec2(0), vec4(base_texel(ivec2(0)), 0.0, 0.0));
    return;
  }

  // Levels 0 and 1.
  {
    ivec2 first, last;
    group_range(1, first, last);
    const ivec2 count = last - first + 1;
    const ivec2 fine_size = imageSize(world_position), coarse_size = imageSize(levels[1]);
    for (int y = invocation.y; y < count.y; y += stride.y) {
      for (int x = invocation.x; x < count.x; x += stride.x) {
        const ivec2 texel = first + ivec2(x, y);
        const ivec2 last_pixel = depth_pyramid_last_finer(texel, coarse_size, fine_size);
        vec2 range = kPyramidEmptyRange;
        for (int py = 2 * texel.y; py <= last_pixel.y; ++py) {
          for (int px = 2 * texel.x; px <= last_pixel.x; ++px) {
            const vec2 v = base_texel(ivec2(px, py));
            imageStore(levels[0], ivec2(px, py), vec4(v, 0.0, 0.0));
            range = depth_pyramid_merge(range, v);
          }
        }
        imageStore(levels[1], texel, vec4(range, 0.0, 0.0));
        group_texels[level_offset(1) + y * count.x + x] = range;
      }
    }
  }

  // Levels 2..K, each from the group's texels of the level below.
  for (int level = 2; level <= tile_level; ++level) {
    barrier();  // the finer level's texels are all in shared memory
    ivec2 fine_first, fine_last, first, last;
    group_range(level - 1, fine_first, fine_last);
    group_range(level, first, last);
    const int fine_row = fine_last.x - fine_first.x + 1;
    const ivec2 count = last - first + 1;
    const ivec2 fine_size = imageSize(levels[level - 1]), coarse_size = imageSize(levels[level]);
    for (int y = invocation.y; y < count.y; y += stride.y) {
      for (int x = invocation.x; x < count.x; x += stride.x) {
        const ivec2 texel = first + ivec2(x, y);
        const ivec2 last_fine = depth_pyramid_last_finer(texel, coarse_size, fine_size) - fine_first;
        vec2 range = kPyramidEmptyRange;
        for (int fy = 2 * texel.y - fine_first.y; fy <= last_fine.y; ++fy) {
          for (int fx = 2 * texel.x - fine_first.x; fx <= last_fine.x; ++fx) {
            range = depth_pyramid_merge(range, group_texels[level_offset(level - 1) + fy * fine_row + fx]);
          }
        }
        imageStore(levels[level], texel, vec4(range, 0.0, 0.0));
        group_texels[level_offset(level) + y * count.x + x] = range;
      }
    }
  }
}
