#version 450 core
// G-buffer geometry: transforms one instance's vertices to world and clip space. The instance index
// arrives as a per-instance attribute (GpuScene sets baseInstance = instance index per draw).

#include "include/frame_constants.glsl"

#include "include/scene_instances.glsl"
#include "include/surface_motion.glsl"

uniform int write_motion;  // render::SurfaceMotion is on: world_motion is written (else 0)

layout(location = 0) in vec4 position_u;
layout(location = 1) in vec4 normal_v;
layout(location = 2) in uint instance_index;

out vec3 world_position;
out vec3 world_normal;
out vec2 uv;
out vec3 world_motion;  // previous minus current world position (0 where the vertex did not move)
flat out uint material;

// The visibility G-buffer's id pass (visibility.vert.glsl) computes gl_Position the same way; invariant
// in both makes the two G-buffer methods cover the same pixels with the same depths.
invariant gl_Position;

void main() {
  GpuInstance instance = instances[instance_index];
  vec4 world = instance.model * vec4(position_u.xyz, 1.0);
  world_position = world.xyz;
  world_normal = mat3(instance.normal_matrix) * normal_v.xyz;
  uv = vec2(position_u.w, normal_v.w);
  material = instance.material;
  // gl_VertexID includes the draw's base vertex: the vertex's index into the scene's vertex buffer.
  world_motion = write_motion != 0 && mesh_moves[instance.mesh] != 0u
                     ? vertex_world_motion(instance.model, uint(gl_VertexID), position_u.xyz)
                     : vec3(0.0);
  gl_Position = clip_from_world(world.xyz);  // camera-relative (include/frame_constants.glsl)
}
