#include "accel/wide/wide_bvh_trace.h"

#include "accel/bvh_node.h"
#include "accel/trace.h"
#include "accel/wide/wide_bvh_kernels.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>

namespace glint::accel {
namespace {

// A wide traversal is cheaper per ray than a binary one, so chunks are larger than trace.cpp's to
// keep TBB's per-task overhead small, and still small enough to balance incoherent rays.
constexpr size_t kRayGrain = 256;

// -1: automatic; otherwise the forced WideSimdPath.
std::atomic<int> g_forced_path{-1};

template <int N>
void check_wide_traceable(const WideBvh<N>& bvh, size_t ray_count, size_t result_count) {
  check_batch_sizes(ray_count, result_count);
  if (bvh.depth > kMaxBvhDepth)
    fail("accel: wide BVH depth {} exceeds the traversal limit {}", bvh.depth, kMaxBvhDepth);
  if (!bvh.nodes.empty() && bvh.blocks.empty()) fail("accel: wide BVH has nodes but no triangle blocks");
}

template <typename Result, typename Kernel, typename Bvh>
void trace_parallel(const Bvh& bvh, std::span<const Ray> rays, std::span<Result> results, Kernel kernel) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    kernel(bvh, rays.data() + range.begin(), results.data() + range.begin(), range.size());
  });
}

}  // namespace

bool cpu_has_avx2() {
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return has;
}

WideSimdPath wide_simd_path() {
  const int forced = g_forced_path.load(std::memory_order_relaxed);
  if (forced >= 0) return static_cast<WideSimdPath>(forced);
  return cpu_has_avx2() ? WideSimdPath::avx2 : WideSimdPath::sse;
}

void force_wide_simd_path(std::optional<WideSimdPath> path) {
  if (path == WideSimdPath::avx2 && !cpu_has_avx2()) fail("accel: cannot force the AVX2 path: this CPU has no AVX2");
  g_forced_path.store(path ? static_cast<int>(*path) : -1, std::memory_order_relaxed);
}

void trace_closest(const WideBvh4& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  check_wide_traceable(bvh, rays.size(), hits.size());
  trace_parallel(bvh, rays, hits, wide_kernel::closest_sse4);
}

void trace_closest(const WideBvh8& bvh, std::span<const Ray> rays, std::span<Hit> hits) {
  check_wide_traceable(bvh, rays.size(), hits.size());
  trace_parallel(bvh, rays, hits, wide_closest_kernel8());
}

WideClosestKernel8 wide_closest_kernel8() {
  return wide_simd_path() == WideSimdPath::avx2 ? wide_kernel::closest_avx8 : wide_kernel::closest_sse8;
}

void trace_any(const WideBvh4& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  check_wide_traceable(bvh, rays.size(), occluded.size());
  trace_parallel(bvh, rays, occluded, wide_kernel::any_sse4);
}

void trace_any(const WideBvh8& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  check_wide_traceable(bvh, rays.size(), occluded.size());
  trace_parallel(bvh, rays, occluded, wide_any_kernel8());
}

WideAnyKernel8 wide_any_kernel8() {
  return wide_simd_path() == WideSimdPath::avx2 ? wide_kernel::any_avx8 : wide_kernel::any_sse8;
}

}  // namespace glint::accel
