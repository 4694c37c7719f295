#version 450 core
// G-buffer surface: writes albedo + reflectivity, world position, world normal + roughness and
// material id + 1 (formats in src/render/render_targets.h), and with render::SurfaceMotion the world
// motion (location 4, src/render/surface_motion.h; discarded when no image is attached there). The
// normal is the interpolated vertex normal as authored, never flipped towards the viewer.

#include "include/scene_materials.glsl"
layout(binding = 0) uniform sampler2DArray material_textures;  // sRGB layers: sampling gives linear

in vec3 world_position;
in vec3 world_normal;
in vec2 uv;
in vec3 world_motion;
flat in uint material;

layout(location = 0) out vec4 albedo_reflectivity;
layout(location = 1) out vec4 position_out;
layout(location = 2) out vec4 normal_roughness;
layout(location = 3) out uint material_id;
layout(location = 4) out vec4 motion_out;

void main() {
  GpuMaterial m = materials[material];
  vec3 albedo = m.diffuse.rgb;
  if (m.texture_layer >= 0) albedo *= texture(material_textures, vec3(uv, float(m.texture_layer))).rgb;
  albedo_reflectivity = vec4(albedo, m.reflectivity);
  position_out = vec4(world_position, 1.0);
  normal_roughness = vec4(normalize(world_normal), m.roughness);
  material_id = material + 1u;
  motion_out = vec4(world_motion, 0.0);
}
