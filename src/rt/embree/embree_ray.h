#pragma once
// glint's ray as Embree's RTCRay, shared by accel-bench's Embree structures (embree_trace.cpp) and
// the embree ray tracer backend (rt/embree_ray_tracer.cpp): the same inclusive [tnear, tfar], every
// geometry (mask), no motion blur.
#include "accel/ray.h"

#include <embree3/rtcore.h>

namespace glint::rt {

inline RTCRay embree_ray(const accel::Ray& ray) {
  RTCRay query;
  query.org_x = ray.origin.x;
  query.org_y = ray.origin.y;
  query.org_z = ray.origin.z;
  query.tnear = ray.t_min;
  query.dir_x = ray.direction.x;
  query.dir_y = ray.direction.y;
  query.dir_z = ray.direction.z;
  query.time = 0.0f;
  query.tfar = ray.t_max;
  query.mask = 0xFFFFFFFFu;
  query.id = 0;
  query.flags = 0;
  return query;
}

}  // namespace glint::rt
