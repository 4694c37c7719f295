#version 450 core
// Direct lighting of the G-buffer: Blinn-Phong from the point light, shadowed by the shadow mask,
// plus ambient and emissive; background pixels get the sky colour. Output linear HDR radiance.
//
//   E   = light_color * intensity / (1 + (d / range)^2) * max(dot(N, L), 0) * shadow
//   out = E * (albedo / pi + specular * (exponent + 8) / (8 pi) * max(dot(N, H), 0)^exponent)
//         + ambient_fraction * sky_color * albedo + emissive
// N is the G-buffer normal turned towards the camera (sheets are lit on the side one sees), H the
// half vector of L and the view direction. docs/render.md explains the choices.

layout(std140, binding = 0) uniform FrameConstants {
  mat4 view; mat4 projection; mat4 view_projection; mat4 inverse_view; mat4 inverse_projection;
  vec4 camera_position; vec4 light_position_range; vec4 light_color_intensity; vec4 sky_color;
  vec4 near_far; ivec4 viewport;
};

struct GpuMaterial {
  vec4 diffuse; vec4 specular_exponent; vec4 emissive;
  float reflectivity; float roughness; int texture_layer; int pad;
};
layout(std430, binding = 5) readonly buffer Materials { GpuMaterial materials[]; };

layout(binding = 0) uniform sampler2D albedo_reflectivity_texture;
layout(binding = 1) uniform sampler2D world_position_texture;
layout(binding = 2) uniform sampler2D world_normal_texture;
layout(binding = 3) uniform usampler2D material_id_texture;
layout(binding = 4) uniform sampler2D shadow_mask_texture;

uniform float ambient_fraction;

layout(location = 0) out vec4 radiance;

const float kPi = 3.14159265358979;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint id = texelFetch(material_id_texture, pixel, 0).r;
  if (id == 0u) { radiance = vec4(sky_color.rgb, 1.0); return; }
  GpuMaterial m = materials[id - 1u];
  vec3 albedo = texelFetch(albedo_reflectivity_texture, pixel, 0).rgb;
  vec3 position = texelFetch(world_position_texture, pixel, 0).xyz;
  vec3 n = normalize(texelFetch(world_normal_texture, pixel, 0).xyz);
  float shadow = texelFetch(shadow_mask_texture, pixel, 0).r;

  vec3 v = normalize(camera_position.xyz - position);
  if (dot(n, v) < 0.0) n = -n;
  vec3 to_light = light_position_range.xyz - position;
  float d = length(to_light);
  vec3 l = to_light / max(d, 1e-6);
  float n_dot_l = max(dot(n, l), 0.0);
  float attenuation = light_color_intensity.w / (1.0 + (d / light_position_range.w) * (d / light_position_range.w));
  vec3 irradiance = light_color_intensity.rgb * attenuation * n_dot_l * shadow;

  vec3 h = normalize(l + v);
  float exponent = m.specular_exponent.w;
  float specular = n_dot_l > 0.0 ? (exponent + 8.0) / (8.0 * kPi) * pow(max(dot(n, h), 0.0), exponent) : 0.0;
  vec3 direct = irradiance * (albedo / kPi + m.specular_exponent.rgb * specular);
  radiance = vec4(direct + ambient_fraction * sky_color.rgb * albedo + m.emissive.rgb, 1.0);
}
