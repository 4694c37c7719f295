// The tone map and sRGB encoding of a frame (the resolve's last step), written once for both
// languages: shaders/resolve.comp.glsl includes it as GLSL, src/render/tone_map.cpp as C++ (inside a
// namespace with glm's types; glm follows GLSL's names), so the CPU's tone mapping of a linear EXR
// (`glint compare`) is the GPU's, not a copy of it. Keep to what both accept: float literals with
// the f suffix, only GLSL built-ins that glm has, no qualifiers but const.
//
// method: render::ToneMap's value (0 none, 1 reinhard, 2 aces); c: linear colour after exposure.
vec3 apply_tone_map(vec3 c, int method) {
  c = max(c, vec3(0.0f));
  if (method == 1) return c / (1.0f + c);
  if (method == 2) {
    // Narkowicz 2015, "ACES Filmic Tone Mapping Curve" (fit of the ACES RRT + ODT).
    return clamp((c * (2.51f * c + 0.03f)) / (c * (2.43f * c + 0.59f) + 0.14f), 0.0f, 1.0f);
  }
  return min(c, vec3(1.0f));
}

// IEC 61966-2-1 sRGB transfer function.
vec3 srgb_encode(vec3 linear) {
  const vec3 low = linear * 12.92f;
  const vec3 high = 1.055f * pow(linear, vec3(1.0f / 2.4f)) - 0.055f;
  return mix(high, low, lessThanEqual(linear, vec3(0.0031308f)));
}
