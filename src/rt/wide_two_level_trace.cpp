#include "rt/wide_two_level_trace.h"

#include "accel/bvh_node.h"
#include "accel/tlas_traverse.h"
#include "accel/trace.h"
#include "accel/wide_bvh_trace.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace glint::rt {
namespace {

// As accel's two-level batch: chunks small enough to balance incoherent reflection rays, whose
// cost per ray varies a lot, across the cores.
constexpr size_t kRayGrain = 64;

struct WideTlasView {
  accel::TlasView tlas;
  const accel::WideBvh8* const* wide = nullptr;
};

accel::Hit trace_one(const WideTlasView& view, accel::WideClosestKernel8 kernel, const accel::Ray& ray) {
  accel::Hit hit;
  float t_max = ray.t_max;
  accel::traverse_bvh<false>(view.tlas.bvh, ray.origin, ray.direction, ray.t_min, t_max, [&](uint32_t index, float& t_limit) {
    const accel::Instance& instance = view.tlas.instances[index];
    const vec3 origin(instance.world_to_object * vec4(ray.origin, 1.0f));
    const vec3 direction(instance.world_to_object * vec4(ray.direction, 0.0f));
    const accel::WideBvh8* wide = view.wide[instance.blas];
    if (wide == nullptr) {
      const accel::Blas& blas = view.tlas.blases[instance.blas];
      if (!accel::intersect_closest(blas.bvh, blas.mesh, origin, direction, ray.t_min, t_limit, hit)) return false;
      hit.instance = index;
      return true;
    }
    // The binary traversal keeps the first of equal t across instances too; the wide kernel starts
    // every call afresh and would take an equal t, so once something was hit only strictly closer
    // floats are allowed. The box tests stay conservative (one ulp is far inside their slack).
    const float limit = hit.valid() ? std::nextafter(t_limit, -accel::kInfinity) : t_limit;
    const accel::Ray local{origin, ray.t_min, direction, limit};
    accel::Hit local_hit;
    kernel(*wide, &local, &local_hit, 1);
    if (!local_hit.valid()) return false;
    t_limit = local_hit.t;
    hit = local_hit;
    hit.instance = index;
    return true;
  });
  return hit;
}

}  // namespace

void trace_closest_wide(const accel::Tlas& tlas, std::span<const accel::Blas> blases,
                        std::span<const accel::WideBvh8* const> wide, std::span<const accel::Ray> rays,
                        std::span<accel::Hit> hits) {
  accel::check_traceable(tlas.bvh, tlas.instances.size(), "instances");
  accel::check_batch_sizes(rays.size(), hits.size());
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
  const WideTlasView view{{tlas.bvh.view(), tlas.instances.data(), blases.data()}, wide.data()};
  const accel::WideClosestKernel8 kernel = accel::wide_closest_kernel8();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) hits[i] = trace_one(view, kernel, rays[i]);
  });
}

}  // namespace glint::rt
