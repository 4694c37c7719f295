#version 450 core
// Shadow mask: 1 where the G-buffer surface sees the point light, 0 where something nearer to the
// light covers it, fractional at PCF edges; background pixels are 1.
//
// Against acne and peter-panning (sizes in cube-map texels at the receiver's distance, so both grow
// linearly with distance from the light):
// - the receiver is first pushed along its normal (turned towards the light) by normal_offset texels;
// - its distance is reduced by a bias of constant_bias + slope_bias * tan(angle between normal and
//   light direction) * (1 + pcf radius) texels: a surface tilted by that angle changes its distance
//   by about tan(angle) per texel, across the whole PCF footprint.

layout(std140, binding = 0) uniform FrameConstants {
  mat4 view; mat4 projection; mat4 view_projection; mat4 inverse_view; mat4 inverse_projection;
  vec4 camera_position; vec4 light_position_range; vec4 light_color_intensity; vec4 sky_color;
  vec4 near_far; ivec4 viewport;
};

layout(binding = 0) uniform sampler2D world_position_texture;
layout(binding = 1) uniform sampler2D world_normal_texture;
layout(binding = 2) uniform samplerCube shadow_cube;  // linear distance / far_distance

uniform float far_distance;
uniform float texel_angle;         // 2 / cube size: a texel's width per unit distance at a face's centre
uniform float pcf_radius_texels;   // 0 = one sample
uniform float constant_bias_texels;
uniform float slope_bias_texels;
uniform float normal_offset_texels;

layout(location = 0) out float shadow;

// 20 directions spread over a cube around the lookup direction (corners and edge midpoints): a
// cheap 3D PCF kernel that needs no per-face tangent frame.
const vec3 kPcfOffsets[20] = vec3[](
  vec3(1, 1, 1), vec3(1, -1, 1), vec3(-1, -1, 1), vec3(-1, 1, 1),
  vec3(1, 1, -1), vec3(1, -1, -1), vec3(-1, -1, -1), vec3(-1, 1, -1),
  vec3(1, 1, 0), vec3(1, -1, 0), vec3(-1, -1, 0), vec3(-1, 1, 0),
  vec3(1, 0, 1), vec3(-1, 0, 1), vec3(1, 0, -1), vec3(-1, 0, -1),
  vec3(0, 1, 1), vec3(0, -1, 1), vec3(0, -1, -1), vec3(0, 1, -1));

float lit(vec3 direction, float receiver_distance) {
  float occluder_distance = texture(shadow_cube, direction).r * far_distance;
  return receiver_distance <= occluder_distance ? 1.0 : 0.0;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(world_position_texture, pixel, 0);
  if (position.w == 0.0) { shadow = 1.0; return; }
  vec3 light = light_position_range.xyz;
  vec3 to_light = light - position.xyz;
  float distance_to_light = length(to_light);
  if (distance_to_light <= 0.0) { shadow = 1.0; return; }
  vec3 l = to_light / distance_to_light;
  vec3 n = normalize(texelFetch(world_normal_texture, pixel, 0).xyz);
  if (dot(n, l) < 0.0) n = -n;  // the side facing the light (surfaces are single-sided sheets)
  float cos_angle = clamp(dot(n, l), 1e-3, 1.0);
  float tan_angle = min(sqrt(1.0 - cos_angle * cos_angle) / cos_angle, 20.0);
  float texel = texel_angle * distance_to_light;  // world size of one cube texel here

  vec3 receiver = position.xyz + n * (normal_offset_texels * texel);
  vec3 direction = receiver - light;
  float receiver_distance = length(direction);
  float bias = texel * (constant_bias_texels + slope_bias_texels * tan_angle * (1.0 + pcf_radius_texels));
  float compare_distance = receiver_distance - bias;

  if (pcf_radius_texels <= 0.0) { shadow = lit(direction, compare_distance); return; }
  float radius = pcf_radius_texels * texel / sqrt(2.0);  // offsets have length up to sqrt(3)
  float sum = 0.0;
  for (int i = 0; i < 20; ++i) sum += lit(direction + kPcfOffsets[i] * radius, compare_distance);
  shadow = sum / 20.0;
}
