#version 450 core
// Primary hits to visibility ids (PrimaryRayPass): the closest hit of pixel i's camera ray becomes
// the id VisibilityIdPass would have drawn there, {instance + 1, triangle} (visibility.frag.glsl),
// {0, 0} for a miss. The tracers' instance is the Scene's instance index, as GpuScene's.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"

struct Hit { float t; uint instance, prim; float u, v; };  // accel::Hit
layout(std430, binding = 11) readonly buffer PrimaryHits { Hit hits[]; };

layout(binding = 0, rg32ui) uniform writeonly uimage2D visibility_ids;

const uint kInvalidIndex = 0xFFFFFFFFu;

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, viewport.xy))) return;
  const Hit hit = hits[pixel.y * viewport.x + pixel.x];
  const uvec2 id = hit.prim == kInvalidIndex ? uvec2(0u) : uvec2(hit.instance + 1u, hit.prim);
  imageStore(visibility_ids, pixel, uvec4(id, 0u, 0u));
}
