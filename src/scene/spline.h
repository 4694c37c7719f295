#pragma once
// A centripetal Catmull-Rom spline (alpha = 0.5) through a list of points, re-parametrized by arc
// length: equal steps in distance give equal steps along the curve, which is what a camera moving at
// constant speed needs. Centripetal rather than uniform knot spacing because it provably has no cusps
// or self-intersections inside a segment and does not overshoot when short and long segments meet
// (Yuksel, Schaefer & Keyser 2011), which walkthrough paths with irregular spacing always have.
//
// The arc-length table is built once in the constructor (adaptive Gauss-Legendre integration per
// segment); a query is a binary search in that table plus a few safeguarded Newton steps.
#include "core/math.h"

#include <cstddef>
#include <vector>

namespace glint {

class CatmullRomSpline {
public:
  // Throws glint::Error when fewer than 2 distinct points remain or a coordinate is not finite.
  // Consecutive (numerically) equal points are merged: their centripetal knot spacing would be 0.
  explicit CatmullRomSpline(std::vector<vec3> control_points);

  float length() const;
  // s is clamped to [0, length()].
  vec3 position_at_distance(float s) const;
  // u is a fraction of the arc length, clamped to [0, 1].
  vec3 position_at_fraction(float u) const;
  // Unit direction of travel at arc length s (clamped like position_at_distance).
  vec3 tangent_at_distance(float s) const;

  // The points the curve passes through, after merging consecutive duplicates.
  const std::vector<vec3>& control_points() const { return points_; }
  // Arc length at which the curve passes control_points()[i]; throws glint::Error when i is out of range.
  float distance_of_control_point(std::size_t i) const;

  // Double-precision forms of the queries, for callers that accumulate many small steps (and for
  // the float versions above, which forward here).
  glm::dvec3 position_at_distance_d(double s) const;
  glm::dvec3 tangent_at_distance_d(double s) const;
  double length_d() const { return total_length_; }

private:
  // One piece of the curve, p(u) = ((a u + b) u + c) u + d for u in [0, 1], from point i to i + 1.
  struct Segment {
    glm::dvec3 a, b, c, d;
    glm::dvec3 position(double u) const { return ((a * u + b) * u + c) * u + d; }
    glm::dvec3 derivative(double u) const { return (3.0 * a * u + 2.0 * b) * u + c; }
    double speed(double u) const { return glm::length(derivative(u)); }
  };
  // A sample of the arc-length table: the curve is at arc length `distance` at parameter `u` of
  // segment `segment`. Samples are sorted by distance; each segment starts with a u = 0 sample.
  struct ArcSample {
    double distance;
    double u;
    std::size_t segment;
  };

  void build_segments();
  void build_arc_length_table();
  // Maps an arc length to (segment, u): table lookup, then Newton's method within one table interval.
  void locate(double s, std::size_t& segment, double& u) const;

  std::vector<vec3> points_;
  std::vector<Segment> segments_;
  std::vector<ArcSample> table_;
  std::vector<double> point_distances_;  // arc length at each control point
  double total_length_ = 0.0;
};

}  // namespace glint
