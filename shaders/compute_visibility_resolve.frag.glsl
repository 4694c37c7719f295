#version 450 core
// Compute rasteriser, last step (ComputeVisibilityPass): a full-screen draw that turns each pixel's
// kept triangle into the id VisibilityIdPass writes ({instance + 1, triangle in its mesh}, {0, 0}
// for the background) and writes the kept depth into the depth target (1 where nothing was drawn,
// the id draw's clear), so every later pass finds the targets as the id draw leaves them. A draw,
// because compute shaders cannot write a depth texture.
#include "include/frame_constants.glsl"
#include "include/compute_visibility_buffers.glsl"

uniform uint instance_count;

layout(location = 0) out uvec2 visibility_id;

void main() {
  const ivec2 pixel = ivec2(gl_FragCoord.xy);
  const uint i = uint(pixel.y * viewport.x + pixel.x);
  const uint triangle = winners[i];
  if (triangle == kNothingDrawn) {
    visibility_id = uvec2(0u);
    gl_FragDepth = 1.0;
    return;
  }
  const uint instance = instance_of_triangle(triangle, instance_count);
  visibility_id = uvec2(instance + 1u, triangle - instance_first_triangle[instance]);
  gl_FragDepth = uintBitsToFloat(depth_keys[i]);
}
