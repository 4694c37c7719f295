#version 450 core
// Direct lighting of the G-buffer (LightingPass): Blinn-Phong from the point light, shadowed by the
// shadow mask, plus ambient and emissive (surface_radiance in include/surface_lighting.glsl, with the
// camera as the viewer); background pixels get the sky colour. Output linear HDR radiance.
// One invocation per pixel of the lit image.
layout(local_size_x = 8, local_size_y = 8) in;  // render::kImageTileSize

#include "include/frame_constants.glsl"
#include "include/scene_materials.glsl"
#include "include/surface_lighting.glsl"

layout(binding = 0) uniform sampler2D albedo_reflectivity_texture;
layout(binding = 1) uniform sampler2D world_position_texture;
layout(binding = 2) uniform sampler2D world_normal_texture;
layout(binding = 3) uniform usampler2D material_id_texture;
layout(binding = 4) uniform sampler2D shadow_mask_texture;

layout(binding = 0, rgba16f) uniform writeonly image2D lit_image;  // kLitFormat

uniform float ambient_fraction;

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(lit_image)))) return;
  uint id = texelFetch(material_id_texture, pixel, 0).r;
  if (id == 0u) { imageStore(lit_image, pixel, vec4(sky_color.rgb, 1.0)); return; }
  GpuMaterial m = materials[id - 1u];
  vec3 albedo = texelFetch(albedo_reflectivity_texture, pixel, 0).rgb;
  vec3 position = texelFetch(world_position_texture, pixel, 0).xyz;
  vec3 n = normalize(texelFetch(world_normal_texture, pixel, 0).xyz);
  float shadow = texelFetch(shadow_mask_texture, pixel, 0).r;

  vec3 v = normalize(camera_position.xyz - position);
  imageStore(lit_image, pixel, vec4(surface_radiance(position, n, v, albedo, m, shadow, ambient_fraction), 1.0));
}
