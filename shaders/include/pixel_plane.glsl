// The surface a pixel sees, as a plane: through its view-space point with its view-space normal.
// Needs include/frame_constants.glsl. Shared by the depth pyramid's level 0
// (include/depth_pyramid.glsl) and the SSR trace's pixel test (include/ssr_march.glsl), so that the two
// agree on where a pixel's surface lies.

// A plane seen edge-on would reach any depth; a pixel's surface is kept within this factor of its
// centre depth either way.
const float kPixelPlaneSpread = 2.0;
const float kPixelPlaneFar = 3.0e38;

// Positive view depth of the point of the plane (view-space point p, normal n, p's depth d = -p.z)
// seen through `screen` (pixels, y up; pixel centres at + 0.5) of a screen_size image.
float pixel_plane_depth(vec3 p, vec3 n, vec2 screen, vec2 screen_size) {
  const vec2 ndc = screen / screen_size * 2.0 - 1.0;
  const vec4 far_point = inverse_projection * vec4(ndc, 1.0, 1.0);
  const vec3 dir = far_point.xyz / -far_point.z;  // view ray with z = -1: the point s * dir has depth s
  const float denom = dot(n, dir);
  float depth = abs(denom) > 1e-12 ? dot(n, p) / denom : kPixelPlaneFar;
  if (!(depth > 0.0)) depth = kPixelPlaneFar;  // the view ray misses the plane in front of the camera
  return clamp(depth, -p.z / kPixelPlaneSpread, -p.z * kPixelPlaneSpread);
}
