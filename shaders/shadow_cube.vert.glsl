#version 450 core
// Shadow cube map: world-space vertices; the geometry shader projects them onto the six faces.

#include "include/scene_instances.glsl"

layout(location = 0) in vec4 position_u;
layout(location = 2) in uint instance_index;

out vec3 vertex_world_position;

void main() {
  vertex_world_position = (instances[instance_index].model * vec4(position_u.xyz, 1.0)).xyz;
}
