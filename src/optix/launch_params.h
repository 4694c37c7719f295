#pragma once
// What the host hands the OptiX device programs (src/optix/device/trace_closest_programs.cu) at each
// launch, in the pipeline's launch-parameter block. Shared by host and device code, so it uses only
// CUDA's vector types and OptiX's handle type: the device programs never include glm. The host side
// checks that OptixRayRecord and OptixHitRecord have the layouts of accel::Ray and accel::Hit
// (optix_trace_launch.cpp), which is what lets raygen read glint's ray list and write glint's hit
// records in place.
#include <optix_types.h>
#include <vector_types.h>

#include <cstdint>

namespace glint::optix {

// accel::Ray: origin.xyz, t_min | direction.xyz, t_max, as two 16-byte loads.
struct OptixRayRecord {
  float4 origin_tmin;
  float4 direction_tmax;
};

// accel::Hit: t, instance, prim, u, v (a miss: t = infinity, instance = prim = 0xFFFFFFFF).
struct OptixHitRecord {
  float t;
  std::uint32_t instance;
  std::uint32_t prim;
  float u;
  float v;
};

struct OptixLaunchParams {
  OptixTraversableHandle root = 0;  // the IAS over the scene's instances, or one GAS (accel-bench)
  const OptixRayRecord* rays = nullptr;
  // Which query: null `occluded` traces closest hits into `hits`; otherwise the occlusion query
  // (terminate on first hit) writes occluded[i] = 1 when ray i hits anything, else 0, and `hits` is
  // unused.
  OptixHitRecord* hits = nullptr;
  std::uint32_t* occluded = nullptr;
  // Rays to trace, read on the GPU: the launch has `capacity` threads and those at or past
  // *ray_count return at once, so the host never waits for the count.
  const std::uint32_t* ray_count = nullptr;
  std::uint32_t capacity = 0;
};

// The name the device programs declare their launch parameters under (OptixPipelineCompileOptions).
inline constexpr const char* kLaunchParamsName = "glint_launch_params";

}  // namespace glint::optix
