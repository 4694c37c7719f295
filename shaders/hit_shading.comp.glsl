#version 450 core
// Hit shading (HitShadingPass, docs/hybrid.md): one invocation per listed ray. The hit record
// {t, instance, prim, u, v} is turned back into a surface point from the GpuScene buffers (the
// instance's mesh, its triangle `prim`, barycentrics u, v: surface_point() of
// include/surface_point.glsl, shared with the visibility G-buffer), and shaded exactly like the raster path:
// the material's albedo times its texture, the light's cube-map shadow at the hit (with rt and
// hybrid shadows: the answer of a shadow ray cast from the hit, hit_shadow_rays.comp.glsl), and
// surface_radiance() with the reflecting surface as the viewer. The result goes to the ray's pixel
// of the reflection image as vec4(radiance, distance from the reflecting surface to the hit).
// Glossy reflections (docs/glossy.md): the radiance is multiplied by the sampled direction's BRDF
// weight (reflection_weight of include/glossy_sampling.glsl, from the reflecting pixel's G-buffer
// normal and roughness); a mirror's weight is exactly 1.
//
// Texture level of detail: ray cones (Akenine-Moller et al., "Texture Level of Detail Strategies
// for Real-Time Ray Tracing", Ray Tracing Gems 2019, ch. 20). A pixel's cone opens by
// pixel_spread = 2 tan(fov / 2) / height; a planar mirror does not change the spread, so at the
// hit the cone is pixel_spread * (camera-to-mirror + mirror-to-hit distance) wide, and
//   lod = log2(width * sqrt(uv area / world area) * texture size / |cos(incidence)|)
// picks the mip level whose texel matches the cone's footprint on the triangle. The texture is
// filtered here (trilinear, repeat wrapping, from texelFetch: include/trilinear_texel.glsl) rather
// than by textureLod: Mesa's llvmpipe takes ~1 ms per filtered array sample in a compute shader,
// texelFetch is fast everywhere.
layout(local_size_x = 64) in;

#include "include/frame_constants.glsl"
#include "include/surface_point.glsl"
#include "include/surface_lighting.glsl"
#include "include/cube_shadow.glsl"
#include "include/trilinear_texel.glsl"
#include "include/occlusion_flag.glsl"
#include "include/glossy_sampling.glsl"

struct Ray { vec3 origin; float t_min; vec3 direction; float t_max; };  // accel::Ray
struct Hit { float t; uint instance; uint prim; float u; float v; };    // accel::Hit
layout(std430, binding = 6) readonly buffer Rays { Ray rays[]; };
layout(std430, binding = 7) readonly buffer RayPixels { uint ray_pixels[]; };
layout(std430, binding = 8) readonly buffer Hits { Hit hits[]; };

layout(binding = 0, rgba16f) uniform writeonly image2D reflection;
layout(binding = 0) uniform sampler2DArray material_textures;  // sRGB layers: sampling gives linear
layout(binding = 1) uniform samplerCube shadow_cube;
// The reflecting pixels' normal + roughness, read when glossy_weight is 1.
layout(binding = 1, rgba16f) uniform readonly image2D world_normal_roughness;
uniform int glossy_weight;

// Written by the ray-list pass: the shader reads the number of rays itself, so a GPU ray tracer's
// frame can be shaded without the host ever learning it (the dispatch covers max_rays).
layout(std430, binding = 9) readonly buffer RayCounters { uint ray_count; uint reflective_count; };
uniform float miss_distance;
uniform float ambient_fraction;
uniform float texture_layer_size;
uniform float near_distance;
uniform float texel_angle;
uniform float pcf_radius_texels;
uniform float constant_bias_texels;
uniform float slope_bias_texels;
uniform float normal_offset_texels;
// 1 with rt and hybrid shadows: ray i's shadow ray from the hit (hit_shadow_rays.comp.glsl) answered
// by the tracer's occlusion query replaces the cube-map lookup.
uniform int shadow_from_rays;

const uint kInvalidIndex = 0xFFFFFFFFu;

float texture_lod(vec3 e1, vec3 e2, vec2 uv1, vec2 uv2, vec3 normal, Ray ray, float t) {
  const float world_area = length(cross(e1, e2));
  const float uv_area = abs(uv1.x * uv2.y - uv1.y * uv2.x);
  if (world_area <= 0.0 || uv_area <= 0.0) return 0.0;
  const float pixel_spread = pixel_footprint(1.0, viewport.y);  // world size of a pixel at distance 1
  const float cone_width = pixel_spread * (distance(camera_position.xyz, ray.origin) + t * length(ray.direction));
  const float cos_incidence = max(abs(dot(normalize(ray.direction), normal)), 0.05);
  return log2(max(cone_width * sqrt(uv_area / world_area) * texture_layer_size / cos_incidence, 1e-8));
}

// The BRDF weight of ray i's direction at its pixel (1 for a mirror or without the G-buffer).
float sample_weight(ivec2 pixel, Ray ray) {
  if (glossy_weight == 0) return 1.0;
  const vec4 normal_roughness = imageLoad(world_normal_roughness, pixel);
  const float roughness = glossy_roughness(normal_roughness.w);
  if (roughness <= 0.0) return 1.0;
  return reflection_weight(normalize(ray.origin - camera_position.xyz), normalize(normal_roughness.xyz), roughness,
                           normalize(ray.direction));
}

void main() {
  const int i = int(gl_GlobalInvocationID.x);
  if (uint(i) >= ray_count) return;
  const uint pixel_index = ray_pixels[i];
  const ivec2 pixel = ivec2(int(pixel_index) % viewport.x, int(pixel_index) / viewport.x);
  const Ray ray = rays[i];
  const Hit hit = hits[i];
  const float weight = sample_weight(pixel, ray);
  if (hit.prim == kInvalidIndex) {
    imageStore(reflection, pixel, vec4(weight * sky_color.rgb, miss_distance));
    return;
  }

  // The surface point is rebuilt by the function the visibility G-buffer shares (surface_point.glsl).
  const SceneTriangle triangle = scene_triangle(hit.instance, hit.prim);
  const SurfacePoint surface = surface_point(triangle, vec2(hit.u, hit.v));
  const vec3 position = surface.position;
  const vec3 normal = surface.normal;

  const GpuMaterial material = materials[surface.material];
  vec3 albedo = material.diffuse.rgb;
  if (material.texture_layer >= 0) {
    const float lod = texture_lod(triangle.position[1] - triangle.position[0], triangle.position[2] - triangle.position[0],
                                  triangle.uv[1] - triangle.uv[0], triangle.uv[2] - triangle.uv[0], normal, ray, hit.t);
    albedo *= trilinear_texel(material_textures, material.texture_layer, surface.uv, lod);
  }

  const CubeShadowSettings shadow_settings = CubeShadowSettings(light_position_range.xyz, near_distance, texel_angle,
      pcf_radius_texels, constant_bias_texels, slope_bias_texels, normal_offset_texels);
  const float shadow = shadow_from_rays != 0 ? (occluded(uint(i)) ? 0.0 : 1.0)
                                             : cube_shadow_visibility(shadow_cube, shadow_settings, position, normal);
  const vec3 to_viewer = -normalize(ray.direction);
  const vec3 radiance = surface_radiance(position, normal, to_viewer, albedo, material, shadow, ambient_fraction);
  imageStore(reflection, pixel, vec4(weight * radiance, hit.t * length(ray.direction)));
}
