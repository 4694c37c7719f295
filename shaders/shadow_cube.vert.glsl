#version 450 core
// Shadow cube map: world-space vertices; the geometry shader projects them onto the six faces.

struct GpuInstance { mat4 model; mat4 normal_matrix; uint mesh; uint material; uint pad0; uint pad1; };
layout(std430, binding = 4) readonly buffer Instances { GpuInstance instances[]; };

layout(location = 0) in vec4 position_u;
layout(location = 2) in uint instance_index;

out vec3 vertex_world_position;

void main() {
  vertex_world_position = (instances[instance_index].model * vec4(position_u.xyz, 1.0)).xyz;
}
