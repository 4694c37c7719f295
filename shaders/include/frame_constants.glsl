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
//   relative_view_projection  projection * view without its translation, for camera-relative points
layout(std140, binding = 0) uniform FrameConstants {
  mat4 view; mat4 projection; mat4 view_projection; mat4 inverse_view; mat4 inverse_projection;
  vec4 camera_position; vec4 light_position_range; vec4 light_color_intensity; vec4 sky_color;
  vec4 near_far; ivec4 viewport; vec4 reflection_sampling; mat4 relative_view_projection;
};

// Camera-relative rendering (docs/render.md "precision far from the origin"): a world point is made
// relative to the camera before any rotation or projection. Far from the origin (coordinates near
// 1e5, rounded to about 0.008) `view_projection * world` rounds clip z and w independently, an
// error of several units in depth; the difference of two nearby floats is exact, so here the
// rounding is only that of the point itself.
vec4 clip_from_world(vec3 world) { return relative_view_projection * vec4(world - camera_position.xyz, 1.0); }
vec3 view_from_world(vec3 world) { return mat3(view) * (world - camera_position.xyz); }
// World size of one pixel at positive view depth `depth` on a screen `screen_height` pixels tall.
float pixel_footprint(float depth, int screen_height) { return depth * 2.0 / (projection[1][1] * float(screen_height)); }
