#pragma once
// The agreement rule between two structures' closest hits on the same ray: both miss, or both hit
// at t within what single precision can tell apart at that place (hit_t_tolerance below). A
// different triangle at (nearly) the same t is a tie (shared edge or vertex, duplicate or coplanar
// overlapping triangles) and accepted: which one a structure reports depends on its traversal order,
// not on its correctness.
#include "accel/ray.h"
#include "core/math.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace glint::accel_bench {

// How many float ulps of the largest coordinate magnitude two t may differ by (hit_t_tolerance).
inline constexpr float kHitToleranceUlps = 64.0f;

// The largest |coordinate| of `bounds` (0 for an empty box): every vertex and every hit point of the
// scene is no farther from the origin than this on any axis, so it bounds the rounding of their
// coordinates. It grows with the scene's size and with its offset from the origin alike.
float coordinate_magnitude(const Aabb& bounds);

// The largest difference between two single-precision t of the same surface point along `ray`, in
// units of ray.direction, in a scene whose coordinate_magnitude is `scene_magnitude`:
//
//   kHitToleranceUlps * FLT_EPSILON * max(scene_magnitude, max |ray.origin coordinate|) / |ray.direction|
//
// Why: every single-precision ray/triangle test (glint's watertight one, Embree's, OptiX's) starts
// by moving the triangle into the ray's frame, vertex - origin (or precomputed edges, vertex -
// vertex), and rounds each coordinate of the result to within FLT_EPSILON * M, M the largest
// |coordinate| involved: the vertices (inside the scene box, so <= scene_magnitude) and the origin.
// That is the same as moving the triangle by up to about FLT_EPSILON * M, which moves the point
// where the ray meets its plane by as much divided by cos(angle of incidence), i.e. t by that over
// |direction|. The rest of the test (shear or cross products, the quotient for t) rounds terms no
// larger than |vertex - origin| <= 2 sqrt(3) M once each: a few FLT_EPSILON * M more. The two
// structures compared round differently, so their errors add. That makes about 10 FLT_EPSILON * M
// at normal incidence; the factor 64 leaves room for incidence up to about 80 degrees (1 / cos = 6)
// on top. It is absolute, not relative to t: near the origin of a far-away ray t is tiny while its
// error is not (a camera inside a plane sees it at t = 0 or 1.4e-7, both right). On the atrium
// (|coordinates| <= 22) it is about 2e-4 units; on an interior with coordinates to 1,700, 0.013; on
// Sponza scaled by 1000 and moved to (20000, 5000, -30000), about 0.4 (of a scene 30,000 units long).
float hit_t_tolerance(const accel::Ray& ray, float scene_magnitude);

// Why `actual` disagrees with `reference` on `ray`, or nullopt when they agree (above).
std::optional<std::string> hit_disagreement(const accel::Ray& ray, const accel::Hit& reference, const accel::Hit& actual,
                                            float scene_magnitude);

// An edge graze: the two disagree because one of them missed a hit that lies within this barycentric
// distance of its triangle's boundary (min(u, v, 1 - u - v)), i.e. at the limit of single precision.
// glint's traversal is watertight there; Embree (even with RTC_SCENE_FLAG_ROBUST) and OptiX may let
// such a ray through (seen: 1 of 1,434,105 reflection rays at 1280x720 on atrium, the hit at
// v = 2e-6, confirmed by brute force). Grazes are counted apart from other disagreements and
// accepted up to kMaxEdgeGrazeFraction of the rays; more than that is a disagreement of its own.
inline constexpr float kEdgeGrazeBarycentric = 1e-5f;
inline constexpr double kMaxEdgeGrazeFraction = 1e-4;

// True when the disagreement of `actual` with `reference` is an edge graze (above).
bool is_edge_graze(const accel::Hit& reference, const accel::Hit& actual);

// One structure's hits checked against the reference's.
struct HitCheck {
  size_t disagreements = 0;  // rays whose hits disagree, edge grazes not counted
  size_t edge_grazes = 0;    // rays whose hits disagree by an edge graze
  // Empty when the structure agrees: no disagreement and edge grazes within kMaxEdgeGrazeFraction.
  // Otherwise one line: "<structure> disagrees with <reference> on <n> of <rays> rays; first: ray
  // <i> (origin ..., direction ...): <why>", or the edge grazes beyond the allowance.
  std::string problem;

  bool agrees() const { return problem.empty(); }
};

// Checks every ray. glint::Error only when the sizes differ (a bug, not a disagreement).
HitCheck check_hits(std::string_view structure, std::string_view reference, std::span<const accel::Ray> rays,
                    std::span<const accel::Hit> reference_hits, std::span<const accel::Hit> hits, float scene_magnitude);

}  // namespace glint::accel_bench
