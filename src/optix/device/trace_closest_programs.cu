// The OptiX device programs of the optix backend: one closest-hit query per ray of glint's ray list,
// written as glint's hit record (src/rt/ray_tracer.h's convention), so shading is the same for every
// backend; or, when the launch parameters carry an occlusion buffer, one occlusion query per ray. Compiled at build time to OptiX-IR and embedded in the binary
// (cmake/GlintOptix.cmake); never linked as ordinary CUDA code.
#include "optix/launch_params.h"

#include <optix.h>

extern "C" {
__constant__ glint::optix::OptixLaunchParams glint_launch_params;
}

namespace {

constexpr unsigned int kInvalidIndex = 0xFFFFFFFFu;

__device__ float infinity() { return __int_as_float(0x7f800000); }

}  // namespace

// glint's rays have an inclusive [t_min, t_max] with t_max possibly infinite; OptiX takes the
// largest finite float as "unbounded" just as well, and a finite bound is what validation expects.
__device__ float finite_t_max(float t_max) { return fminf(t_max, 3.402823466e38f); }

// The occlusion query of ray `index`: OptiX stops at the first triangle it finds (terminate on first
// hit) and runs no hit program; only the miss program, which writes "no hit" (t = infinity) over
// raygen's "hit" marker, tells a miss.
__device__ void trace_occlusion(const glint::optix::OptixLaunchParams& params, unsigned int index,
                                float4 origin_tmin, float4 direction_tmax) {
  unsigned int t_bits = 0u;  // anything but infinity: occluded unless the miss program runs
  optixTrace(params.root, make_float3(origin_tmin.x, origin_tmin.y, origin_tmin.z),
             make_float3(direction_tmax.x, direction_tmax.y, direction_tmax.z), origin_tmin.w,
             finite_t_max(direction_tmax.w), 0.0f, OptixVisibilityMask(255),
             OPTIX_RAY_FLAG_TERMINATE_ON_FIRST_HIT | OPTIX_RAY_FLAG_DISABLE_ANYHIT | OPTIX_RAY_FLAG_DISABLE_CLOSESTHIT,
             0, 1, 0, t_bits);
  params.occluded[index] = t_bits == __float_as_uint(infinity()) ? 0u : 1u;
}

// One thread per slot of the ray list; slots past the GPU-side ray count do nothing.
extern "C" __global__ void __raygen__trace_closest() {
  const glint::optix::OptixLaunchParams& params = glint_launch_params;
  const unsigned int index = optixGetLaunchIndex().x;
  if (index >= params.capacity || index >= *params.ray_count) return;
  const float4 origin_tmin = params.rays[index].origin_tmin;
  const float4 direction_tmax = params.rays[index].direction_tmax;
  if (params.occluded != nullptr) {
    trace_occlusion(params, index, origin_tmin, direction_tmax);
    return;
  }
  // Payload: t, instance, prim, u, v. The miss program leaves them at "no hit".
  unsigned int t_bits = __float_as_uint(infinity());
  unsigned int instance = kInvalidIndex;
  unsigned int prim = kInvalidIndex;
  unsigned int u_bits = 0u;
  unsigned int v_bits = 0u;
  const float t_max = finite_t_max(direction_tmax.w);
  optixTrace(params.root, make_float3(origin_tmin.x, origin_tmin.y, origin_tmin.z),
             make_float3(direction_tmax.x, direction_tmax.y, direction_tmax.z), origin_tmin.w, t_max,
             0.0f,                           // ray time (no motion blur)
             OptixVisibilityMask(255),       // every instance
             OPTIX_RAY_FLAG_DISABLE_ANYHIT,  // opaque triangles; no face culling flag: both sides hit
             0, 1, 0,                        // SBT offset, stride, miss index: one hit group, one miss
             t_bits, instance, prim, u_bits, v_bits);
  glint::optix::OptixHitRecord& hit = params.hits[index];
  hit.t = __uint_as_float(t_bits);
  hit.instance = instance;
  hit.prim = prim;
  hit.u = __uint_as_float(u_bits);
  hit.v = __uint_as_float(v_bits);
}

// The closest triangle: the instance's index in the IAS build input (= the scene's instance index;
// 0 when the root is a single GAS), the triangle's index in its mesh's index buffer, the hit's t
// along the unnormalised ray and OptiX's barycentrics, which follow glint's convention
// (point = (1 - u - v) v0 + u v1 + v v2).
extern "C" __global__ void __closesthit__triangle() {
  const float2 barycentrics = optixGetTriangleBarycentrics();
  optixSetPayload_0(__float_as_uint(optixGetRayTmax()));
  optixSetPayload_1(optixGetInstanceIndex());
  optixSetPayload_2(optixGetPrimitiveIndex());
  optixSetPayload_3(__float_as_uint(barycentrics.x));
  optixSetPayload_4(__float_as_uint(barycentrics.y));
}

// A miss: t = infinity, "no hit". The closest-hit query's raygen starts from accel::Hit{} already
// (the other payload values stay as it set them); the occlusion query reads a miss from this alone.
extern "C" __global__ void __miss__no_hit() { optixSetPayload_0(__float_as_uint(infinity())); }
