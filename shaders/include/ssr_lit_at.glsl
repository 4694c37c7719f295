// SSR's colour at a trusted hit (docs/ssr.md step 6), shared by the march when it fetches the colour
// itself (ssr.comp.glsl, colour_in_march) and by the colour pass (ssr_colour.comp.glsl). The
// including shader declares the images `world_position` (rgba32f) and `lit` (rgba16f) and the ivec2
// `screen_size` before including this.
// The lit colour where the ray met the surface: bilinear between the pixel centres around `point`
// (inside `hit_pixel`), over the neighbours on the hit's surface only: a neighbour off the hit's
// plane by more than kSamePlane footprints (the hit pixel's world size) is another surface. (Its
// normal is not compared too: that cost 0.06 ms of SSR's 0.23 on an H100 for a few ten-thousandths
// of SSIM, docs/ssr.md.) The hit pixel's own colour alone was the reflection of the pixel centre, up
// to half a pixel from the hit: textured walls' reflections came out shifted (docs/ssr.md "Where
// the hit is").
const float kSamePlane = 0.5;
vec3 lit_at(vec2 point, ivec2 hit_pixel, vec3 hit_position, vec3 hit_normal, float footprint) {
  const vec2 q = clamp(point, vec2(hit_pixel), vec2(hit_pixel + 1)) - 0.5;
  const ivec2 base = ivec2(floor(q));
  const vec2 f = q - vec2(base);
  vec3 sum = vec3(0.0);
  float total = 0.0;
  for (int i = 0; i < 4; ++i) {
    const ivec2 corner = ivec2(i & 1, i >> 1);
    const ivec2 texel = clamp(base + corner, ivec2(0), screen_size - 1);
    const float w = mix(1.0 - f.x, f.x, float(corner.x)) * mix(1.0 - f.y, f.y, float(corner.y));
    const vec4 position = imageLoad(world_position, texel);
    const bool same_surface = texel == hit_pixel ||
                              (position.w != 0.0 &&
                               abs(dot(position.xyz - hit_position, hit_normal)) <= kSamePlane * footprint);
    if (w > 0.0 && same_surface) {
      sum += w * imageLoad(lit, texel).rgb;
      total += w;
    }
  }
  return total > 0.0 ? sum / total : imageLoad(lit, hit_pixel).rgb;
}
