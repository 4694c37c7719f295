#version 450 core
// One level of the depth pyramid from the level below it (DepthPyramidPass): min of the minima and
// max of the maxima of the 2x2 texels under each texel. Level sizes halve rounding down (GL's mip
// sizes), so where the finer level is odd the last texel of a row or column also takes the finer
// level's last texel: every texel then covers every pixel that maps to it (clamped to the level's
// size), which the hierarchical trace in ssr.comp.glsl relies on.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rg32f) uniform readonly image2D finer;
layout(binding = 1, rg32f) uniform writeonly image2D coarser;

void main() {
  const ivec2 coarse_size = imageSize(coarser);
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, coarse_size))) return;
  const ivec2 fine_size = imageSize(finer);
  const ivec2 first = 2 * texel;
  ivec2 last = min(first + 1, fine_size - 1);
  if (texel.x == coarse_size.x - 1) last.x = fine_size.x - 1;
  if (texel.y == coarse_size.y - 1) last.y = fine_size.y - 1;
  vec2 range = vec2(3.4e38, -3.4e38);
  for (int y = first.y; y <= last.y; ++y) {
    for (int x = first.x; x <= last.x; ++x) {
      const vec2 v = imageLoad(finer, ivec2(x, y)).rg;
      range = vec2(min(range.x, v.x), max(range.y, v.y));
    }
  }
  imageStore(coarser, texel, vec4(range, 0.0, 0.0));
}
