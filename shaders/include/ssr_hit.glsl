// A trusted SSR hit, from the march (ssr.comp.glsl) to the colour fetch (ssr_colour.comp.glsl),
// stored per pixel in an rgba32ui image (SsrPass::hits(), render::kSsrHitFormat):
//   x, y  the point where the ray met the hit pixel's surface (float bits; pixels, y up)
//   z     the hit pixel, x | y << 16 (textures are at most 16384 wide); kNoSsrHit: no trusted hit
//   w     the reflection's BRDF weight (float bits; 1 for a mirror, docs/glossy.md)
struct SsrHit {
  vec2 point;
  ivec2 pixel;
  float weight;
};

const uint kNoSsrHit = 0xFFFFFFFFu;

SsrHit ssr_no_hit() { return SsrHit(vec2(0.0), ivec2(-1), 0.0); }

uvec4 pack_ssr_hit(SsrHit hit) {
  if (hit.pixel.x < 0) return uvec4(0u, 0u, kNoSsrHit, 0u);
  return uvec4(floatBitsToUint(hit.point), uint(hit.pixel.x) | uint(hit.pixel.y) << 16, floatBitsToUint(hit.weight));
}

bool unpack_ssr_hit(uvec4 stored, out SsrHit hit) {
  hit = ssr_no_hit();
  if (stored.z == kNoSsrHit) return false;
  hit.point = uintBitsToFloat(stored.xy);
  hit.pixel = ivec2(stored.z & 0xFFFFu, stored.z >> 16);
  hit.weight = uintBitsToFloat(stored.w);
  return true;
}
