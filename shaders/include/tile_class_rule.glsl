// The tile rule of `--reflections auto`: the GLSL twin of render::classify_tile
// (src/render/tile_classification.h states it; tests/render/tile_classification_test.cpp keeps the
// two equal). Classes as render::TileClass.
const uint kTileNone = 0u;
const uint kTileSsrOnly = 1u;
const uint kTileSsrFallback = 2u;
const uint kTileRtOnly = 3u;

uint classify_tile(uint reflective, uint known, uint failed_known, float ssr_only_at_most, float rt_at_least,
                   float min_known_fraction) {
  if (reflective == 0u) return kTileNone;
  if (known == 0u || float(known) < min_known_fraction * float(reflective))
    return rt_at_least <= 0.0 ? kTileRtOnly : kTileSsrFallback;
  // render::failure_rate's integer division, bit for bit (a float division may be off by 2.5 ulp).
  const float f = float((failed_known * 65536u) / known) / 65536.0;
  if (f <= ssr_only_at_most) return kTileSsrOnly;
  if (f >= rt_at_least) return kTileRtOnly;
  return kTileSsrFallback;
}
