// Where a pixel's shadow ray sits in the dense shadow-ray list (shadow_rays.comp.glsl writes it,
// shadow_ray_mask.comp.glsl reads its answer), written once for both languages: the shaders include
// it as GLSL, src/render/shadow_ray_index.cpp as C++ (glm's ivec2 and min stand in for GLSL's). Keep
// to what both accept: int arithmetic, only built-ins glm has, no qualifiers but const.
//
// The rays go in blocks of kShadowRayBlock (8 x 4 pixels: one warp of 32 rays on NVIDIA GPUs) rather
// than row by row, so the rays a warp traces start close together and walk much the same nodes. The
// list is still dense: bands of 4 rows one after the other, in a band its blocks left to right, in a
// block its rows; the last block of a band is narrower where the width is no multiple of 8 and the
// last band lower where the height is no multiple of 4, so pixel (x, y) of a width x height image
// maps to a unique index below width * height. On an H100 the occlusion query of 921,600 rays took
// 0.50 ms in rows of 32 and 0.42 in blocks (gl backend; docs/perf.md "Ninth round").
const ivec2 kShadowRayBlock = ivec2(8, 4);

int shadow_ray_index(ivec2 pixel, ivec2 size) {
  const int band = pixel.y / kShadowRayBlock.y;
  const int band_height = min(kShadowRayBlock.y, size.y - band * kShadowRayBlock.y);
  const int block = pixel.x / kShadowRayBlock.x;
  const int block_width = min(kShadowRayBlock.x, size.x - block * kShadowRayBlock.x);
  const ivec2 in_block = pixel - ivec2(block * kShadowRayBlock.x, band * kShadowRayBlock.y);
  return band * kShadowRayBlock.y * size.x + block * kShadowRayBlock.x * band_height + in_block.y * block_width +
         in_block.x;
}
