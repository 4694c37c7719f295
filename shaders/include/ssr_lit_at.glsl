// SSR's colour at a trusted hit (docs/ssr.md step 6), shared by the march when it fetches the colour
// itself (ssr.comp.glsl, colour_in_march) and by the colour pass (ssr_colour.comp.glsl). The
// including shader declares the images `world_position` (rgba32f), `lit` (rgba16f) and
// `albedo_reflectivity` (rgba8) and the ivec2 `screen_size` before including this; this file declares
// the materials buffer and the material id and shadow mask textures (SsrPass binds them).
#include "include/scene_materials.glsl"  // materials[] (render::kMaterialBinding)
#include "include/surface_lighting.glsl"

layout(binding = 1) uniform usampler2D material_id_texture;  // kMaterialIdFormat; 0 = no material
layout(binding = 2) uniform sampler2D shadow_mask_texture;   // kShadowMaskFormat: the lighting's shadow

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

// The hit's lit colour `seen_by_camera` (lit_at) as the reflecting surface sees it, which is what rt's
// hit shading computes (surface_radiance with -ray as the viewer): the lit image holds the hit's
// direct light seen from the camera (its Blinn-Phong highlight, and N turned towards the camera), so
// the hit pixel's direct term for the camera is taken out and the one for the reflected ray put in,
// both by direct_radiance() of include/surface_lighting.glsl at the hit pixel (its position, normal,
// material, shadow mask value). Where both see the same side of the surface only the specular part
// differs (albedo 0 below): a material without specular colour keeps the lit colour as it is, after
// one id fetch. A trusted hit faces the ray (dot(n, ray) < 0), so the sides differ only where the
// camera sees the normal's back, and then the diffuse part changes too. A hit pixel with material id
// 0 (SsrPass without materials: the synthetic G-buffers of the tests) keeps the camera's view.
vec3 seen_along_ray(vec3 seen_by_camera, ivec2 hit_pixel, vec3 hit_position, vec3 hit_normal, vec3 ray) {
  const uint id = texelFetch(material_id_texture, hit_pixel, 0).r;
  if (id == 0u) return seen_by_camera;
  const GpuMaterial material = materials[id - 1u];
  const vec3 to_camera = normalize(camera_position.xyz - hit_position);  // as the lighting pass has it
  const bool same_side = dot(hit_normal, to_camera) >= 0.0;
  if (same_side && all(equal(material.specular_exponent.rgb, vec3(0.0)))) return seen_by_camera;
  const float shadow = texelFetch(shadow_mask_texture, hit_pixel, 0).r;
  const vec3 albedo = same_side ? vec3(0.0) : imageLoad(albedo_reflectivity, hit_pixel).rgb;
  const vec3 to_surface = -ray;
  const vec3 camera_view =
      direct_radiance(light_at_surface(hit_position, hit_normal, to_camera, shadow), to_camera, albedo, material);
  const vec3 ray_view =
      direct_radiance(light_at_surface(hit_position, hit_normal, to_surface, shadow), to_surface, albedo, material);
  return max(seen_by_camera - camera_view + ray_view, vec3(0.0));
}
