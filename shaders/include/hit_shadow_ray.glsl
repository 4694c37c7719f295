// The shadow ray of a reflection hit (docs/hybrid.md "Shadows of reflection hits"), the one GLSL rule
// of both ways it is traced: hit_shadow_rays.comp.glsl writes it into a ray list for the tracer's
// occlusion query (cpu, embree, optix, and the gl backend's three-step path),
// hit_shadows_inline.comp.glsl makes and traces it in one pass after the closest hits (gl backend). The rule is
// rt/hit_shadow_ray.h's, which the cuda backend applies in CUDA (keep the two the same): n is the hit
// triangle's geometric normal (world space) turned towards the reflection ray's origin (the side the
// reflecting surface sees), and
//   origin    = hit point + origin_offset * n
//   direction = light position - origin (unnormalised), t in [0, 1 - 1e-4]: the light is at t = 1
// A miss, a degenerate triangle and a hit facing away from the light (unlit whatever the shadow says)
// get an empty ray (t_min > t_max), which is never occluded. The hit point is surface_point()'s, as
// hit shading rebuilds it. The includer also includes frame_constants.glsl and binds the GpuScene's
// buffers.
#include "include/accel_records.glsl"
#include "include/surface_point.glsl"

uniform float origin_offset;

const float kHitShadowRayEnd = 1.0 - 1e-4;
const uint kNoHit = 0xFFFFFFFFu;  // Hit.prim of a miss (accel::Hit::kInvalidIndex)

Ray empty_hit_shadow_ray() { return Ray(vec3(0.0), 1.0, vec3(0.0, 0.0, 1.0), 0.0); }

// The shadow ray of `hit`, the closest hit of `reflection_ray`.
Ray hit_shadow_ray(Ray reflection_ray, Hit hit) {
  if (hit.prim == kNoHit) return empty_hit_shadow_ray();
  const SceneTriangle triangle = scene_triangle(hit.instance, hit.prim);
  const SurfacePoint surface = surface_point(triangle, vec2(hit.u, hit.v));
  vec3 n = cross(triangle.position[1] - triangle.position[0], triangle.position[2] - triangle.position[0]);
  if (!(length(n) > 0.0)) return empty_hit_shadow_ray();
  n = normalize(n);
  if (dot(n, -reflection_ray.direction) < 0.0) n = -n;  // the side the reflecting surface sees
  const vec3 to_light = light_position_range.xyz - surface.position;
  if (dot(n, to_light) <= 0.0) return empty_hit_shadow_ray();
  // `precise`, as in pixel_shadow_ray.glsl: the walk that traces the ray inline is precise, so the
  // ray is made by the stated operations in both passes, not contracted in one of them only.
  precise vec3 origin = surface.position + origin_offset * n;
  precise vec3 direction = light_position_range.xyz - origin;
  return Ray(origin, 0.0, direction, kHitShadowRayEnd);
}
