// The GpuScene material buffer (read-only std430 SSBO at render::kMaterialBinding = 5).
#include "include/scene_types.glsl"

layout(std430, binding = 5) readonly buffer Materials { GpuMaterial materials[]; };
