#version 450 core
// Shadow cube map: emits each triangle to every cube face (gl_Layer = face) whose frustum it may
// touch, so all six faces are rendered in one layered pass.

layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;

uniform mat4 face_view_projection[6];  // light's 90-degree views from the origin, GL cube-map face order +X..-Z

in vec3 vertex_light_position[];  // relative to the light (shadow_cube.vert.glsl)

void main() {
  for (int face = 0; face < 6; ++face) {
    vec4 clip[3];
    for (int i = 0; i < 3; ++i) clip[i] = face_view_projection[face] * vec4(vertex_light_position[i], 1.0);
    // Skip the face when all three corners are outside one of its frustum planes (most triangles
    // land on one or two faces; the other faces would only clip them away, at a cost).
    bool outside = false;
    for (int axis = 0; axis < 3 && !outside; ++axis) {
      outside = (clip[0][axis] > clip[0].w && clip[1][axis] > clip[1].w && clip[2][axis] > clip[2].w) ||
                (clip[0][axis] < -clip[0].w && clip[1][axis] < -clip[1].w && clip[2][axis] < -clip[2].w);
    }
    if (outside) continue;
    for (int i = 0; i < 3; ++i) {
      gl_Layer = face;
      gl_Position = clip[i];
      EmitVertex();
    }
    EndPrimitive();
  }
}
