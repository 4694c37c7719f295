#include "scene/spline.h"

#include "core/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace glint {
namespace {

// 5-point Gauss-Legendre rule on [-1, 1]: exact for polynomials of degree 9, so on the smooth speed
// of a cubic it is accurate to ~1e-12 after a few subdivisions.
constexpr std::array<double, 5> kGaussNodes = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                               0.9061798459386640};
constexpr std::array<double, 5> kGaussWeights = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                                 0.4786286704993665, 0.2369268850561891};

// Every segment is split at least this often, so that Newton's method starts near the answer.
constexpr int kMinSubdivisionDepth = 3;  // 8 intervals
constexpr int kMaxSubdivisionDepth = 24;
// Relative tolerance of the adaptive integration (per interval, against the segment's length).
constexpr double kIntegrationTolerance = 1e-11;
// Points closer than this fraction of the path's extent are treated as the same point.
constexpr double kMergeTolerance = 1e-6;

template <typename SpeedFn>
double gauss_legendre(const SpeedFn& speed, double u0, double u1) {
  const double half = 0.5 * (u1 - u0), mid = 0.5 * (u0 + u1);
  double sum = 0.0;
  for (std::size_t k = 0; k < kGaussNodes.size(); ++k) sum += kGaussWeights[k] * speed(mid + half * kGaussNodes[k]);
  return sum * half;
}

glm::dvec3 to_double(const vec3& v) { return glm::dvec3(v); }

std::vector<vec3> merge_consecutive_duplicates(const std::vector<vec3>& points) {
  Aabb box;
  for (const vec3& p : points) box.extend(p);
  const double scale = glm::length(glm::dvec3(box.extent()));
  std::vector<vec3> merged;
  merged.reserve(points.size());
  for (const vec3& p : points) {
    if (!merged.empty() && glm::distance(to_double(merged.back()), to_double(p)) <= kMergeTolerance * scale) continue;
    merged.push_back(p);
  }
  return merged;
}

}  // namespace

CatmullRomSpline::CatmullRomSpline(std::vector<vec3> control_points) {
  if (control_points.size() < 2)
    fail("spline: needs at least 2 control points, got {}", control_points.size());
  for (std::size_t i = 0; i < control_points.size(); ++i) {
    const vec3& p = control_points[i];
    if (!is_finite(p)) fail("spline: control point {} is not finite ({}, {}, {})", i, p.x, p.y, p.z);
  }
  points_ = merge_consecutive_duplicates(control_points);
  if (points_.size() < 2)
    fail("spline: needs at least 2 distinct control points, got {} points that all coincide", control_points.size());
  build_segments();
  build_arc_length_table();
}

void CatmullRomSpline::build_segments() {
  const std::size_t n = points_.size();
  // Phantom end points, reflected through the first and last point, so that the curve starts and
  // ends exactly at them and heads straight at its neighbour there.
  auto point = [&](std::ptrdiff_t i) -> glm::dvec3 {
    if (i < 0) return 2.0 * to_double(points_[0]) - to_double(points_[1]);
    if (i >= static_cast<std::ptrdiff_t>(n)) return 2.0 * to_double(points_[n - 1]) - to_double(points_[n - 2]);
    return to_double(points_[static_cast<std::size_t>(i)]);
  };
  segments_.clear();
  segments_.reserve(n - 1);
  for (std::size_t s = 0; s + 1 < n; ++s) {
    const auto i = static_cast<std::ptrdiff_t>(s);
    const glm::dvec3 p0 = point(i - 1), p1 = point(i), p2 = point(i + 1), p3 = point(i + 2);
    // Centripetal knot spacing: sqrt of the chord length (alpha = 0.5). Consecutive points are
    // distinct after merging, and the phantoms differ from their neighbours, so no spacing is 0.
    const double dt0 = std::sqrt(glm::distance(p0, p1));
    const double dt1 = std::sqrt(glm::distance(p1, p2));
    const double dt2 = std::sqrt(glm::distance(p2, p3));
    // Tangents of the non-uniform Catmull-Rom curve (Barry-Goldman), scaled to u in [0, 1] over
    // this segment, then the cubic Hermite curve written in power form.
    const glm::dvec3 m1 = dt1 * ((p1 - p0) / dt0 - (p2 - p0) / (dt0 + dt1) + (p2 - p1) / dt1);
    const glm::dvec3 m2 = dt1 * ((p2 - p1) / dt1 - (p3 - p1) / (dt1 + dt2) + (p3 - p2) / dt2);
    Segment seg;
    seg.a = 2.0 * p1 - 2.0 * p2 + m1 + m2;
    seg.b = -3.0 * p1 + 3.0 * p2 - 2.0 * m1 - m2;
    seg.c = m1;
    seg.d = p1;
    segments_.push_back(seg);
  }
}

void CatmullRomSpline::build_arc_length_table() {
  table_.clear();
  point_distances_.assign(points_.size(), 0.0);
  double distance = 0.0;
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const Segment& seg = segments_[s];
    auto speed = [&seg](double u) { return seg.speed(u); };
    point_distances_[s] = distance;
    // The chord is a lower bound of the segment's length: a scale for the tolerance.
    const double chord = glm::distance(seg.position(0.0), seg.position(1.0));
    const double tolerance = kIntegrationTolerance * chord;
    // Adaptive bisection: an interval is accepted when splitting it no longer changes its integral.
    // Intervals are visited left to right (explicit stack, right half pushed first), so the table
    // comes out sorted.
    struct Interval {
      double u0, u1, length;
      int depth;
    };
    std::vector<Interval> stack{{0.0, 1.0, gauss_legendre(speed, 0.0, 1.0), 0}};
    while (!stack.empty()) {
      const Interval in = stack.back();
      stack.pop_back();
      const double mid = 0.5 * (in.u0 + in.u1);
      const double left = gauss_legendre(speed, in.u0, mid), right = gauss_legendre(speed, mid, in.u1);
      const bool converged = std::abs(left + right - in.length) <= tolerance;
      if ((converged && in.depth >= kMinSubdivisionDepth) || in.depth >= kMaxSubdivisionDepth) {
        table_.push_back({distance, in.u0, s});
        distance += left + right;
      } else {
        stack.push_back({mid, in.u1, right, in.depth + 1});
        stack.push_back({in.u0, mid, left, in.depth + 1});
      }
    }
  }
  point_distances_.back() = distance;
  total_length_ = distance;
  // Closing sample: the end of the last segment.
  table_.push_back({distance, 1.0, segments_.size() - 1});
}

void CatmullRomSpline::locate(double s, std::size_t& segment, double& u) const {
  // The last sample whose distance is <= s; s < total_length_ here, so it is never the closing one.
  auto next = std::upper_bound(table_.begin(), table_.end(), s,
                               [](double value, const ArcSample& sample) { return value < sample.distance; });
  const ArcSample& start = *(next - 1);
  segment = start.segment;
  const Segment& seg = segments_[segment];
  // The interval ends at the next sample, or at u = 1 when that sample starts the next segment.
  const double u_end = next->segment == segment ? next->u : 1.0;
  const double target = s - start.distance;
  const double span = next->distance - start.distance;
  auto speed = [&seg](double x) { return seg.speed(x); };

  // Newton's method on F(u) = length(start.u .. u) - target, kept inside a shrinking bracket and
  // falling back to bisection whenever a step would leave it (or the speed vanishes).
  double lo = start.u, hi = u_end;
  u = span > 0.0 ? start.u + (u_end - start.u) * (target / span) : start.u;
  for (int iteration = 0; iteration < 40; ++iteration) {
    const double f = gauss_legendre(speed, start.u, u) - target;
    if (std::abs(f) <= 1e-13 * std::max(total_length_, 1e-30)) break;
    if (f > 0.0)
      hi = u;
    else
      lo = u;
    const double derivative = seg.speed(u);
    const double newton = derivative > 0.0 ? u - f / derivative : lo;  // lo: rejected just below
    const double candidate = (newton > lo && newton < hi) ? newton : 0.5 * (lo + hi);
    if (candidate == u) break;
    u = candidate;
  }
}

glm::dvec3 CatmullRomSpline::position_at_distance_d(double s) const {
  if (!(s > 0.0)) return to_double(points_.front());  // also catches NaN
  if (s >= total_length_) return to_double(points_.back());
  std::size_t segment = 0;
  double u = 0.0;
  locate(s, segment, u);
  return segments_[segment].position(u);
}

glm::dvec3 CatmullRomSpline::tangent_at_distance_d(double s) const {
  std::size_t segment = 0;
  double u = 0.0;
  if (!(s > 0.0)) {
    // The start: segment 0 at u = 0, as initialized.
  } else if (s >= total_length_) {
    segment = segments_.size() - 1;
    u = 1.0;
  } else {
    locate(s, segment, u);
  }
  const glm::dvec3 derivative = segments_[segment].derivative(u);
  const double speed = glm::length(derivative);
  if (speed > 0.0 && std::isfinite(speed)) return derivative / speed;
  // A centripetal segment has no cusps, so this is only reachable through rounding; the chord is
  // the best direction then.
  return glm::normalize(to_double(points_[segment + 1]) - to_double(points_[segment]));
}

float CatmullRomSpline::length() const { return static_cast<float>(total_length_); }

vec3 CatmullRomSpline::position_at_distance(float s) const { return vec3(position_at_distance_d(double(s))); }

vec3 CatmullRomSpline::position_at_fraction(float u) const {
  const double clamped = std::clamp(double(u), 0.0, 1.0);
  return vec3(position_at_distance_d(clamped * total_length_));
}

vec3 CatmullRomSpline::tangent_at_distance(float s) const { return vec3(tangent_at_distance_d(double(s))); }

float CatmullRomSpline::distance_of_control_point(std::size_t i) const {
  if (i >= points_.size()) fail("spline: control point {} out of range (the spline has {})", i, points_.size());
  return static_cast<float>(point_distances_[i]);
}

}  // namespace glint
