// The previous frame's GpuScene vertices (render::SurfaceMotion, src/render/surface_motion.h;
// read-only std430 SSBO at render::kPreviousVertexBufferBinding = 29), which meshes move, and the
// world displacement of a vertex since then. The G-buffer methods interpolate it into the world_motion image, which the
// reflection denoiser adds to a pixel's world position to find where its surface point was.
#include "include/scene_types.glsl"

layout(std430, binding = 29) readonly buffer PreviousVertices { GpuVertex previous_vertices[]; };
// Per mesh: 1 when it deforms (its vertices may move), else 0 (render::kMovingMeshBinding = 30).
layout(std430, binding = 30) readonly buffer MovingMeshes { uint mesh_moves[]; };

// Previous minus current world position of vertex `vertex` (an index into vertices[]) of an instance
// with `model`, whose current object-space position is `current`: exactly 0 for a vertex that did
// not move (the difference is taken in object space, before the transform).
vec3 vertex_world_motion(mat4 model, uint vertex, vec3 current) {
  return mat3(model) * (previous_vertices[vertex].position_u.xyz - current);
}
