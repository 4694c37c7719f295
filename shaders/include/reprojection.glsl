// Where a world point was on the previous frame's screen (ReflectionDenoiser, docs/glossy.md):
// the camera's motion vector of a pixel, from the previous frame's view-projection. In pixels, x
// right, y up, pixel centres at +0.5; w <= 0 (behind the previous camera) gives (-1, -1).
vec2 previous_pixel_position(mat4 previous_view_projection, vec3 world, vec2 size) {
  const vec4 clip = previous_view_projection * vec4(world, 1.0);
  if (clip.w <= 0.0) return vec2(-1.0);
  return (clip.xy / clip.w * 0.5 + 0.5) * size;
}

// Whether a previous-frame surface sample (position, normal) is the same surface as the current
// one: on its plane within depth_tolerance x the distance to the camera, and facing the same way.
bool same_surface(vec3 position, vec3 normal, float camera_distance, vec4 previous_position, vec3 previous_normal,
                  float depth_tolerance) {
  if (previous_position.w == 0.0) return false;
  return abs(dot(normal, previous_position.xyz - position)) <= depth_tolerance * camera_distance &&
         dot(normal, previous_normal) > 0.9;
}
