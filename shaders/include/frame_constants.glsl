// Per-frame constants: one std140 uniform block at binding 0 (render::kFrameConstantsBinding), the
// twin of render::FrameConstants in src/render/frame_constants.h; the layouts must match exactly.
//   camera_position        xyz world, w unused
//   light_position_range   xyz world, w = PointLight::range
//   light_color_intensity  rgb linear colour, w = intensity
//   sky_color              rgb linear, w unused
//   near_far               x near, y far (world units), zw unused
//   viewport               x width, y height, z frame number, w unused
//   reflection_sampling    x SSR roughness cutoff, y sample index, z samples per pixel, w 1 = glossy
//                          (0: every surface a mirror); include/glossy_sampling.glsl, docs/glossy.md
layout(std140, binding = 0) uniform FrameConstants {
  mat4 view; mat4 projection; mat4 view_projection; mat4 inverse_view; mat4 inverse_projection;
  vec4 camera_position; vec4 light_position_range; vec4 light_color_intensity; vec4 sky_color;
  vec4 near_far; ivec4 viewport; vec4 reflection_sampling;
};
