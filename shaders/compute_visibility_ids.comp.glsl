#version 450 core
#include "include/compute_raster_extensions.glsl"
// Compute rasteriser, last step (ComputeVisibilityPass::run): each pixel's kept triangle becomes the
// id VisibilityIdPass writes, stored into the id image by a compute dispatch (all SMs; the draw that
// also writes the depth runs on the graphics SMs and only when the depth is read:
// compute_visibility_resolve.frag.glsl).
layout(local_size_x = 8, local_size_y = 8) in;  // render::kImageTileSize

#include "include/frame_constants.glsl"
#include "include/compute_visibility_buffers.glsl"

layout(binding = 0, rg32ui) uniform writeonly uimage2D visibility_ids;

uniform uint instance_count;

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, viewport.xy))) return;
  const uint i = uint(pixel.y * viewport.x + pixel.x);
  imageStore(visibility_ids, pixel, uvec4(kept_triangle_id(i, instance_count), 0u, 0u));
}
