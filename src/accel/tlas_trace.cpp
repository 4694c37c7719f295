#include "accel/tlas_trace.h"

#include "accel/tlas_traverse.h"
#include "accel/trace.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace glint::accel {
namespace {

constexpr size_t kRayGrain = 64;

TlasView checked_view(const Tlas& tlas, std::span<const Blas> blases) {
  check_traceable(tlas.bvh, tlas.instances.size(), "instances");
  for (size_t i = 0; i < tlas.instances.size(); ++i)
    if (tlas.instances[i].blas >= blases.size())
      fail("accel: instance {} uses BLAS {} of {}", i, tlas.instances[i].blas, blases.size());
  return {tlas.bvh.view(), tlas.instances.data(), blases.data()};
}

}  // namespace

void trace_closest(const Tlas& tlas, std::span<const Blas> blases, std::span<const Ray> rays, std::span<Hit> hits) {
  const TlasView view = checked_view(tlas, blases);
  check_batch_sizes(rays.size(), hits.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) hits[i] = trace_closest(view, rays[i]);
  });
}

void trace_any(const Tlas& tlas, std::span<const Blas> blases, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  const TlasView view = checked_view(tlas, blases);
  check_batch_sizes(rays.size(), occluded.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) occluded[i] = trace_any(view, rays[i]) ? 1 : 0;
  });
}

}  // namespace glint::accel
