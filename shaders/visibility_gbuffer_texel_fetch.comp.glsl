#version 450 core
// Visibility G-buffer, resolve (VisibilityGBufferPass) on Mesa's software renderers: llvmpipe runs
// textureGrad in a compute shader about 60x slower than the whole raster G-buffer, and filters it
// trilinearly anyway (its anisotropic filter is for fragment shaders only). So the shader filters
// itself: the GL specification's isotropic level log2(max(|ddx|, |ddy|) x layer size), trilinear
// from texelFetch. Body: include/visibility_gbuffer_main.glsl.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/trilinear_texel.glsl"

layout(binding = 0) uniform sampler2DArray material_textures;  // sRGB layers: sampling gives linear

vec3 material_texel(int layer, vec2 uv, vec2 ddx, vec2 ddy) {
  const float size = float(textureSize(material_textures, 0).x);  // layers are square
  const float lod = log2(max(max(length(ddx), length(ddy)) * size, 1e-8));
  return trilinear_texel(material_textures, layer, uv, lod);
}

#include "include/visibility_gbuffer_main.glsl"
