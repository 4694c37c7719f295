#version 450 core
// Screen-space reflections (SsrPass, docs/ssr.md). One invocation per pixel: reflect the view ray
// about the G-buffer normal, march it in screen space with McGuire & Mara's perspective-correct DDA
// (JCGT 2014: clip to the near plane, project both ends, interpolate Q = view point / w and k = 1/w
// linearly in screen space, step along the major axis), refine the hit interval by bisection, and
// keep the hit only if it passes every trust test; otherwise mark the pixel for ray tracing.
// Depths here are positive linear view depths (distance in front of the camera along -z).
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"
#include "include/tile_list.glsl"  // --reflections auto: only the listed tiles (render/tile_dispatch.h)

layout(binding = 0, rgba8) uniform readonly image2D albedo_reflectivity;
layout(binding = 1, rgba32f) uniform readonly image2D world_position;
layout(binding = 2, rgba16f) uniform readonly image2D world_normal;
layout(binding = 3, rgba16f) uniform readonly image2D lit;
layout(binding = 4, rgba16f) uniform writeonly image2D reflection;
layout(binding = 5, r8ui) uniform writeonly uimage2D failure_mask;

// [0] reflective pixels, [1] failed pixels (render_targets.h kPixelCountersBinding).
layout(std430, binding = 0) buffer PixelCounters { uint pixel_counters[2]; };

uniform int max_steps;
uniform float stride;
uniform int refinement_steps;
uniform int jitter;
uniform float thickness;
uniform float max_distance;
uniform float confidence_threshold;
uniform float edge_fade;
uniform float self_hit_distance;

const uint kNotReflective = 0u;
const uint kHit = 1u;
const uint kFailed = 2u;
const float kBackgroundDepth = 3.0e38;  // background is infinitely far: no ray is ever behind it

ivec2 screen_size;

// Positive linear view depth of the surface seen at `pixel`.
float scene_depth(ivec2 pixel) {
  const vec4 position = imageLoad(world_position, pixel);
  if (position.w == 0.0) return kBackgroundDepth;
  return -(view * vec4(position.xyz, 1.0)).z;
}

// A per-pixel, per-frame number in [0, 1) (PCG-style integer hash), so jitter decorrelates pixels
// and frames without a noise texture.
float hash01(uvec3 v) {
  uint h = v.x * 1664525u + v.y * 22695477u + v.z * 2891336453u + 1013904223u;
  h ^= h >> 16; h *= 0x7feb352du; h ^= h >> 15; h *= 0x846ca68bu; h ^= h >> 16;
  return float(h >> 8) * (1.0 / 16777216.0);
}

float edge_term(vec2 pixel_center) {
  if (edge_fade <= 0.0) return 1.0;
  const float band = edge_fade * float(screen_size.y);
  const vec2 to_edge = min(pixel_center, vec2(screen_size) - pixel_center);
  const vec2 fade = smoothstep(vec2(0.0), vec2(band), to_edge);
  return fade.x * fade.y;
}

// The march state along the screen-space line: s counts strides from the origin.
struct Line {
  vec2 p0, dp;   // screen position (major axis in x when permuted) and its step
  float q0z, dqz; // homogeneous view z (Q.z = z / w) and its step
  float k0, dk;   // 1 / w and its step
  bool permute;
};

vec2 line_pixel_position(Line line, float s) {
  const vec2 p = line.p0 + line.dp * s;
  return line.permute ? p.yx : p;
}
float line_depth(Line line, float s) { return -(line.q0z + line.dqz * s) / (line.k0 + line.dk * s); }

// The ray's depth range over one pixel along the major axis, centred on s.
vec2 pixel_span(Line line, float s) {
  const float half_pixel = 0.5 / stride;
  const float a = line_depth(line, s - half_pixel), b = line_depth(line, s + half_pixel);
  return vec2(min(a, b), max(a, b));
}

// How far a surface depth lies outside a depth range (0 when inside).
float depth_gap(vec2 span, float surface) { return max(max(span.x - surface, surface - span.y), 0.0); }

bool on_screen(vec2 p) { return all(greaterThanEqual(p, vec2(0.0))) && all(lessThan(p, vec2(screen_size))); }

// Marches one reflective pixel; writes the reflection it trusts into `result`.
uint trace(ivec2 pixel, vec3 origin_ws, vec3 normal_ws, out vec4 result) {
  result = vec4(0.0);
  const vec3 view_dir = normalize(origin_ws - camera_position.xyz);
  const vec3 ray_ws = normalize(reflect(view_dir, normal_ws));

  // View space, clipped to the near plane (a ray towards the camera ends there: what lies behind
  // the camera is not on screen, so such rays fail by running out of line).
  const vec3 origin_vs = (view * vec4(origin_ws, 1.0)).xyz;
  const vec3 ray_vs = mat3(view) * ray_ws;
  const float near_z = -near_far.x;
  float ray_length = max_distance;
  if (origin_vs.z + ray_vs.z * ray_length > near_z) ray_length = (near_z - origin_vs.z) / ray_vs.z;
  if (!(ray_length > 0.0)) return kFailed;  // a surface at or before the near plane: nothing to march
  const vec3 end_vs = origin_vs + ray_vs * ray_length;

  const vec4 h0 = projection * vec4(origin_vs, 1.0);
  const vec4 h1 = projection * vec4(end_vs, 1.0);
  const float k0 = 1.0 / h0.w, k1 = 1.0 / h1.w;
  const float q0z = origin_vs.z * k0, q1z = end_vs.z * k1;
  vec2 p0 = (h0.xy * k0 * 0.5 + 0.5) * vec2(screen_size);
  vec2 p1 = (h1.xy * k1 * 0.5 + 0.5) * vec2(screen_size);
  // A ray along the view direction projects to a point; give the line a length to step along.
  if (dot(p1 - p0, p1 - p0) < 1e-4) p1 += vec2(0.01);

  Line line;
  vec2 delta = p1 - p0;
  line.permute = abs(delta.x) < abs(delta.y);
  if (line.permute) { delta = delta.yx; p0 = p0.yx; }
  const float step_dir = sign(delta.x);
  const float inv_dx = step_dir / delta.x;  // one pixel along the major axis
  line.p0 = p0;
  line.dp = vec2(step_dir, delta.y * inv_dx) * stride;
  line.q0z = q0z;
  line.dqz = (q1z - q0z) * inv_dx * stride;
  line.k0 = k0;
  line.dk = (k1 - k0) * inv_dx * stride;
  const float last_s = abs(delta.x) / stride;  // the end of the clipped ray

  // Start one stride away (the origin pixel would hit itself), plus the jitter.
  const float start = 1.0 + (jitter != 0 ? hash01(uvec3(pixel, uint(viewport.z))) : 0.0);
  float previous_s = 0.0;
  float previous_depth = -origin_vs.z;
  float hit_s = -1.0;
  for (int i = 0; i < max_steps; ++i) {
    const float s = start + float(i);
    if (s > last_s) return kFailed;  // out of distance (or clipped by the near plane)
    const vec2 p = line_pixel_position(line, s);
    if (!on_screen(p)) return kFailed;
    // The ray's depth range over this step: from where the last step's range ended to half a step
    // ahead, so that a surface between two samples is not skipped.
    const float ahead_depth = line_depth(line, s + 0.5);
    const float ray_min = min(previous_depth, ahead_depth);
    const float ray_max = max(previous_depth, ahead_depth);
    previous_depth = ahead_depth;
    const float surface = scene_depth(ivec2(p));
    if (ray_max >= surface && ray_min <= surface + thickness) {
      hit_s = s;
      break;
    }
    previous_s = s;
  }
  if (hit_s < 0.0) return kFailed;  // out of steps

  // Bisection on the last interval for the first position whose one-pixel depth range reaches a
  // surface (within the thickness); with strides > 1 this finds the pixel the stride skipped over.
  // The step's depth range reached half a step ahead, so the crossing may lie up to there.
  float lo = previous_s, hi = min(hit_s + 0.5, last_s);
  bool refined = false;
  for (int i = 0; i < refinement_steps; ++i) {
    const float mid = 0.5 * (lo + hi);
    const vec2 mid_p = line_pixel_position(line, mid);
    const ivec2 mid_pixel = ivec2(mid_p);
    const vec2 span = pixel_span(line, mid);
    const float surface = scene_depth(mid_pixel);
    // The origin's own pixel is never a hit (any point of the ray beyond it is "behind" it); the
    // half step ahead may reach past the border.
    if (on_screen(mid_p) && mid_pixel != pixel && span.y >= surface && span.x <= surface + thickness) {
      hi = mid;
      refined = true;
    } else {
      lo = mid;
    }
  }
  if (!refined) hi = hit_s;  // no finer position found: keep the step that hit
  const vec2 hit_p = line_pixel_position(line, hi);
  const ivec2 hit_pixel = ivec2(hit_p);

  // Trust tests (docs/ssr.md "Failure rules").
  const vec4 hit_position = imageLoad(world_position, hit_pixel);
  if (hit_position.w == 0.0) return kFailed;  // background
  const float distance_ws = length(hit_position.xyz - origin_ws);
  if (hit_pixel == pixel || distance_ws < self_hit_distance) return kFailed;  // self-intersection
  const vec3 hit_normal = imageLoad(world_normal, hit_pixel).xyz;
  if (dot(hit_normal, ray_ws) > 0.0) return kFailed;  // back face
  const float depth_difference = depth_gap(pixel_span(line, hi), scene_depth(hit_pixel));
  const float confidence =
      (1.0 - smoothstep(0.0, thickness, depth_difference)) * edge_term(vec2(hit_pixel) + 0.5);
  if (confidence < confidence_threshold) return kFailed;

  result = vec4(imageLoad(lit, hit_pixel).rgb, distance_ws);
  return kHit;
}

shared uint group_reflective;
shared uint group_failed;

void main() {
  screen_size = imageSize(world_position);
  if (gl_LocalInvocationIndex == 0u) {
    group_reflective = 0u;
    group_failed = 0u;
  }
  memoryBarrierShared();
  barrier();

  const ivec2 pixel = tile_list_pixel();
  if (all(lessThan(pixel, screen_size))) {
    const vec4 position = imageLoad(world_position, pixel);
    const float reflectivity = imageLoad(albedo_reflectivity, pixel).a;
    uint outcome = kNotReflective;
    vec4 result = vec4(0.0);
    if (position.w != 0.0 && reflectivity > 0.0)
      outcome = trace(pixel, position.xyz, normalize(imageLoad(world_normal, pixel).xyz), result);
    imageStore(reflection, pixel, result);
    imageStore(failure_mask, pixel, uvec4(outcome == kFailed ? 1u : 0u));
    if (outcome != kNotReflective) atomicAdd(group_reflective, 1u);
    if (outcome == kFailed) atomicAdd(group_failed, 1u);
  }

  // One global atomic per work group and counter instead of one per pixel.
  memoryBarrierShared();
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    if (group_reflective != 0u) atomicAdd(pixel_counters[0], group_reflective);
    if (group_failed != 0u) atomicAdd(pixel_counters[1], group_failed);
  }
}
