#version 450 core
// Up to kMaxLevels levels of the depth pyramid in one dispatch (DepthPyramidPass, docs/ssr.md "Depth
// pyramid"), from the level below them: with FROM_GBUFFER that is level 0, made here from the
// G-buffer and written too; without, the image `finer`.
//
// Level 0: per pixel the range of positive linear view depths that the pixel's surface covers. The
// surface is the plane through the G-buffer's world position with its normal
// (include/pixel_plane.glsl), cut by the view rays through the pixel's four corners; a plane seen
// edge-on would span everything, so its range is clamped to [d / 2, 2 d] around the centre depth d.
// Background pixels are infinitely far (both ends kBackgroundDepth). Everything is a ratio of view
// depths, so the pyramid does not depend on the scene's scale or position.
//
// Each further level: min of the minima and max of the maxima of the 2x2 texels under each texel.
// Level sizes halve rounding down (GL's mip sizes), so where the finer level is odd the last texel
// of a row or column also takes the finer level's last texel: every texel then covers every pixel
// that maps to it (clamped to the level's size), which the hierarchical trace in ssr.comp.glsl
// relies on.
//
// Tiles: each work group owns one texel of the dispatch's top level (level_count - 1) and makes the
// whole tree of texels under it, level by level in shared memory: normally 32 x 32 texels of the
// input level, 16 x 16 of the first output level, ..., 1 x 1 of the fifth. The group of a top level's
// last row or column owns its odd remainder too (up to 63 texels of the input level, 31 of the first
// output level). Every texel is made from the same finer texels, in the same order, as one dispatch
// per level with the rule above would make it.
layout(local_size_x = 16, local_size_y = 16) in;

const int kGroupSize = 16;
const int kMaxLevels = 5;                    // DepthPyramidPass::kLevelsPerDispatch
const int kTileWidth = (1 << kMaxLevels) - 1;  // widest region of the first output level (31)
const int kOddTileWidth = kTileWidth / 2;      // widest region of the second (15)

#ifdef FROM_GBUFFER
#include "include/frame_constants.glsl"
#include "include/pixel_plane.glsl"

layout(binding = 0, rgba32f) uniform readonly image2D world_position;
layout(binding = 1, rgba16f) uniform readonly image2D world_normal;
layout(binding = 2, rg32f) uniform writeonly image2D pyramid_base;

const float kBackgroundDepth = 3.0e38;

vec2 base_range(ivec2 pixel, ivec2 size) {
  const vec4 position = imageLoad(world_position, pixel);
  if (position.w == 0.0) return vec2(kBackgroundDepth, kBackgroundDepth);
  const vec3 p = view_from_world(position.xyz);
  const vec3 n = mat3(view) * imageLoad(world_normal, pixel).xyz;
  float lo = -p.z, hi = -p.z;
  for (int corner = 0; corner < 4; ++corner) {
    const float depth = pixel_plane_depth(p, n, vec2(pixel + ivec2(corner & 1, corner >> 1)), vec2(size));
    lo = min(lo, depth);
    hi = max(hi, depth);
  }
  return vec2(lo, hi);
}

// A texel of the input level: level 0 made from the G-buffer and stored (every pixel is under exactly
// one texel of the first output level, so it is made once).
vec2 input_texel(ivec2 pixel, ivec2 size) {
  const vec2 range = base_range(pixel, size);
  imageStore(pyramid_base, pixel, vec4(range, 0.0, 0.0));
  return range;
}
ivec2 input_size() { return imageSize(world_position); }
#else
layout(binding = 0, rg32f) uniform readonly image2D finer;  // the level below this dispatch's first

vec2 input_texel(ivec2 texel, ivec2 size) { return imageLoad(finer, texel).rg; }
ivec2 input_size() { return imageSize(finer); }
#endif

// Output levels, consecutive from the first; units of levels past level_count are not read.
layout(binding = 3, rg32f) uniform writeonly image2D coarser[kMaxLevels];
uniform int level_count;  // 1..kMaxLevels; 0 only with FROM_GBUFFER for a 1 x 1 image (level 0 alone)

// Level j's texels under this group, [first, end) of every level down to the input level (j = -1).
shared vec2 tile[kTileWidth * kTileWidth + kOddTileWidth * kOddTileWidth];

// The last finer texel under `texel` of a coarse_size level over a fine_size one.
ivec2 last_under(ivec2 texel, ivec2 coarse_size, ivec2 fine_size) {
  ivec2 last = min(2 * texel + 1, fine_size - 1);
  if (texel.x == coarse_size.x - 1) last.x = fine_size.x - 1;
  if (texel.y == coarse_size.y - 1) last.y = fine_size.y - 1;
  return last;
}

// The group's region of a level `steps` levels below the top (size `size`, top size `top_size`):
// the texels under the top texel `top`.
void region(ivec2 top, ivec2 top_size, int steps, ivec2 size, out ivec2 first, out ivec2 end) {
  first = top << steps;
  end = (top + 1) << steps;
  if (top.x == top_size.x - 1) end.x = size.x;
  if (top.y == top_size.y - 1) end.y = size.y;
}

// Where level j's region lives in `tile`: even levels at 0 with rows of kTileWidth, odd ones after
// them with rows of kOddTileWidth (a level reads the previous one's while it writes its own).
int tile_offset(int j) { return (j & 1) == 0 ? 0 : kTileWidth * kTileWidth; }
int tile_stride(int j) { return (j & 1) == 0 ? kTileWidth : kOddTileWidth; }

void main() {
  const ivec2 top = ivec2(gl_WorkGroupID.xy);
  const ivec2 local = ivec2(gl_LocalInvocationID.xy);
#ifdef FROM_GBUFFER
  if (level_count == 0) {
    if (all(equal(local, ivec2(0)))) input_texel(top, input_size());
    return;
  }
#endif
  const ivec2 top_size = imageSize(coarser[level_count - 1]);

  // The first output level, from the input level.
  {
    const ivec2 size = imageSize(coarser[0]);
    const ivec2 fine_size = input_size();
    ivec2 first, end;
    region(top, top_size, level_count - 1, size, first, end);
    for (int y = first.y + local.y; y < end.y; y += kGroupSize) {
      for (int x = first.x + local.x; x < end.x; x += kGroupSize) {
        const ivec2 texel = ivec2(x, y);
        const ivec2 last = last_under(texel, size, fine_size);
        vec2 range = vec2(3.4e38, -3.4e38);
        for (int fy = 2 * y; fy <= last.y; ++fy) {
          for (int fx = 2 * x; fx <= last.x; ++fx) {
            const vec2 v = input_texel(ivec2(fx, fy), fine_size);
            range = vec2(min(range.x, v.x), max(range.y, v.y));
          }
        }
        imageStore(coarser[0], texel, vec4(range, 0.0, 0.0));
        tile[tile_offset(0) + (y - first.y) * tile_stride(0) + (x - first.x)] = range;
      }
    }
  }

  // Each further level from the one before it, in shared memory.
  for (int j = 1; j < level_count; ++j) {
    memoryBarrierShared();
    barrier();
    const ivec2 size = imageSize(coarser[j]);
    const ivec2 fine_size = imageSize(coarser[j - 1]);
    ivec2 first, end, fine_first, fine_end;
    region(top, top_size, level_count - 1 - j, size, first, end);
    region(top, top_size, level_count - j, fine_size, fine_first, fine_end);
    for (int y = first.y + local.y; y < end.y; y += kGroupSize) {
      for (int x = first.x + local.x; x < end.x; x += kGroupSize) {
        const ivec2 texel = ivec2(x, y);
        const ivec2 last = last_under(texel, size, fine_size);
        vec2 range = vec2(3.4e38, -3.4e38);
        for (int fy = 2 * y; fy <= last.y; ++fy) {
          for (int fx = 2 * x; fx <= last.x; ++fx) {
            const vec2 v = tile[tile_offset(j - 1) + (fy - fine_first.y) * tile_stride(j - 1) + (fx - fine_first.x)];
            range = vec2(min(range.x, v.x), max(range.y, v.y));
          }
        }
        imageStore(coarser[j], texel, vec4(range, 0.0, 0.0));
        tile[tile_offset(j) + (y - first.y) * tile_stride(j) + (x - first.x)] = range;
      }
    }
  }
}
