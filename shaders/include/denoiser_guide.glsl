// The reflection denoiser's per-pixel guide (ReflectionDenoiser, docs/glossy.md): what its edge
// tests read of a pixel, in one RG32UI texel (8 bytes) so that a tap costs one small fetch. The
// temporal pass writes it from the G-buffer each frame; this frame's spatial passes read it, and the
// next frame's temporal pass reads it as the previous frame's surface (replacing copies of the
// position and normal images).
//   x  the world position as t along the pixel centre's ray, origin + t x direction(pixel)
//      (GuideRays below: the camera and an affine map of pixel centres to ray directions; exact up to
//      rounding for points on the centre's ray, which every G-buffer position is)
//   y  bits 0-10 and 11-21: the unit normal, octahedral, 11 bits a coordinate
//      bits 22-29: roughness (after glossy_roughness), 8-bit unorm
//      bit 30: reflective (geometry with reflectivity > 0); a guide without it is all 0
// The includer declares the rays of the frame(s) it reads as uniforms and passes them in.

const uint kGuideReflective = 1u << 30;

// A frame's camera rays: direction(pixel) = corner + (pixel.x + 0.5) step_x + (pixel.y + 0.5) step_y
// (unnormalised; render::guide_rays on the host).
struct GuideRays {
  vec3 origin;
  vec3 corner;
  vec3 step_x;
  vec3 step_y;
};

vec3 guide_direction(GuideRays rays, ivec2 pixel) {
  return rays.corner + (float(pixel.x) + 0.5) * rays.step_x + (float(pixel.y) + 0.5) * rays.step_y;
}

vec2 guide_sign(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

uvec2 pack_guide(GuideRays rays, ivec2 pixel, vec3 position, vec3 normal, float roughness) {
  const vec3 direction = guide_direction(rays, pixel);
  const float t = dot(position - rays.origin, direction) / dot(direction, direction);
  const vec3 n = normal / (abs(normal.x) + abs(normal.y) + abs(normal.z));
  const vec2 octahedral = n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * guide_sign(n.xy);
  const uvec2 q = uvec2(round(clamp(octahedral * 0.5 + 0.5, 0.0, 1.0) * 2047.0));
  const uint r = uint(round(clamp(roughness, 0.0, 1.0) * 255.0));
  return uvec2(floatBitsToUint(t), q.x | (q.y << 11) | (r << 22) | kGuideReflective);
}

bool guide_reflective(uvec2 guide) { return (guide.y & kGuideReflective) != 0u; }
vec3 guide_position(GuideRays rays, ivec2 pixel, uvec2 guide) {
  return rays.origin + uintBitsToFloat(guide.x) * guide_direction(rays, pixel);
}
float guide_roughness(uvec2 guide) { return float((guide.y >> 22) & 255u) / 255.0; }

vec3 guide_normal(uvec2 guide) {
  const vec2 octahedral = vec2(float(guide.y & 2047u), float((guide.y >> 11) & 2047u)) / 2047.0 * 2.0 - 1.0;
  vec3 n = vec3(octahedral, 1.0 - abs(octahedral.x) - abs(octahedral.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * guide_sign(n.xy);
  return normalize(n);
}
