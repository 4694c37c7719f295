#pragma once
// glint's rays and hits seen as the device programs' records (launch_params.h): the layouts
// are checked here, once, so raygen can read accel::Ray lists and write accel::Hit records in place,
// in the GL buffers the renderer shares with CUDA.
#include "accel/ray.h"
#include "optix/launch_params.h"

#include <cstddef>

namespace glint::optix {

static_assert(sizeof(accel::Ray) == sizeof(OptixRayRecord) && offsetof(accel::Ray, t_min) == 12 &&
                  offsetof(accel::Ray, direction) == 16 && offsetof(accel::Ray, t_max) == 28,
              "OptixRayRecord reads accel::Ray as origin.xyz, t_min | direction.xyz, t_max");
static_assert(sizeof(accel::Hit) == sizeof(OptixHitRecord) && offsetof(accel::Hit, t) == offsetof(OptixHitRecord, t) &&
                  offsetof(accel::Hit, instance) == offsetof(OptixHitRecord, instance) &&
                  offsetof(accel::Hit, prim) == offsetof(OptixHitRecord, prim) &&
                  offsetof(accel::Hit, u) == offsetof(OptixHitRecord, u) &&
                  offsetof(accel::Hit, v) == offsetof(OptixHitRecord, v),
              "OptixHitRecord writes accel::Hit");
static_assert(accel::Hit::kInvalidIndex == 0xFFFFFFFFu, "the miss program's invalid index");

inline const OptixRayRecord* as_ray_records(const accel::Ray* rays) {
  return reinterpret_cast<const OptixRayRecord*>(rays);
}
inline OptixHitRecord* as_hit_records(accel::Hit* hits) { return reinterpret_cast<OptixHitRecord*>(hits); }

}  // namespace glint::optix
