// The glossy sampler (render/glossy_sampling.h, the twin of shaders/include/glossy_sampling.glsl)
// against its density: a chi-square test over the sphere of directions, the density's own
// normalisation, the mirror case and the sequence.
#include "render/glossy_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace glint::render::glossy {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A frame of (cos theta, phi) bins over the whole sphere around the normal (0, 0, 1).
struct SphereBins {
  int cos_bins = 40;
  int phi_bins = 80;
  int index(const glm::dvec3& d) const {
    const double c = std::clamp(d.z, -1.0, 1.0);
    double phi = std::atan2(d.y, d.x);
    if (phi < 0.0) phi += 2.0 * kPi;
    const int i = std::min(static_cast<int>((c + 1.0) * 0.5 * cos_bins), cos_bins - 1);
    const int j = std::min(static_cast<int>(phi / (2.0 * kPi) * phi_bins), phi_bins - 1);
    return i * phi_bins + j;
  }
  // The density integrated over each bin (midpoint rule on 6 x 6 sub-cells; d omega = d cos d phi).
  template <typename Pdf>
  std::vector<double> expected(const Pdf& pdf) const {
    std::vector<double> p(static_cast<std::size_t>(cos_bins * phi_bins), 0.0);
    constexpr int kSub = 6;
    const double dc = 2.0 / (cos_bins * kSub), dphi = 2.0 * kPi / (phi_bins * kSub);
    for (int i = 0; i < cos_bins * kSub; ++i)
      for (int j = 0; j < phi_bins * kSub; ++j) {
        const double c = -1.0 + (i + 0.5) * dc, phi = (j + 0.5) * dphi;
        const double s = std::sqrt(std::max(1.0 - c * c, 0.0));
        p[static_cast<std::size_t>((i / kSub) * phi_bins + j / kSub)] +=
            pdf(glm::dvec3(s * std::cos(phi), s * std::sin(phi), c)) * dc * dphi;
      }
    return p;
  }
};

// Pearson's statistic over bins with >= 5 expected samples (the rest pooled) and its degrees of freedom.
struct ChiSquare {
  double statistic = 0.0;
  int dof = 0;
};
ChiSquare chi_square(const std::vector<double>& expected_fraction, const std::vector<int>& counts, int samples) {
  ChiSquare result;
  double pooled_expected = 0.0, pooled_observed = 0.0;
  int cells = 0;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    const double e = expected_fraction[k] * samples;
    if (e < 5.0) {
      pooled_expected += e;
      pooled_observed += counts[k];
      continue;
    }
    result.statistic += (counts[k] - e) * (counts[k] - e) / e;
    ++cells;
  }
  if (pooled_expected > 0.0) {
    result.statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++cells;
  }
  result.dof = cells - 1;
  return result;
}

// Upper 1e-3 quantile of chi-square with k degrees of freedom (Wilson-Hilferty).
double chi_square_critical(int k) {
  const double z = 3.0902;  // standard normal 0.999 quantile
  const double a = 2.0 / (9.0 * k);
  return k * std::pow(1.0 - a + z * std::sqrt(a), 3.0);
}

void expect_sampler_matches_pdf(const vec3& incident, float roughness, bool low_discrepancy) {
  const SphereBins bins;
  const vec3 normal(0.0f, 0.0f, 1.0f);
  const std::vector<double> expected = bins.expected([&](const glm::dvec3& l) {
    return reflection_pdf(glm::dvec3(incident), glm::dvec3(normal), roughness, l);
  });
  double total = 0.0;
  for (double p : expected) total += p;
  EXPECT_NEAR(total, 1.0, 2e-3) << "the density integrates to 1 over the sphere (roughness " << roughness << ")";

  constexpr int kSamples = 400000;
  std::vector<int> counts(expected.size(), 0);
  std::mt19937 random(1234u);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int s = 0; s < kSamples; ++s) {
    const vec2 u = low_discrepancy ? sample_point(glm::uvec2(3, 5), static_cast<std::uint32_t>(s))
                                   : vec2(uniform(random), uniform(random));
    const vec3 l = reflection_direction(incident, normal, roughness, u);
    ASSERT_NEAR(glm::length(l), 1.0f, 1e-4f);
    ++counts[static_cast<std::size_t>(bins.index(glm::dvec3(l)))];
  }
  const ChiSquare chi = chi_square(expected, counts, kSamples);
  EXPECT_LT(chi.statistic, chi_square_critical(chi.dof))
      << "roughness " << roughness << ", " << chi.dof << " degrees of freedom"
      << (low_discrepancy ? ", R2 sequence" : ", random points");
}

TEST(GlossySampling, VisibleNormalSamplerMatchesItsPdfChiSquare) {
  const vec3 head_on = glm::normalize(vec3(0.0f, 0.0f, -1.0f));
  const vec3 oblique = glm::normalize(vec3(0.8f, 0.1f, -0.6f));
  const vec3 grazing = glm::normalize(vec3(0.97f, -0.1f, -0.2f));
  for (float roughness : {0.3f, 0.6f, 1.0f}) expect_sampler_matches_pdf(oblique, roughness, false);
  expect_sampler_matches_pdf(head_on, 0.5f, false);
  expect_sampler_matches_pdf(grazing, 0.4f, false);
  expect_sampler_matches_pdf(oblique, 0.5f, true);  // the passes' own sequence
}

TEST(GlossySampling, RoughnessZeroIsTheMirrorBitForBitWithWeightOne) {
  std::mt19937 random(7u);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  for (int i = 0; i < 1000; ++i) {
    const vec3 incident = glm::normalize(vec3(uniform(random), uniform(random), uniform(random)));
    const vec3 normal = glm::normalize(vec3(uniform(random), uniform(random), uniform(random)));
    const vec2 u(0.5f * (uniform(random) + 1.0f), 0.5f * (uniform(random) + 1.0f));
    const vec3 mirror = glm::normalize(glm::reflect(incident, normal));
    const vec3 sampled = reflection_direction(incident, normal, 0.0f, u);
    EXPECT_EQ(sampled.x, mirror.x);
    EXPECT_EQ(sampled.y, mirror.y);
    EXPECT_EQ(sampled.z, mirror.z);
    EXPECT_EQ(reflection_weight(incident, normal, 0.0f, sampled), 1.0f);
  }
}

TEST(GlossySampling, DirectionsStayNearTheMirrorForSmallRoughnessAndSpreadWithIt) {
  const vec3 incident = glm::normalize(vec3(0.6f, 0.0f, -0.8f));
  const vec3 normal(0.0f, 0.0f, 1.0f);
  const vec3 mirror = glm::reflect(incident, normal);
  auto mean_cos = [&](float roughness) {
    double sum = 0.0;
    for (std::uint32_t s = 0; s < 4096; ++s)
      sum += glm::dot(reflection_direction(incident, normal, roughness, sample_point(glm::uvec2(1, 2), s)), mirror);
    return sum / 4096.0;
  };
  EXPECT_GT(mean_cos(0.05f), 0.999);
  EXPECT_GT(mean_cos(0.2f), mean_cos(0.5f));
  EXPECT_GT(mean_cos(0.5f), mean_cos(0.9f));
  // Either orientation of the normal gives the same directions.
  const vec2 u = sample_point(glm::uvec2(4, 9), 17u);
  const vec3 a = reflection_direction(incident, normal, 0.4f, u), b = reflection_direction(incident, -normal, 0.4f, u);
  EXPECT_NEAR(glm::distance(a, b), 0.0f, 1e-6f);
}

TEST(GlossySampling, WeightIsTheMaskingRatioAndZeroBelowTheSurface) {
  const vec3 incident = glm::normalize(vec3(0.6f, 0.0f, -0.8f));
  const vec3 normal(0.0f, 0.0f, 1.0f);
  EXPECT_EQ(reflection_weight(incident, normal, 0.5f, glm::normalize(vec3(1.0f, 0.0f, -0.1f))), 0.0f);
  const float w = reflection_weight(incident, normal, 0.5f, glm::reflect(incident, normal));
  EXPECT_GT(w, 0.9f);
  EXPECT_LE(w, 1.0f);
  EXPECT_LT(reflection_weight(incident, normal, 0.9f, glm::normalize(vec3(0.99f, 0.0f, 0.05f))), w)
      << "a grazing direction is masked more";
}

TEST(GlossySampling, SequenceIsInTheUnitSquareAndDiffersBetweenPixelsAndSamples) {
  double mean_x = 0.0, mean_y = 0.0;
  for (std::uint32_t s = 0; s < 1024; ++s) {
    const vec2 u = sample_point(glm::uvec2(10, 20), s);
    ASSERT_GE(u.x, 0.0f);
    ASSERT_LT(u.x, 1.0f);
    ASSERT_GE(u.y, 0.0f);
    ASSERT_LT(u.y, 1.0f);
    mean_x += u.x;
    mean_y += u.y;
  }
  EXPECT_NEAR(mean_x / 1024.0, 0.5, 0.01);
  EXPECT_NEAR(mean_y / 1024.0, 0.5, 0.01);
  EXPECT_NE(sample_point(glm::uvec2(10, 20), 0u), sample_point(glm::uvec2(11, 20), 0u));
  EXPECT_NE(sample_point(glm::uvec2(10, 20), 0u), sample_point(glm::uvec2(10, 20), 1u));
}

}  // namespace
}  // namespace glint::render::glossy
