#version 450 core
// Shadow cube map, one face per draw (ShadowCubeDraw::per_face): the face's view-projection here,
// no geometry shader. Same arithmetic as shadow_cube.vert.glsl + shadow_cube.geom.glsl, so both ways
// rasterise the same triangles to the same depths.

#include "include/scene_instances.glsl"

layout(location = 0) in vec4 position_u;
layout(location = 2) in uint instance_index;

uniform mat4 face_view_projection;  // this draw's face seen from the origin, GL cube-map face order +X..-Z
uniform vec3 light_origin;          // the light's world position: vertices are made light-relative

void main() {
  vec3 light_position = (instances[instance_index].model * vec4(position_u.xyz, 1.0)).xyz - light_origin;
  gl_Position = face_view_projection * vec4(light_position, 1.0);
}
