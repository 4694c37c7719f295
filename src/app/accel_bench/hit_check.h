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

// An edge graze: the two disagree because one of them missed a hit that lies within this barycentric
// distance of its triangle's boundary (min(u, v, 1 - u - v)), i.e. at the limit of single precision.
// glint's traversal is watertight there; Embree (even with RTC_SCENE_FLAG_ROBUST) and OptiX may let
// such a ray through (seen: 1 of 1,434,105 reflection rays at 1280x720 on atrium, the hit at
// v = 2e-6, confirmed by brute force). Grazes are counted and reported, not fatal, up to
// kMaxEdgeGrazeFraction of the rays; any other disagreement is an error.
inline constexpr float kEdgeGrazeBarycentric = 1e-5f;
inline constexpr double kMaxEdgeGrazeFraction = 1e-4;

// Why `actual` disagrees with `reference`, or nullopt when they agree.
std::optional<std::string> hit_disagreement(const accel::Hit& reference, const accel::Hit& actual);

// True when the disagreement of `actual` with `reference` is an edge graze (above).
bool is_edge_graze(const accel::Hit& reference, const accel::Hit& actual);

// Throws glint::Error "accel-bench: <structure> disagrees with <reference> on ray <i> (origin ...,
// direction ...): <why>" at the first disagreement that is not an edge graze, when the grazes exceed
// kMaxEdgeGrazeFraction of the rays, or when the sizes differ. Returns the number of edge grazes.
size_t check_hits(std::string_view structure, std::string_view reference, std::span<const accel::Ray> rays,
                  std::span<const accel::Hit> reference_hits, std::span<const accel::Hit> hits);

}  // namespace glint::accel_bench
