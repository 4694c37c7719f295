// The GpuScene instance buffer (read-only std430 SSBO at render::kInstanceBinding = 4).
#include "include/scene_types.glsl"

layout(std430, binding = 4) readonly buffer Instances { GpuInstance instances[]; };
