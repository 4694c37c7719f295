#include "scene/spline.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace glint {
namespace {

// An independent Catmull-Rom evaluator (Barry-Goldman pyramid, a different formulation from the
// Hermite form the spline uses) with knot exponent `alpha`: 0 = uniform, 0.5 = centripetal. Same
// reflected phantom end points. Returns `per_segment` samples per segment, ends included.
std::vector<glm::dvec3> reference_curve(const std::vector<vec3>& points, double alpha, int per_segment) {
  const std::size_t n = points.size();
  std::vector<glm::dvec3> p;
  p.push_back(2.0 * glm::dvec3(points[0]) - glm::dvec3(points[1]));
  for (const vec3& q : points) p.emplace_back(q);
  p.push_back(2.0 * glm::dvec3(points[n - 1]) - glm::dvec3(points[n - 2]));
  auto lerp = [](const glm::dvec3& a, const glm::dvec3& b, double ta, double tb, double t) {
    return (tb - t) / (tb - ta) * a + (t - ta) / (tb - ta) * b;
  };
  std::vector<glm::dvec3> out;
  for (std::size_t s = 0; s + 1 < n; ++s) {
    const glm::dvec3 &p0 = p[s], &p1 = p[s + 1], &p2 = p[s + 2], &p3 = p[s + 3];
    const double t0 = 0.0, t1 = t0 + std::pow(glm::distance(p0, p1), alpha), t2 = t1 + std::pow(glm::distance(p1, p2), alpha),
                 t3 = t2 + std::pow(glm::distance(p2, p3), alpha);
    for (int k = (s == 0 ? 0 : 1); k <= per_segment; ++k) {
      const double t = t1 + (t2 - t1) * k / per_segment;
      const glm::dvec3 a1 = lerp(p0, p1, t0, t1, t), a2 = lerp(p1, p2, t1, t2, t), a3 = lerp(p2, p3, t2, t3, t);
      const glm::dvec3 b1 = lerp(a1, a2, t0, t2, t), b2 = lerp(a2, a3, t1, t3, t);
      out.push_back(lerp(b1, b2, t1, t2, t));
    }
  }
  return out;
}

double polyline_length(const std::vector<glm::dvec3>& samples) {
  double sum = 0.0;
  for (std::size_t i = 1; i < samples.size(); ++i) sum += glm::distance(samples[i - 1], samples[i]);
  return sum;
}

// Number of crossings between non-adjacent segments of a polyline in the xy plane.
int self_intersections_xy(const std::vector<glm::dvec3>& c) {
  auto orient = [](const glm::dvec3& o, const glm::dvec3& a, const glm::dvec3& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  int count = 0;
  for (std::size_t i = 0; i + 1 < c.size(); ++i)
    for (std::size_t j = i + 2; j + 1 < c.size(); ++j)
      if (orient(c[i], c[i + 1], c[j]) * orient(c[i], c[i + 1], c[j + 1]) < 0.0 &&
          orient(c[j], c[j + 1], c[i]) * orient(c[j], c[j + 1], c[i + 1]) < 0.0)
        ++count;
  return count;
}

std::vector<glm::dvec3> sample_by_fraction(const CatmullRomSpline& spline, int count) {
  std::vector<glm::dvec3> out;
  for (int i = 0; i < count; ++i) out.emplace_back(spline.position_at_distance_d(spline.length_d() * i / (count - 1)));
  return out;
}

// (max - min) / mean of the distances between consecutive samples at fractions f / (frames - 1).
double step_spread(const CatmullRomSpline& spline, int frames) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0, sum = 0.0;
  vec3 previous = spline.position_at_fraction(0.0f);
  for (int f = 1; f < frames; ++f) {
    const vec3 current = spline.position_at_fraction(static_cast<float>(f) / static_cast<float>(frames - 1));
    const double step = glm::distance(previous, current);
    lo = std::min(lo, step);
    hi = std::max(hi, step);
    sum += step;
    previous = current;
  }
  return (hi - lo) / (sum / (frames - 1));
}

// An S through irregularly spaced points, in 3D (it climbs a little).
const std::vector<vec3> kSPath = {{0, 0, 0},    {1, 0.2f, 0.5f}, {4, 0.5f, 3}, {4.5f, 0.6f, 6}, {3, 0.8f, 7.5f},
                                  {1, 1, 9},    {0.5f, 1, 12},   {2, 1.2f, 15}, {6, 1.5f, 15.5f}};

TEST(CatmullRomSpline, PassesThroughEveryControlPointWithIrregularSpacingAndSharpTurns) {
  const std::vector<vec3> points = {{0, 0, 0}, {10, 0, 0}, {10.1f, 0, 0.05f}, {0, 2, 1}, {0.3f, 2, 1.2f},
                                    {8, -3, 7}, {8, -3, 7.01f}, {-5, 4, -2}};
  const CatmullRomSpline spline(points);
  ASSERT_EQ(spline.control_points().size(), points.size());
  Aabb box;
  for (const vec3& p : points) box.extend(p);
  const float tolerance = 1e-4f * glm::length(box.extent());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_LE(glm::distance(spline.position_at_distance(spline.distance_of_control_point(i)), points[i]), tolerance)
        << "control point " << i;
    if (i > 0) {
      EXPECT_GT(spline.distance_of_control_point(i), spline.distance_of_control_point(i - 1));
    }
  }
  EXPECT_EQ(spline.distance_of_control_point(0), 0.0f);
  EXPECT_EQ(spline.distance_of_control_point(points.size() - 1), spline.length());
  EXPECT_EQ(spline.position_at_fraction(0.0f), points.front());
  EXPECT_EQ(spline.position_at_fraction(1.0f), points.back());
}

TEST(CatmullRomSpline, IsTheCentripetalCatmullRomCurveAtTheRightArcLength) {
  // Our point at the reference's polyline length must be the reference's point: checks both the
  // curve's shape (against an independent formulation) and the arc-length mapping.
  const std::vector<glm::dvec3> reference = reference_curve(kSPath, 0.5, 4000);
  const CatmullRomSpline spline(kSPath);
  double walked = 0.0;
  double worst = 0.0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    if (i > 0) walked += glm::distance(reference[i - 1], reference[i]);
    if (i % 97 == 0) worst = std::max(worst, glm::distance(spline.position_at_distance_d(walked), reference[i]));
  }
  EXPECT_LT(worst, 1e-5 * spline.length_d());
}

TEST(CatmullRomSpline, LengthMatchesAFinePolylineSum) {
  for (const auto& points : {kSPath, std::vector<vec3>{{0, 0, 0}, {20, 0, 0}, {20.05f, 0, 0.02f}, {20, 0, 20}}}) {
    const CatmullRomSpline spline(points);
    const double brute_force = polyline_length(reference_curve(points, 0.5, 20000));
    EXPECT_NEAR(spline.length_d(), brute_force, 1e-3 * brute_force);
    EXPECT_NEAR(spline.length_d(), polyline_length(sample_by_fraction(spline, 100000)), 1e-3 * brute_force);
  }
}

TEST(CatmullRomSpline, EqualFractionStepsAreEqualDistancesOnAnIrregularSPath) {
  const CatmullRomSpline spline(kSPath);
  EXPECT_LT(step_spread(spline, 4900), 0.01);
}

TEST(CatmullRomSpline, EqualFractionStepsAreEqualDistancesWithAVeryShortSegmentNextToALongOne) {
  // A 0.2 segment between 20- and 10-unit ones: a chord- or uniform-parametrized curve would crawl
  // through it. The turn there is kept wider than a frame step, because on a hairpin tighter than
  // one step the chord between two frames is shorter than the arc, whatever the parametrization.
  const CatmullRomSpline spline({{0, 0, 0}, {20, 0, 0}, {20.2f, 0, 0.05f}, {24, 0, 10}, {10, 1, 22}});
  EXPECT_LT(step_spread(spline, 4900), 0.01);
}

TEST(CatmullRomSpline, HasNoLoopAtAHairpinWhereTheUniformParametrizationLoops) {
  // A long segment, a short sharp turn, a long way back: the classic configuration where uniform
  // Catmull-Rom's large tangents tie a loop into the short segment.
  const std::vector<vec3> hairpin = {{0, 0, 0}, {10, 0, 0}, {9.5f, 0.2f, 0}, {2, 2, 0}};
  ASSERT_GT(self_intersections_xy(reference_curve(hairpin, 0.0, 600)), 0) << "the configuration must trap uniform CR";
  const CatmullRomSpline spline(hairpin);
  EXPECT_EQ(self_intersections_xy(sample_by_fraction(spline, 1800)), 0);
}

TEST(CatmullRomSpline, DoesNotOvershootAShortSegmentBetweenLongOnes) {
  // Uniform Catmull-Rom swings out to x = 11.25 on the 1-unit segment from (10,0) to (10,1);
  // centripetal stays within a quarter of that segment's length.
  const std::vector<vec3> points = {{0, 0, 0}, {10, 0, 0}, {10, 1, 0}, {0, 1, 0}};
  double uniform_max_x = 0.0;
  for (const glm::dvec3& p : reference_curve(points, 0.0, 2000)) uniform_max_x = std::max(uniform_max_x, p.x);
  ASSERT_GT(uniform_max_x, 11.0);
  double max_x = 0.0;
  for (const glm::dvec3& p : sample_by_fraction(CatmullRomSpline(points), 5000)) max_x = std::max(max_x, p.x);
  EXPECT_LE(max_x, 10.25);
}

TEST(CatmullRomSpline, TangentIsUnitAndAlongTheDirectionOfTravel) {
  const CatmullRomSpline spline(kSPath);
  const float h = 1e-3f * spline.length();
  for (int i = 1; i < 50; ++i) {
    const float s = spline.length() * static_cast<float>(i) / 50.0f;
    const vec3 tangent = spline.tangent_at_distance(s);
    EXPECT_NEAR(glm::length(tangent), 1.0f, 1e-5f);
    const vec3 secant = glm::normalize(spline.position_at_distance(s + h) - spline.position_at_distance(s - h));
    EXPECT_GT(glm::dot(tangent, secant), 0.9999f) << "at s = " << s;
  }
  // At the ends the phantom points make the curve head straight at its neighbour.
  EXPECT_GT(glm::dot(spline.tangent_at_distance(0.0f), glm::normalize(kSPath[1] - kSPath[0])), 0.999f);
}

TEST(CatmullRomSpline, TwoPointsGiveAStraightLine) {
  const CatmullRomSpline spline({{1, 2, 3}, {5, 2, 6}});
  EXPECT_NEAR(spline.length(), 5.0f, 1e-5f);
  const vec3 quarter = spline.position_at_fraction(0.25f);
  EXPECT_NEAR(glm::distance(quarter, vec3(2, 2, 3.75f)), 0.0f, 1e-5f);
}

TEST(CatmullRomSpline, ClampsDistancesAndFractions) {
  const CatmullRomSpline spline(kSPath);
  EXPECT_EQ(spline.position_at_distance(-3.0f), kSPath.front());
  EXPECT_EQ(spline.position_at_distance(spline.length() + 10.0f), kSPath.back());
  EXPECT_EQ(spline.position_at_fraction(-0.5f), kSPath.front());
  EXPECT_EQ(spline.position_at_fraction(1.5f), kSPath.back());
}

TEST(CatmullRomSpline, MergesConsecutiveDuplicatePoints) {
  const CatmullRomSpline spline({{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}});
  ASSERT_EQ(spline.control_points().size(), 4u);
  EXPECT_EQ(spline.control_points()[1], vec3(1, 0, 0));
  EXPECT_TRUE(std::isfinite(spline.length()));
  for (int i = 0; i <= 20; ++i) EXPECT_TRUE(is_finite(spline.position_at_fraction(static_cast<float>(i) / 20.0f)));
  EXPECT_LE(glm::distance(spline.position_at_distance(spline.distance_of_control_point(2)), vec3(1, 1, 0)), 1e-5f);
}

TEST(CatmullRomSpline, RejectsTooFewOrNonFinitePoints) {
  EXPECT_THROW(CatmullRomSpline({}), Error);
  EXPECT_THROW(CatmullRomSpline({vec3(1, 2, 3)}), Error);
  EXPECT_THROW(CatmullRomSpline({vec3(1, 2, 3), vec3(1, 2, 3)}), Error);  // one distinct point
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(CatmullRomSpline({vec3(0, 0, 0), vec3(nan, 0, 0), vec3(1, 0, 0)}), Error);
  EXPECT_THROW(CatmullRomSpline({vec3(0, 0, 0), vec3(std::numeric_limits<float>::infinity(), 0, 0)}), Error);
  const CatmullRomSpline spline({{0, 0, 0}, {1, 0, 0}});
  EXPECT_THROW((void)spline.distance_of_control_point(2), Error);
}

}  // namespace
}  // namespace glint
