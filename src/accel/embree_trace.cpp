// EmbreeScene's batch queries: rtcIntersect1/rtcOccluded1 per ray in TBB chunks.
#include "accel/embree_scene.h"

#include "accel/trace.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace glint::accel {
namespace {

// Same grain as glint's own batches (accel/trace.cpp), so both are scheduled alike.
constexpr size_t kRayGrain = 64;

void set_ray(const Ray& in, RTCRay& out) {
  out.org_x = in.origin.x;
  out.org_y = in.origin.y;
  out.org_z = in.origin.z;
  out.tnear = in.t_min;
  out.dir_x = in.direction.x;
  out.dir_y = in.direction.y;
  out.dir_z = in.direction.z;
  out.time = 0.0f;
  out.tfar = in.t_max;
  out.mask = 0xFFFFFFFFu;
  out.id = 0;
  out.flags = 0;
}

}  // namespace

void EmbreeScene::trace_closest(std::span<const Ray> rays, std::span<Hit> hits) const {
  check_batch_sizes(rays.size(), hits.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (size_t i = range.begin(); i != range.end(); ++i) {
      RTCRayHit ray_hit;
      set_ray(rays[i], ray_hit.ray);
      ray_hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      ray_hit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene_, &context, &ray_hit);
      Hit hit;
      if (ray_hit.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        hit.t = ray_hit.ray.tfar;
        hit.instance = 0;
        hit.prim = ray_hit.hit.primID;
        hit.u = ray_hit.hit.u;
        hit.v = ray_hit.hit.v;
      }
      hits[i] = hit;
    }
  });
  device_.check("trace_closest");
}

void EmbreeScene::trace_any(std::span<const Ray> rays, std::span<uint8_t> occluded) const {
  check_batch_sizes(rays.size(), occluded.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (size_t i = range.begin(); i != range.end(); ++i) {
      RTCRay ray;
      set_ray(rays[i], ray);
      rtcOccluded1(scene_, &context, &ray);
      // Embree marks an occluded ray by setting tfar to -infinity.
      occluded[i] = ray.tfar == -kInfinity ? 1 : 0;
    }
  });
  device_.check("trace_any");
}

}  // namespace glint::accel
