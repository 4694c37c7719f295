#version 450 core
// Visibility G-buffer, resolve (VisibilityGBufferPass) on GPUs: the sampler filters the uv
// footprint of the pixel's quad with textureGrad, exactly what the raster G-buffer's texture() does
// with its implicit derivatives (trilinear, anisotropic). Body: include/visibility_gbuffer_main.glsl.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray material_textures;  // sRGB layers: sampling gives linear

vec3 material_texel(int layer, vec2 uv, vec2 ddx, vec2 ddy) {
  return textureGrad(material_textures, vec3(uv, float(layer)), ddx, ddy).rgb;
}

#include "include/visibility_gbuffer_main.glsl"
