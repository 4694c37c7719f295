#pragma once
// The agreement rule between two structures' closest hits on the same ray: both miss, or both hit
// at t within what single precision can tell apart at that place (hit_t_tolerance below). A
// different triangle at (nearly) the same t is a tie (shared edge or vertex, duplicate or coplanar
// overlapping triangles) and accepted: which one a structure reports depends on its traversal order,
// not on its correctness.
#include "accel/ray.h"
#include "accel/triangle_mesh.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace glint::accel_bench {

// The triangles the structures were built over (a hit's prim indexes them) and the largest
// |coordinate| of their vertices: every vertex and every hit point lies within that of the origin on
// each axis, so it bounds the rounding of their coordinates. It grows with the scene's size and with
// its offset from the origin alike.
struct HitGeometry {
  accel::TriangleMesh mesh;
  float magnitude = 0.0f;
};
HitGeometry hit_geometry(const accel::TriangleMesh& mesh);

// |cos| of the angle between the ray and the triangle's normal: 1 head on, 0 along the triangle's
// plane (or for a degenerate triangle).
float incidence_cosine(const accel::Ray& ray, const accel::Triangle& triangle);

// How far apart (in units of ray.direction) two single-precision t of one surface point may be:
//
//   kHitToleranceUlps * FLT_EPSILON * max(magnitude, max |ray.origin coordinate|)
//     / (|ray.direction| * max(incidence_cosine, kMinIncidenceCosine))
//
// Why: every single-precision ray/triangle test (glint's watertight one, Embree's, OptiX's) works on
// the triangle moved into the ray's frame (vertex - origin, or edges vertex - vertex precomputed in
// world space). Each coordinate of those is rounded by up to FLT_EPSILON * M, M the largest
// |coordinate| involved: the vertices' (<= magnitude) and the origin's. That is the same as moving
// the triangle's plane by about FLT_EPSILON * M, which moves the point where the ray meets it by as
// much divided by the incidence cosine, i.e. t by that over |direction|. The rest of the test
// (shear or cross products, the quotient for t) rounds terms of size up to |vertex - origin| <=
// 2 sqrt(3) M, and a thin triangle's normal is only known to FLT_EPSILON over the sine of its
// angle. The two structures compared round differently, so their errors add. The error is absolute,
// not relative to t: near a far-away ray's origin t is tiny while its error is not (a camera inside
// a plane sees it at t = 0 or 1.4e-7, both right).
//
// Measured (|t_a - t_b| * cosine in units of FLT_EPSILON * M / |direction|, Embree's qualities
// against glint's median BVH, up to 172,800 rays of three 320x180 frames each; glint's structures
// agree bit for bit): at most 1.3 for Sponza's reflection rays, 26 for random rays in Sponza, 41
// for random rays in Sponza scaled by 100 (coordinates to 1,742), 11 for primary rays in Sponza
// scaled by 1000 and moved to (20000, 5000, -30000) (coordinates to 37,800); without the cosine up
// to 104 (a random ray at 85 degrees from the normal). kHitToleranceUlps = 128 leaves three times the worst seen. On the
// atrium (coordinates to 20.5) a head-on hit may then differ by 3.1e-4 units; on Sponza moved away
// as above by 0.58 units, in a scene 34,800 units long.
inline constexpr float kHitToleranceUlps = 128.0f;
// Below this cosine (0.06 degrees from the plane) t is taken to be as uncertain as at this cosine:
// a ray in the plane has no single t at all, and the tolerance must stay finite.
inline constexpr float kMinIncidenceCosine = 1e-3f;

float hit_t_tolerance(const accel::Ray& ray, float magnitude, float incidence_cosine);

// Why `actual` disagrees with `reference` on `ray`, or nullopt when they agree (above). A tie
// (another triangle) is allowed the larger tolerance of the two triangles. A hit within its
// tolerance of the ray's t_min (or t_max) agrees with a miss, and a nearer hit within its tolerance
// of t_min with a farther hit: the other structure may have computed that t just outside the range
// (a camera inside a plane sees it at t = 0 in one structure and at t = -1e-7, a miss, in another).
std::optional<std::string> hit_disagreement(const accel::Ray& ray, const accel::Hit& reference, const accel::Hit& actual,
                                            const HitGeometry& geometry);

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
                    std::span<const accel::Hit> reference_hits, std::span<const accel::Hit> hits,
                    const HitGeometry& geometry);

}  // namespace glint::accel_bench
