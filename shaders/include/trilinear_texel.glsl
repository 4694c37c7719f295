// Trilinear filtering of a texture array layer from texelFetch (repeat wrapping), for compute
// shaders on Mesa's llvmpipe, which takes about a millisecond per SIMD group for a filtered
// (textureLod, textureGrad) array sample in a compute shader; texelFetch is fast everywhere. Hit
// shading always filters with it; the visibility G-buffer on software renderers only.

// Bilinear sample of mip `level` of texture array layer `layer` at `uv`, wrapping (GL_REPEAT).
vec3 bilinear_texel(sampler2DArray textures, int layer, vec2 uv, int level) {
  // The level's size from level 0's rather than textureSize(textures, level): llvmpipe
  // answers a size query for one lane's level in every lane of the SIMD group, and the lanes of a
  // group hold rays in a run-dependent order, so frames differed from run to run
  // (docs/reliability.md, "Deterministic frames").
  const ivec2 size = max(textureSize(textures, 0).xy >> level, ivec2(1));
  const vec2 position = uv * vec2(size) - 0.5;
  const ivec2 base = ivec2(floor(position));
  const vec2 f = position - vec2(base);
  vec3 row[2];
  for (int dy = 0; dy < 2; ++dy) {
    const int y = ((base.y + dy) % size.y + size.y) % size.y;
    const vec3 left = texelFetch(textures, ivec3((base.x % size.x + size.x) % size.x, y, layer), level).rgb;
    const vec3 right = texelFetch(textures, ivec3(((base.x + 1) % size.x + size.x) % size.x, y, layer), level).rgb;
    row[dy] = mix(left, right, f.x);
  }
  return mix(row[0], row[1], f.y);
}

// Trilinear: the two mip levels around `lod`, blended.
vec3 trilinear_texel(sampler2DArray textures, int layer, vec2 uv, float lod) {
  const float top = float(textureQueryLevels(textures) - 1);
  const float clamped = clamp(lod, 0.0, top);
  const int lower = int(floor(clamped));
  const float blend = clamped - float(lower);
  const vec3 a = bilinear_texel(textures, layer, uv, lower);
  if (blend <= 0.0) return a;
  return mix(a, bilinear_texel(textures, layer, uv, min(lower + 1, int(top))), blend);
}
