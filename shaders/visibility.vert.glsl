#version 450 core
// Visibility buffer, geometry (VisibilityIdPass, docs/render.md): transforms one instance's vertices
// to clip space exactly as gbuffer.vert.glsl does (both declare gl_Position invariant, so both
// G-buffer methods rasterise the same pixels with the same depths) and hands the instance index to
// the fragment shader. No other varying: the compute pass rebuilds the surface from the ids.

#include "include/frame_constants.glsl"

#include "include/scene_instances.glsl"

layout(location = 0) in vec4 position_u;
layout(location = 2) in uint instance_index;

flat out uint instance;

invariant gl_Position;

void main() {
  const vec4 world = instances[instance_index].model * vec4(position_u.xyz, 1.0);
  instance = instance_index;
  gl_Position = clip_from_world(world.xyz);
}
