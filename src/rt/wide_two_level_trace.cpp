#include "rt/wide_two_level_trace.h"

#include "accel/bvh_node.h"
#include "accel/tlas_traverse.h"
#include "accel/trace.h"
#include "accel/wide/wide_bvh_trace.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <type_traits>

namespace glint::rt {
namespace {

// As accel's two-level batch: chunks small enough to balance incoherent reflection rays, whose
// cost per ray varies a lot, across the cores.
constexpr size_t kRayGrain = 64;

struct WideTlasView {
  accel::TlasView tlas;
  const accel::WideBvh8* const* wide = nullptr;
};

// One ray through the two levels. kAnyHit false: the closest hit into `hit`, with `kernel` the
// closest-hit kernel; true: returns at the first hit (`hit` untouched), `kernel` the any-hit kernel.
// One walk for both, switched at compile time, so the closest-hit path is unchanged by the other.
template <bool kAnyHit>
using WideKernel8 = std::conditional_t<kAnyHit, accel::WideAnyKernel8, accel::WideClosestKernel8>;

template <bool kAnyHit>
bool trace_one(const WideTlasView& view, WideKernel8<kAnyHit> kernel, const accel::Ray& ray, accel::Hit& hit) {
  float t_max = ray.t_max;
  return accel::traverse_bvh<kAnyHit>(view.tlas.bvh, ray.origin, ray.direction, ray.t_min, t_max,
                                      [&](uint32_t index, float& t_limit) {
    const accel::Instance& instance = view.tlas.instances[index];
    const accel::ObjectRay object = accel::to_object_space(instance, ray);
    const accel::WideBvh8* wide = view.wide[instance.blas];
    const accel::Blas& blas = view.tlas.blases[instance.blas];
    if constexpr (kAnyHit) {
      if (wide == nullptr)
        return accel::intersect_any(blas.bvh, blas.mesh, object.origin, object.direction, ray.t_min, ray.t_max);
      const accel::Ray local{object.origin, ray.t_min, object.direction, ray.t_max};
      uint8_t occluded = 0;
      kernel(*wide, &local, &occluded, 1);
      return occluded != 0;
    } else {
      if (wide == nullptr) {
        if (!accel::intersect_closest(blas.bvh, blas.mesh, object.origin, object.direction, ray.t_min, t_limit, hit))
          return false;
        hit.instance = index;
        return true;
      }
      // The binary traversal keeps the first of equal t across instances too; the wide kernel starts
      // every call afresh and would take an equal t, so once something was hit only strictly closer
      // floats are allowed. The box tests stay conservative (one ulp is far inside their slack).
      const float limit = hit.valid() ? std::nextafter(t_limit, -accel::kInfinity) : t_limit;
      const accel::Ray local{object.origin, ray.t_min, object.direction, limit};
      accel::Hit local_hit;
      kernel(*wide, &local, &local_hit, 1);
      if (!local_hit.valid()) return false;
      t_limit = local_hit.t;
      hit = local_hit;
      hit.instance = index;
      return true;
    }
  });
}

WideTlasView checked_view(const accel::Tlas& tlas, std::span<const accel::Blas> blases,
                          std::span<const accel::WideBvh8* const> wide, size_t ray_count, size_t result_count) {
  accel::check_traceable(tlas.bvh, tlas.instances.size(), "instances");
  accel::check_batch_sizes(ray_count, result_count);
  if (wide.size() != blases.size()) fail("rt: {} wide BVHs for {} BLASes", wide.size(), blases.size());
  for (size_t i = 0; i < tlas.instances.size(); ++i)
    if (tlas.instances[i].blas >= blases.size())
      fail("rt: instance {} uses BLAS {} of {}", i, tlas.instances[i].blas, blases.size());
  for (size_t b = 0; b < wide.size(); ++b) {
    if (wide[b] == nullptr) continue;
    if (wide[b]->prim_count != blases[b].mesh.triangle_count)
      fail("rt: wide BVH {} is over {} triangles, its BLAS mesh has {}", b, wide[b]->prim_count,
           blases[b].mesh.triangle_count);
    if (wide[b]->depth > accel::kMaxBvhDepth)
      fail("rt: wide BVH {} depth {} exceeds the traversal limit {}", b, wide[b]->depth, accel::kMaxBvhDepth);
  }
  return {{tlas.bvh.view(), tlas.instances.data(), blases.data()}, wide.data()};
}

}  // namespace

void trace_closest_wide(const accel::Tlas& tlas, std::span<const accel::Blas> blases,
                        std::span<const accel::WideBvh8* const> wide, std::span<const accel::Ray> rays,
                        std::span<accel::Hit> hits) {
  const WideTlasView view = checked_view(tlas, blases, wide, rays.size(), hits.size());
  const accel::WideClosestKernel8 kernel = accel::wide_closest_kernel8();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      accel::Hit hit;
      trace_one<false>(view, kernel, rays[i], hit);
      hits[i] = hit;
    }
  });
}

void trace_any_wide(const accel::Tlas& tlas, std::span<const accel::Blas> blases,
                    std::span<const accel::WideBvh8* const> wide, std::span<const accel::Ray> rays,
                    std::span<uint8_t> occluded) {
  const WideTlasView view = checked_view(tlas, blases, wide, rays.size(), occluded.size());
  const accel::WideAnyKernel8 kernel = accel::wide_any_kernel8();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      accel::Hit unused;
      occluded[i] = trace_one<true>(view, kernel, rays[i], unused) ? 1 : 0;
    }
  });
}

}  // namespace glint::rt
