#version 450 core
// Shadow cube map: vertices relative to the light (light-relative, like the camera-relative G-buffer:
// far from the origin the faces' projections see no large coordinates, docs/render.md); the
// geometry shader projects them onto the six faces.

#include "include/scene_instances.glsl"

layout(location = 0) in vec4 position_u;
layout(location = 2) in uint instance_index;

uniform vec3 light_origin;  // the light's world position, the cube map's centre

out vec3 vertex_light_position;  // world position minus light_origin

void main() {
  vertex_light_position = (instances[instance_index].model * vec4(position_u.xyz, 1.0)).xyz - light_origin;
}
