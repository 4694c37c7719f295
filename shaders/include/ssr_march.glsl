// Screen-space reflections (SsrPass, docs/ssr.md). One invocation per pixel: reflect the view ray
// about the G-buffer normal, follow it as a perspective-correct screen-space line (McGuire & Mara,
// JCGT 2014: Q = view point / w and k = 1 / w are linear in screen space, so the ray's depth at any
// point of the line is -Q.z / k exactly) cell by cell through the depth pyramid (DepthPyramidPass:
// per texel the [min, max] view depth of the surfaces under it): a level up after a cell the ray
// crosses in front of everything, a level down where its depth range meets the cell's, a hit at
// level 0 where it meets the pixel's surface. The hit is kept only if it passes every trust test;
// otherwise the pixel is marked for ray tracing. Depths are positive linear view depths, and every
// depth tolerance is a fraction of one, so nothing depends on the scene's scale or position.
// The including shader sets `const bool kColourInMarch` first: true (ssr.comp.glsl, SsrPass::run)
// also fetches each trusted hit's colour from the lit image; false (ssr_march.comp.glsl,
// SsrPass::march) reads only the G-buffer and can run before lighting, so that the frame's ray list
// and traces follow it in one GL-CUDA hand-over (docs/ssr.md "March, then colour"): each trusted hit
// goes to `ssr_hits` (include/ssr_hit.glsl), and ssr_colour.comp.glsl fetches its colour once the lit
// image exists. A compile-time constant, not a uniform: a uniform branch made the march 20% slower
// on an H100 (docs/perf.md "Seventh round").

#include "include/frame_constants.glsl"
#include "include/glossy_sampling.glsl"  // glossy reflections: the sampled direction (docs/glossy.md)
#include "include/pixel_plane.glsl"
#include "include/ssr_hit.glsl"
#include "include/tile_list.glsl"  // --reflections auto: only the listed tiles (render/tile_dispatch.h)

layout(binding = 0, rgba8) uniform readonly image2D albedo_reflectivity;
layout(binding = 1, rgba32f) uniform readonly image2D world_position;
layout(binding = 2, rgba16f) uniform readonly image2D world_normal;
layout(binding = 3, rgba16f) uniform readonly image2D lit;  // read only with kColourInMarch
layout(binding = 4, rgba16f) uniform writeonly image2D reflection;  // a = distance to a trusted hit
layout(binding = 5, r8ui) uniform writeonly uimage2D failure_mask;
layout(binding = 6, rgba32ui) uniform writeonly uimage2D ssr_hits;
layout(binding = 0) uniform sampler2D depth_pyramid;  // rg = min, max view depth; texelFetch only

// [0] reflective pixels, [1] failed pixels (render_targets.h kPixelCountersBinding).
layout(std430, binding = 0) buffer PixelCounters { uint pixel_counters[2]; };

uniform int max_steps;
uniform float thickness;
uniform float max_distance;
uniform float confidence_threshold;
uniform float edge_fade;
uniform float min_hit_cosine;
uniform float silhouette_footprints;
uniform float max_screen_fraction;
uniform float empty_behind;
uniform int pyramid_levels;

const uint kNotReflective = 0u;
const uint kHit = 1u;
const uint kFailed = 2u;
const float kHuge = 3.0e38;

ivec2 screen_size;

#include "include/ssr_lit_at.glsl"

float edge_term(vec2 pixel_center) {
  if (edge_fade <= 0.0) return 1.0;
  const float band = edge_fade * float(screen_size.y);
  const vec2 to_edge = min(pixel_center, vec2(screen_size) - pixel_center);
  const vec2 fade = smoothstep(vec2(0.0), vec2(band), to_edge);
  return fade.x * fade.y;
}

// The ray as a screen-space line p(t) = p0 + t * dp, t in [0, 1] over the clipped ray.
struct Line {
  vec2 p0, dp;
  float q0z, dqz;  // homogeneous view z (Q.z = z / w) and its change over the line
  float k0, dk;    // 1 / w and its change
};

float line_depth(Line line, float t) { return -(line.q0z + line.dqz * t) / (line.k0 + line.dk * t); }

// The line parameter where the line leaves the axis-aligned box [lo, hi] it is inside of.
float exit_parameter(Line line, vec2 lo, vec2 hi, vec2 inv_dp) {
  const vec2 bound = mix(lo, hi, greaterThanEqual(line.dp, vec2(0.0)));
  const vec2 t = (bound - line.p0) * inv_dp;
  return min(t.x, t.y);
}

// Largest distance of a 4-neighbour of `pixel` from the plane through `p` with normal `n` (world
// units; background neighbours are infinitely far): large on a silhouette, ~0 inside a surface.
// Divided by the hit's pixel footprint it is scale-free; the trust test fails a hit from about 0.42
// footprints on (silhouette_footprints 0.7), so that a neighbour across a crease (a pillar's corner,
// a moulding's edge: under one footprint off the plane) or a sub-pixel step fails it too, not only a
// silhouette; a trusted hit's four neighbours are then all on its surface as lit_at takes them
// (kSamePlane). docs/ssr.md "Silhouettes, creases and steps".
float neighbour_plane_distance(ivec2 pixel, vec3 p, vec3 n) {
  float largest = 0.0;
  const ivec2 offsets[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
  for (int i = 0; i < 4; ++i) {
    const ivec2 q = clamp(pixel + offsets[i], ivec2(0), screen_size - 1);
    const vec4 neighbour = imageLoad(world_position, q);
    largest = max(largest, neighbour.w == 0.0 ? kHuge : abs(dot(neighbour.xyz - p, n)));
  }
  return largest;
}

// Traces one reflective pixel; a trusted hit goes into `hit`, its distance from the surface into
// `hit_distance` and, with kColourInMarch, its colour into `colour`.
uint trace(ivec2 pixel, vec3 origin_ws, vec3 normal_ws, out SsrHit hit, out float hit_distance, out vec3 colour) {
  hit = ssr_no_hit();
  hit_distance = 0.0;
  colour = vec3(0.0);
  const vec3 view_dir = normalize(origin_ws - camera_position.xyz);
  // The mirror direction, or on a glossy surface the sample the ray list traces too; surfaces
  // rougher than the cutoff are left to the rays.
  const float roughness = imageLoad(world_normal, pixel).w;
  if (beyond_ssr_roughness(roughness)) return kFailed;
  const vec3 ray_ws = pixel_reflection_direction(view_dir, normal_ws, roughness, pixel);

  // View space, clipped to the near plane (what lies behind the camera is not on screen: such rays
  // fail by running out of line) and to the far plane.
  const vec3 origin_vs = view_from_world(origin_ws);  // camera-relative: exact far from the origin
  const vec3 ray_vs = mat3(view) * ray_ws;
  float ray_length = near_far.y;
  if (ray_vs.z > 0.0) ray_length = min(ray_length, (-near_far.x - origin_vs.z) / ray_vs.z);
  if (ray_vs.z < 0.0) ray_length = min(ray_length, (-near_far.y - origin_vs.z) / ray_vs.z);
  if (max_distance > 0.0) ray_length = min(ray_length, max_distance);
  if (!(ray_length > 0.0)) return kFailed;  // a surface at or before the near plane: nothing to trace
  const vec3 end_vs = origin_vs + ray_vs * ray_length;

  const vec4 h0 = projection * vec4(origin_vs, 1.0);
  const vec4 h1 = projection * vec4(end_vs, 1.0);
  Line line;
  line.k0 = 1.0 / h0.w;
  line.dk = 1.0 / h1.w - line.k0;
  line.q0z = origin_vs.z * line.k0;
  line.dqz = end_vs.z / h1.w - line.q0z;
  line.p0 = (h0.xy * line.k0 * 0.5 + 0.5) * vec2(screen_size);
  line.dp = (h1.xy / h1.w * 0.5 + 0.5) * vec2(screen_size) - line.p0;
  // A ray along the view direction projects to a point; give the line a direction to walk.
  if (dot(line.dp, line.dp) < 1e-6) line.dp = vec2(1e-3);
  const vec2 inv_dp = 1.0 / mix(line.dp, vec2(1e-12), equal(line.dp, vec2(0.0)));
  // The line ends at its clipped end or where it leaves the screen, whichever comes first.
  const float t_end = min(1.0, exit_parameter(line, vec2(0.0), vec2(screen_size), inv_dp));
  // A nudge of a hundredth of a pixel along the major axis puts a cell's exit point into the next cell.
  const float nudge = 0.01 / max(abs(line.dp.x), abs(line.dp.y));

  // Start where the line leaves the origin's pixel: the surface never reflects itself there.
  float t = exit_parameter(line, vec2(pixel), vec2(pixel + 1), inv_dp) + nudge;
  int level = 0;
  const int top_level = pyramid_levels - 1;
  bool found = false;
  ivec2 hit_pixel = pixel;
  vec2 hit_point = vec2(pixel) + 0.5;
  float hit_gap = 0.0;  // how far behind the hit pixel's surface the ray passed (view depth)
  for (int i = 0; i < max_steps; ++i) {
    if (t >= t_end) return kFailed;  // off screen, or the end of the clipped ray
    const vec2 p = line.p0 + line.dp * t;
    const ivec2 at = clamp(ivec2(floor(p)), ivec2(0), screen_size - 1);
    const ivec2 cell = at >> level;
    const ivec2 level_size = max(screen_size >> level, ivec2(1));
    const float cell_size = float(1 << level);
    const float t_exit = min(exit_parameter(line, vec2(cell) * cell_size, vec2(cell + 1) * cell_size, inv_dp), t_end);
    const float za = line_depth(line, t), zb = line_depth(line, t_exit);
    const vec2 ray = vec2(min(za, zb), max(za, zb));
    const vec2 surface = texelFetch(depth_pyramid, min(cell, level_size - 1), level).rg;
    if (ray.y < surface.x) {  // in front of every surface under the cell: empty space
      t = t_exit + nudge;
      level = min(level + 1, top_level);
      continue;
    }
    if (ray.x > surface.y * (1.0 + thickness)) {
      // Behind every surface under the cell: hidden from the camera. Close behind a surface the ray
      // is probably inside what it went behind, and what it meets there is unknown: it fails. Far
      // behind, that space is taken to be empty and the ray walks on.
      if (ray.x <= surface.y * (1.0 + empty_behind)) return kFailed;
      t = t_exit + nudge;
      level = min(level + 1, top_level);
      continue;
    }
    if (level > 0) {
      --level;
      continue;
    }
    // One pixel whose depth range the ray meets: compare the ray with the pixel's own plane where
    // the ray enters and leaves the pixel (a range test alone would take a ray skimming over a
    // receding surface for a hit).
    const vec4 cell_position = imageLoad(world_position, at);
    const vec3 plane_p = view_from_world(cell_position.xyz);
    const vec3 plane_n = mat3(view) * imageLoad(world_normal, at).xyz;
    const float behind_a = za - pixel_plane_depth(plane_p, plane_n, line.p0 + line.dp * t, vec2(screen_size));
    const float behind_b = zb - pixel_plane_depth(plane_p, plane_n, line.p0 + line.dp * t_exit, vec2(screen_size));
    const float tolerance = thickness * -plane_p.z;
    if (max(behind_a, behind_b) < 0.0 || min(behind_a, behind_b) > tolerance) {
      // In front of the surface all through the pixel, or hidden behind it all through (failing
      // close behind it, as above).
      const float least_behind = min(behind_a, behind_b);
      if (least_behind > tolerance && least_behind <= empty_behind * -plane_p.z) return kFailed;
      t = t_exit + nudge;
      level = min(level + 1, top_level);
      continue;
    }
    found = true;
    hit_pixel = at;
    hit_gap = max(min(behind_a, behind_b), 0.0);  // 0 where the ray crosses the surface inside the pixel
    // Where the ray meets the pixel's plane inside the pixel (where it enters, if behind it already).
    const bool crosses = (behind_a < 0.0) != (behind_b < 0.0);
    const float cross_at = crosses ? clamp(behind_a / (behind_a - behind_b), 0.0, 1.0) : 0.0;
    hit_point = line.p0 + line.dp * mix(t, t_exit, cross_at);
    break;
  }
  if (!found) return kFailed;  // out of steps

  // Trust tests (docs/ssr.md "Failure rules").
  const vec4 hit_position = imageLoad(world_position, hit_pixel);
  if (hit_position.w == 0.0 || hit_pixel == pixel) return kFailed;  // background, or itself
  const vec3 hit_normal = normalize(imageLoad(world_normal, hit_pixel).xyz);
  const float facing = -dot(hit_normal, ray_ws);
  if (facing <= 0.0) return kFailed;  // back face (the G-buffer normal is never flipped)
  const float hit_depth = -view_from_world(hit_position.xyz).z;
  const float footprint = pixel_footprint(hit_depth, screen_size.y);
  const float off_plane = neighbour_plane_distance(hit_pixel, hit_position.xyz, hit_normal) / footprint;
  const vec2 hit_center = vec2(hit_pixel) + 0.5;
  const float screen_fraction = length(hit_center - line.p0) / length(vec2(screen_size));
  const float confidence = (1.0 - smoothstep(0.0, thickness * hit_depth, hit_gap)) * edge_term(hit_center) *
                           smoothstep(0.0, min_hit_cosine, facing) *
                           (1.0 - smoothstep(0.5 * silhouette_footprints, silhouette_footprints, off_plane)) *
                           (1.0 - smoothstep(0.75 * max_screen_fraction, max_screen_fraction, screen_fraction));
  if (confidence < confidence_threshold) return kFailed;

  hit.point = hit_point;
  hit.pixel = hit_pixel;
  hit.weight = reflection_weight(view_dir, normal_ws, glossy_roughness(roughness), ray_ws);  // 1 for a mirror
  hit_distance = length(hit_position.xyz - origin_ws);
  if (kColourInMarch) colour = hit.weight * lit_at(hit_point, hit_pixel, hit_position.xyz, hit_normal, footprint);
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
    SsrHit hit = ssr_no_hit();
    float hit_distance = 0.0;
    vec3 colour = vec3(0.0);
    if (position.w != 0.0 && reflectivity > 0.0)
      outcome = trace(pixel, position.xyz, normalize(imageLoad(world_normal, pixel).xyz), hit, hit_distance, colour);
    imageStore(reflection, pixel, vec4(colour, hit_distance));  // without kColourInMarch: ssr_colour adds it
    if (!kColourInMarch) imageStore(ssr_hits, pixel, pack_ssr_hit(hit));
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
