#pragma once
// Batch tracing of wide BVHs on the CPU: TBB over chunks of rays, each traced by the SIMD kernel
// for the BVH's width (SSE for 4-wide; AVX2 for 8-wide when the CPU has it, else two SSE halves).
// Hits equal the binary traversal's: the same watertight triangle test, bit for bit.
#include "accel/ray.h"
#include "accel/wide/wide_bvh.h"
#include "core/enum_names.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace glint::accel {

// hits[i] = closest hit of rays[i] (Hit{} on a miss; instance 0 on a hit). glint::Error when the
// spans differ in size or the BVH is deeper than the kernel's stack allows.
void trace_closest(const WideBvh4& bvh, std::span<const Ray> rays, std::span<Hit> hits);
void trace_closest(const WideBvh8& bvh, std::span<const Ray> rays, std::span<Hit> hits);

// occluded[i] = 1 when anything lies on rays[i] within [t_min, t_max], else 0.
void trace_any(const WideBvh4& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded);
void trace_any(const WideBvh8& bvh, std::span<const Ray> rays, std::span<uint8_t> occluded);

// The closest-hit kernel trace_closest(const WideBvh8&, ...) would use now, for callers that run
// their own loop over rays and cannot hand over a whole batch (the two-level traversal calls it
// with count 1 per instance it enters). Same contract as trace_closest per ray (Hit{} on a miss,
// instance 0 on a hit, a hit at t == ray.t_max is accepted), without the checks: the caller checks
// the BVH's depth once. Pick it once per batch: the path may be forced between batches.
using WideClosestKernel8 = void (*)(const WideBvh8& bvh, const Ray* rays, Hit* hits, size_t count);
WideClosestKernel8 wide_closest_kernel8();
// The same for the any-hit kernel trace_any(const WideBvh8&, ...) would use now.
using WideAnyKernel8 = void (*)(const WideBvh8& bvh, const Ray* rays, uint8_t* occluded, size_t count);
WideAnyKernel8 wide_any_kernel8();

// Which kernel 8-wide BVHs use.
enum class WideSimdPath { sse, avx2 };

inline constexpr EnumNames<WideSimdPath, 2> kWideSimdPathNames{
    "SIMD path", {{WideSimdPath::sse, "sse"}, {WideSimdPath::avx2, "avx2"}}};

inline std::string_view simd_path_name(WideSimdPath path) { return kWideSimdPathNames.name_of(path); }
bool cpu_has_avx2();
// avx2 when the CPU has it, unless a path was forced.
WideSimdPath wide_simd_path();
// Test and benchmark hook: force a path for every later call (process-wide; not for use while
// other threads trace). std::nullopt restores the automatic choice. Forcing avx2 on a CPU without
// it is a glint::Error.
void force_wide_simd_path(std::optional<WideSimdPath> path);

}  // namespace glint::accel
