#pragma once
// The agreement rule between two structures' closest hits on the same ray: both miss, or both hit
// at t within a relative tolerance. A different triangle at (nearly) the same t is a tie (shared
// edge or vertex, duplicate or coplanar overlapping triangles) and accepted: which one a structure
// reports depends on its traversal order, not on its correctness.
#include "accel/ray.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace glint::accel_bench {

inline constexpr float kHitRelativeTolerance = 1e-4f;

// Why `actual` disagrees with `reference`, or nullopt when they agree.
std::optional<std::string> hit_disagreement(const accel::Hit& reference, const accel::Hit& actual);

// Throws glint::Error "accel-bench: <structure> disagrees with <reference> on ray <i> (origin ...,
// direction ...): <why>" at the first disagreement; also when the sizes differ.
void check_hits(std::string_view structure, std::string_view reference, std::span<const accel::Ray> rays,
                std::span<const accel::Hit> reference_hits, std::span<const accel::Hit> hits);

}  // namespace glint::accel_bench
