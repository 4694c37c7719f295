// The two rules of the depth pyramid (DepthPyramidPass, docs/ssr.md "Depth pyramid"), shared by its
// two dispatches (depth_pyramid_tiles.comp.glsl, depth_pyramid_tail.comp.glsl).
#include "include/frame_constants.glsl"
#include "include/pixel_plane.glsl"

const float kPyramidBackgroundDepth = 3.0e38;

// Level 0: per pixel the range [min, max] of positive linear view depths that the pixel's surface
// covers. The surface is the plane through the G-buffer's world position with its normal
// (include/pixel_plane.glsl), cut by the view rays through the pixel's four corners; a plane seen
// edge-on would span everything, so its range is clamped to [d / 2, 2 d] around the centre depth d.
// Background pixels (position.w = 0) are infinitely far (both ends kPyramidBackgroundDepth).
// Everything is a ratio of view depths, so the pyramid does not depend on the scene's scale or
// position. `size` is the image's.
vec2 depth_pyramid_base(ivec2 pixel, ivec2 size, vec4 position, vec3 world_normal) {
  if (position.w == 0.0) return vec2(kPyramidBackgroundDepth);
  const vec3 p = view_from_world(position.xyz);
  const vec3 n = mat3(view) * world_normal;
  float lo = -p.z, hi = -p.z;
  for (int corner = 0; corner < 4; ++corner) {
    const float depth = pixel_plane_depth(p, n, vec2(pixel + ivec2(corner & 1, corner >> 1)), vec2(size));
    lo = min(lo, depth);
    hi = max(hi, depth);
  }
  return vec2(lo, hi);
}

// Levels 1..n: a texel holds the min of the minima and the max of the maxima of the finer texels
// from 2 * texel to this last one (per axis). Level sizes halve rounding down (GL's mip sizes), so
// where the finer level is odd the last texel of a row or column also takes the finer level's last
// texel: a finer texel j belongs to coarser texel min(j / 2, coarse_size - 1), and every texel then
// covers every pixel that maps to it (min(pixel >> level, size - 1)), which the hierarchical trace
// (include/ssr_march.glsl) relies on.
ivec2 depth_pyramid_last_finer(ivec2 texel, ivec2 coarse_size, ivec2 fine_size) {
  return ivec2(texel.x == coarse_size.x - 1 ? fine_size.x - 1 : 2 * texel.x + 1,
               texel.y == coarse_size.y - 1 ? fine_size.y - 1 : 2 * texel.y + 1);
}

vec2 depth_pyramid_merge(vec2 a, vec2 b) { return vec2(min(a.x, b.x), max(a.y, b.y)); }

// The start of a merge: merging anything into it gives that thing.
const vec2 kPyramidEmptyRange = vec2(3.4e38, -3.4e38);
