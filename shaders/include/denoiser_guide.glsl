// The reflection denoiser's per-pixel guide (ReflectionDenoiser, docs/glossy.md): what its edge
// tests read of a pixel, in one RGBA32UI texel so that a tap costs one fetch. The temporal pass
// writes it from the G-buffer each frame; this frame's spatial passes read it, and the next frame's
// temporal pass reads it as the previous frame's surface (replacing copies of the position and
// normal images).
//   xyz  the world position's float bits (exact)
//   w    bits 0-10 and 11-21: the unit normal, octahedral, 11 bits a coordinate
//        bits 22-29: roughness (after glossy_roughness), 8-bit unorm
//        bit 30: reflective (geometry with reflectivity > 0); a guide without it is all 0

const uint kGuideReflective = 1u << 30;

vec2 guide_sign(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

uvec4 pack_guide(vec3 position, vec3 normal, float roughness) {
  const vec3 n = normal / (abs(normal.x) + abs(normal.y) + abs(normal.z));
  const vec2 octahedral = n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * guide_sign(n.xy);
  const uvec2 q = uvec2(round(clamp(octahedral * 0.5 + 0.5, 0.0, 1.0) * 2047.0));
  const uint r = uint(round(clamp(roughness, 0.0, 1.0) * 255.0));
  return uvec4(floatBitsToUint(position), q.x | (q.y << 11) | (r << 22) | kGuideReflective);
}

bool guide_reflective(uvec4 guide) { return (guide.w & kGuideReflective) != 0u; }
vec3 guide_position(uvec4 guide) { return uintBitsToFloat(guide.xyz); }
float guide_roughness(uvec4 guide) { return float((guide.w >> 22) & 255u) / 255.0; }

vec3 guide_normal(uvec4 guide) {
  const vec2 octahedral = vec2(float(guide.w & 2047u), float((guide.w >> 11) & 2047u)) / 2047.0 * 2.0 - 1.0;
  vec3 n = vec3(octahedral, 1.0 - abs(octahedral.x) - abs(octahedral.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * guide_sign(n.xy);
  return normalize(n);
}
