#version 450 core
#include "include/compute_raster_extensions.glsl"
// Compute rasteriser, the depth on demand (ComputeVisibilityPass::write_depth): a full-screen draw
// that writes the kept depth into the depth target (1 where nothing was drawn, the id draw's clear)
// and the id again (the same as compute_visibility_ids.comp.glsl stored), so the targets are as the
// id draw leaves them. A draw, because compute shaders cannot write a depth texture; only when the
// depth is read (no frame pass reads it), since the graphics SMs are few on some GPUs.
#include "include/frame_constants.glsl"
#include "include/compute_visibility_buffers.glsl"

uniform uint instance_count;

layout(location = 0) out uvec2 visibility_id;

void main() {
  const ivec2 pixel = ivec2(gl_FragCoord.xy);
  const uint i = uint(pixel.y * viewport.x + pixel.x);
  visibility_id = kept_triangle_id(i, instance_count);
  gl_FragDepth = kept_triangle(i) == kNothingDrawn ? 1.0 : uintBitsToFloat(kept_depth_key(i));
}
