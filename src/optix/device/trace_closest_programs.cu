// The OptiX device programs of the optix backend: one closest-hit query per ray of glint's ray list,
// written as glint's hit record (src/rt/ray_tracer.h's convention), so shading is the same for every
// backend. Compiled at build time to OptiX-IR and embedded in the binary
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

// One thread per slot of the ray list; slots past the GPU-side ray count do nothing.
extern "C" __global__ void __raygen__trace_closest() {
  const glint::optix::OptixLaunchParams& params = glint_launch_params;
  const unsigned int index = optixGetLaunchIndex().x;
  if (index >= params.capacity || index >= *params.ray_count) return;
  const float4 origin_tmin = params.rays[index].origin_tmin;
  const float4 direction_tmax = params.rays[index].direction_tmax;
  // Payload: t, instance, prim, u, v. The miss program leaves them at "no hit".
  unsigned int t_bits = __float_as_uint(infinity());
  unsigned int instance = kInvalidIndex;
  unsigned int prim = kInvalidIndex;
  unsigned int u_bits = 0u;
  unsigned int v_bits = 0u;
  // glint's rays have an inclusive [t_min, t_max] with t_max possibly infinite; OptiX takes the
  // largest finite float as "unbounded" just as well, and a finite bound is what validation expects.
  const float t_max = fminf(direction_tmax.w, 3.402823466e38f);
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

// A miss: the payload keeps raygen's "no hit" values (accel::Hit{}).
extern "C" __global__ void __miss__no_hit() {}
