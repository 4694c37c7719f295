#version 450 core
// G-buffer geometry: transforms one instance's vertices to world and clip space. The instance index
// arrives as a per-instance attribute (GpuScene sets baseInstance = instance index per draw).

layout(std140, binding = 0) uniform FrameConstants {
  mat4 view; mat4 projection; mat4 view_projection; mat4 inverse_view; mat4 inverse_projection;
  vec4 camera_position; vec4 light_position_range; vec4 light_color_intensity; vec4 sky_color;
  vec4 near_far; ivec4 viewport;
};

struct GpuInstance { mat4 model; mat4 normal_matrix; uint mesh; uint material; uint pad0; uint pad1; };
layout(std430, binding = 4) readonly buffer Instances { GpuInstance instances[]; };

layout(location = 0) in vec4 position_u;
layout(location = 1) in vec4 normal_v;
layout(location = 2) in uint instance_index;

out vec3 world_position;
out vec3 world_normal;
out vec2 uv;
flat out uint material;

void main() {
  GpuInstance instance = instances[instance_index];
  vec4 world = instance.model * vec4(position_u.xyz, 1.0);
  world_position = world.xyz;
  world_normal = mat3(instance.normal_matrix) * normal_v.xyz;
  uv = vec2(position_u.w, normal_v.w);
  material = instance.material;
  gl_Position = view_projection * world;
}
