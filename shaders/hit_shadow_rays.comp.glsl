#version 450 core
// Shadow rays from reflection hits (RayTracedReflections with rt or hybrid shadows, docs/hybrid.md):
// one per listed reflection ray i, written to shadow ray i, so hit shading reads ray i's answer.
// The rule is rt/hit_shadow_ray.h's, which a GPU backend that traces these rays with the hits
// applies in CUDA (keep the two the same): n is the hit triangle's geometric normal (world space)
// turned towards the reflection ray's origin (the side the reflecting surface sees), and
//   origin    = hit point + origin_offset * n
//   direction = light position - origin (unnormalised), t in [0, 1 - 1e-4]: the light is at t = 1
// A miss, a degenerate triangle, a hit facing away from the light (unlit whatever the shadow says)
// and, on a device backend (empty_past_count), a slot past the list's count get an empty ray (t_min >
// t_max), which is never occluded; the gl backend traces only up to the count, so those slots are
// left alone. The hit point is surface_point()'s, as hit shading rebuilds it.
layout(local_size_x = 64) in;

#include "include/frame_constants.glsl"
#include "include/surface_point.glsl"

struct Ray { vec3 origin; float t_min; vec3 direction; float t_max; };  // accel::Ray
struct Hit { float t; uint instance; uint prim; float u; float v; };    // accel::Hit
layout(std430, binding = 6) readonly buffer Rays { Ray rays[]; };
layout(std430, binding = 8) readonly buffer Hits { Hit hits[]; };
layout(std430, binding = 9) readonly buffer RayCounters { uint ray_count; uint reflective_count; };
layout(std430, binding = 10) writeonly buffer ShadowRays { Ray shadow_rays[]; };

uniform float origin_offset;
uniform int max_rays;  // the dispatch's extent: the count (CPU backends) or the capacity
uniform int empty_past_count;  // 1: slots past the count get an empty ray (their tracer reads them)

const uint kInvalidIndex = 0xFFFFFFFFu;
const float kShadowRayEnd = 1.0 - 1e-4;

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= uint(max_rays) || (i >= ray_count && empty_past_count == 0)) return;
  const Ray no_ray = Ray(vec3(0.0), 1.0, vec3(0.0, 0.0, 1.0), 0.0);
  if (i >= ray_count || hits[i].prim == kInvalidIndex) {
    shadow_rays[i] = no_ray;
    return;
  }
  const Hit hit = hits[i];
  const SceneTriangle triangle = scene_triangle(hit.instance, hit.prim);
  const SurfacePoint surface = surface_point(triangle, vec2(hit.u, hit.v));
  vec3 n = cross(triangle.position[1] - triangle.position[0], triangle.position[2] - triangle.position[0]);
  if (!(length(n) > 0.0)) {
    shadow_rays[i] = no_ray;
    return;
  }
  n = normalize(n);
  if (dot(n, -rays[i].direction) < 0.0) n = -n;  // the side the reflecting surface sees
  const vec3 to_light = light_position_range.xyz - surface.position;
  if (dot(n, to_light) <= 0.0) {
    shadow_rays[i] = no_ray;
    return;
  }
  const vec3 origin = surface.position + origin_offset * n;
  shadow_rays[i] = Ray(origin, 0.0, light_position_range.xyz - origin, kShadowRayEnd);
}
