#version 450 core
// Shadow mask (ShadowMaskPass): 1 where the G-buffer surface sees the point light, 0 where something
// nearer to the light covers it, fractional at PCF edges; background pixels are 1. One invocation per
// pixel of the mask.
// The lookup and its biases are cube_shadow_visibility in include/cube_shadow.glsl (explicit level 0
// lookups, so it needs no derivatives in a compute shader).
layout(local_size_x = 8, local_size_y = 8) in;  // render::kImageTileSize

#include "include/frame_constants.glsl"
#include "include/cube_shadow.glsl"

layout(binding = 0) uniform sampler2D world_position_texture;
layout(binding = 1) uniform sampler2D world_normal_texture;
layout(binding = 2) uniform samplerCube shadow_cube;  // near distance / distance along the face axis

layout(binding = 0, r8) uniform writeonly image2D shadow_mask;  // kShadowMaskFormat

uniform float near_distance;     // depth d of the cube stands for near_distance / d
uniform float texel_angle;         // 2 / cube size: a texel's width per unit distance at a face's centre
uniform float pcf_radius_texels;   // 0 = one sample
uniform float constant_bias_texels;
uniform float slope_bias_texels;
uniform float normal_offset_texels;

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(shadow_mask)))) return;
  vec4 position = texelFetch(world_position_texture, pixel, 0);
  if (position.w == 0.0) { imageStore(shadow_mask, pixel, vec4(1.0)); return; }
  vec3 n = normalize(texelFetch(world_normal_texture, pixel, 0).xyz);
  CubeShadowSettings settings = CubeShadowSettings(light_position_range.xyz, near_distance, texel_angle,
      pcf_radius_texels, constant_bias_texels, slope_bias_texels, normal_offset_texels);
  imageStore(shadow_mask, pixel, vec4(cube_shadow_visibility(shadow_cube, settings, position.xyz, n)));
}
