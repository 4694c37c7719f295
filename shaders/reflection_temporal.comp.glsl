#version 450 core
// Temporal accumulation of the reflection (ReflectionDenoiser, docs/glossy.md). Per reflective pixel:
//   c        = fade(distance) * reflection.rgb     (the distance fade of docs/ssr.md, applied here)
//   previous = the history at the pixel's previous-frame position (its world position plus the
//              surface's own motion, render/surface_motion.h, 0 for static geometry, projected
//              with the previous view-projection: include/reprojection.glsl), bilinear over the taps
//              that are the same surface (the previous frame's guide: reflective, plane distance and
//              normal tests); none: disoccluded, the history restarts
//   previous is clamped to mean +- clamp_sigma x deviation of c over the 3x3 neighbourhood
//   n        = min(history length + 1, 1 + (max_history - 1) min(roughness / 0.3, 1)^2)
//   out      = mix(previous, c, 1 / n)   (near-mirrors keep little history: see below)
// Mirrors (roughness 0) and pixels without history pass c through (n = 1). Output: rgb, a = n
// (reflective pixels only: no later read takes a non-reflective pixel's), and every pixel's guide
// (include/denoiser_guide.glsl) for this frame's spatial passes and the next frame's same-surface
// tests; with record_motion the motion buffer: the previous position (pixels), (-1, -1) when the
// history restarted.
//
// Cost: the 3x3 neighbourhood's faded reflection is loaded once per work group into shared memory
// (a 10 x 10 tile: 1.6 loads a pixel instead of 9 x 3 fetches), and a mirror skips the reprojection.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"
#include "include/glossy_sampling.glsl"
#include "include/reprojection.glsl"

// Inputs are read with texelFetch (no filtering): images are limited to 8 per shader on some GPUs.
layout(binding = 0) uniform sampler2D reflection;
layout(binding = 1) uniform sampler2D world_position;
layout(binding = 2) uniform sampler2D world_normal_roughness;
layout(binding = 3) uniform sampler2D albedo_reflectivity;
layout(binding = 4) uniform sampler2D history;
layout(binding = 5) uniform usampler2D previous_guide;
layout(binding = 6) uniform sampler2D world_motion;  // with has_motion: previous - current world position
layout(binding = 0, rgba16f) uniform writeonly image2D accumulated;
layout(binding = 1, rg32ui) uniform writeonly uimage2D guide;
layout(binding = 24, std430) writeonly buffer Motion { vec2 motion[]; };

uniform mat4 previous_view_projection;
uniform GuideRays rays;           // this frame's (the guide written)
uniform GuideRays previous_rays;  // the previous frame's (previous_guide)
uniform int has_history;
uniform int has_motion;
uniform int record_motion;
uniform float max_history;
uniform float clamp_sigma;
uniform float depth_tolerance;
uniform float fade_start;
uniform float fade_end;

bool reflective(ivec2 p) {
  return texelFetch(world_position, p, 0).w != 0.0 && texelFetch(albedo_reflectivity, p, 0).a > 0.0;
}

vec3 faded(ivec2 p) {
  const vec4 value = texelFetch(reflection, p, 0);
  const float fade = fade_end > 0.0 ? 1.0 - smoothstep(fade_start, fade_end, value.a) : 1.0;
  return value.rgb * fade;
}

// The work group's 8 x 8 pixels and a one-pixel border: rgb = faded reflection, a = 1 where
// reflective (and on screen), else all 0.
shared vec4 tile[10][10];

void load_tile(ivec2 size) {
  const ivec2 origin = ivec2(gl_WorkGroupID.xy) * 8 - 1;
  for (uint i = gl_LocalInvocationIndex; i < 100u; i += 64u) {
    const ivec2 q = origin + ivec2(int(i % 10u), int(i / 10u));
    vec4 value = vec4(0.0);
    if (all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size)) && reflective(q)) value = vec4(faded(q), 1.0);
    tile[i / 10u][i % 10u] = value;
  }
  barrier();
}

void store_motion(uint index, vec2 value) {
  if (record_motion != 0) motion[index] = value;
}

void main() {
  const ivec2 size = textureSize(reflection, 0);
  load_tile(size);  // before any return: every invocation reaches the barrier
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  const uint index = uint(pixel.y * size.x + pixel.x);
  const ivec2 local = ivec2(gl_LocalInvocationID.xy) + 1;  // the pixel in the tile
  const vec4 own = tile[local.y][local.x];
  if (own.a == 0.0) {  // not reflective: nothing reads its history (its guide says so)
    imageStore(guide, pixel, uvec4(0u));
    store_motion(index, vec2(-1.0));
    return;
  }
  const vec3 c = own.rgb;
  const vec4 position = texelFetch(world_position, pixel, 0);
  const vec4 normal_roughness = texelFetch(world_normal_roughness, pixel, 0);
  const vec3 normal = normalize(normal_roughness.xyz);
  const float roughness = glossy_roughness(normal_roughness.w);
  imageStore(guide, pixel, uvec4(pack_guide(rays, pixel, position.xyz, normal, roughness), 0u, 0u));
  if (roughness <= 0.0 || has_history == 0) {  // a mirror, or the first frame: c passes through
    imageStore(accumulated, pixel, vec4(c, 1.0));
    store_motion(index, vec2(-1.0));
    return;
  }
  // Where this surface point was: static geometry's motion is exactly 0, so it keeps position.xyz.
  const vec3 previous_world = has_motion != 0 ? position.xyz + texelFetch(world_motion, pixel, 0).xyz : position.xyz;
  const vec2 previous = previous_pixel_position(previous_view_projection, previous_world, vec2(size));

  // Bilinear taps around the previous position that are this surface.
  const vec2 base = previous - 0.5;
  const ivec2 corner = ivec2(floor(base));
  const vec2 f = base - vec2(corner);
  const float camera_distance = distance(camera_position.xyz, position.xyz);
  vec4 sum = vec4(0.0);
  float weight = 0.0;
  if (previous.x >= 0.0) {
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const ivec2 tap = corner + ivec2(i, j);
        if (any(lessThan(tap, ivec2(0))) || any(greaterThanEqual(tap, size))) continue;
        if (!same_surface(previous_world, normal, camera_distance, previous_rays, tap, texelFetch(previous_guide, tap, 0).xy,
                          depth_tolerance))
          continue;
        const float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
        sum += w * texelFetch(history, tap, 0);
        weight += w;
      }
  }
  if (weight < 1e-3) {  // disoccluded
    imageStore(accumulated, pixel, vec4(c, 1.0));
    store_motion(index, vec2(-1.0));
    return;
  }
  store_motion(index, previous);
  vec4 history_value = sum / weight;

  // Neighbourhood clamp: the history may not stray far from what this frame sees around the pixel.
  vec3 mean = vec3(0.0), square = vec3(0.0);
  float count = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) {
      const vec4 v = tile[local.y + y][local.x + x];
      if (v.a == 0.0) continue;
      mean += v.rgb;
      square += v.rgb * v.rgb;
      count += 1.0;
    }
  mean /= count;
  const vec3 deviation = sqrt(max(square / count - mean * mean, vec3(0.0)));
  const vec3 clamped = clamp(history_value.rgb, mean - clamp_sigma * deviation, mean + clamp_sigma * deviation);

  // A sharp reflection moves over its surface when the camera moves, so the surface's motion vector
  // reprojects it to the wrong place: near-mirrors keep little history (their samples are nearly
  // noise-free anyway), a lobe of roughness >= 0.3 the full max_history.
  const float sharpness = clamp(roughness / 0.3, 0.0, 1.0);
  const float n = min(history_value.a + 1.0, 1.0 + (max_history - 1.0) * sharpness * sharpness);
  imageStore(accumulated, pixel, vec4(mix(clamped, c, 1.0 / n), n));
}
