// The GpuScene geometry buffers (read-only std430 SSBOs at render::kVertexBufferBinding = 1,
// kIndexBufferBinding = 2, kMeshRangeBinding = 3): everything needed to rebuild a hit triangle.
#include "include/scene_types.glsl"

layout(std430, binding = 1) readonly buffer Vertices { GpuVertex vertices[]; };
layout(std430, binding = 2) readonly buffer Indices { uint indices[]; };  // mesh-local, 3 per triangle
layout(std430, binding = 3) readonly buffer MeshRanges { GpuMeshRange mesh_ranges[]; };
