#include "accel/builders/builder.h"
#include "accel/wide/wide_bvh_collapse.h"
#include "accel/wide/wide_bvh_trace.h"
#include "core/error.h"
#include "accel/brute_force_check.h"
#include "wide_bvh_test_support.h"

#include <gtest/gtest.h>

#include <span>
#include <string>
#include <tuple>

namespace glint::accel {
namespace {

using testing::TestMesh;
using testing::WideConfig;

// The closest and any hits of a wide BVH of either width.
testing::TraceClosestAndAny trace_with(const testing::AnyWideBvh& wide) {
  return [&wide](std::span<const Ray> rays, std::span<Hit> hits, std::span<uint8_t> occluded) {
    testing::trace_closest_any_width(wide, rays, hits);
    testing::trace_any_any_width(wide, rays, occluded);
  };
}

// builder, binary leaf size, width + SIMD path, merge small subtrees into one leaf or not.
using WideParam = std::tuple<BvhBuilder, uint32_t, WideConfig, bool>;

class WideTraversalMatchesBruteForce : public ::testing::TestWithParam<WideParam> {
protected:
  void check(const testing::BruteForceReference& reference, const testing::BruteForceExpectations& expectations) {
    const auto [builder, leaf_size, config, merge] = GetParam();
    if (config.path == WideSimdPath::avx2 && !cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this CPU";
    const testing::ScopedWidePath path(config);
    BuildOptions options;
    options.max_leaf_size = leaf_size;
    WideCollapseOptions collapse;
    if (!merge) collapse.merge_leaf_size = 0;
    const TriangleMesh mesh = reference.mesh.view();
    const Bvh bvh = build_bvh(builder, mesh, options);
    const testing::AnyWideBvh wide = testing::collapse_any(config.width, bvh, mesh, collapse);
    testing::expect_brute_force_answers(reference, trace_with(wide), expectations);
  }
};

TEST_P(WideTraversalMatchesBruteForce, RandomSoup) {
  check(testing::built_once([] { return testing::make_soup_reference(41, 3000, 12000); }), {.min_hit_fraction = 0.2});
}
TEST_P(WideTraversalMatchesBruteForce, Clustered) {
  check(testing::built_once([] { return testing::make_clustered_reference(43, 4000, 8000); }),
        {.min_hit_fraction = 0.2});
}
TEST_P(WideTraversalMatchesBruteForce, GridEdgesAndVerticesAreWatertight) {
  check(testing::built_once([] { return testing::make_grids_reference(24, 45); }),
        {.every_ray_hits = true, .min_hit_fraction = 0.2});
}
TEST_P(WideTraversalMatchesBruteForce, AxisParallelRays) {
  check(testing::built_once([] { return testing::make_axis_parallel_reference(47, 2000, 10000); }),
        {.min_hit_fraction = 0.2});
}
TEST_P(WideTraversalMatchesBruteForce, RayIntervals) {
  check(testing::built_once([] {
          testing::RayOptions options;
          options.limited_fraction = 1.0f;  // every ray a random [t_min, t_max] segment
          return testing::make_soup_reference(49, 2500, 10000, options);
        }),
        {.min_hit_fraction = 0.2});
}

std::vector<WideParam> wide_params() {
  std::vector<WideParam> params;
  for (const BvhBuilder builder : testing::collapsible_builders())
    for (const unsigned leaf_size : {1u, 4u, 8u})
      if (builder != BvhBuilder::none || leaf_size == 1u)
        for (const WideConfig& config : testing::all_wide_configs())
          for (const bool merge : {true, false}) params.emplace_back(builder, leaf_size, config, merge);
  return params;
}

INSTANTIATE_TEST_SUITE_P(Accel, WideTraversalMatchesBruteForce, ::testing::ValuesIn(wide_params()),
                         [](const ::testing::TestParamInfo<WideParam>& param_info) {
                           return std::string(builder_name(std::get<0>(param_info.param))) + "_leaf" +
                                  std::to_string(std::get<1>(param_info.param)) + "_" +
                                  std::get<2>(param_info.param).name() +
                                  (std::get<3>(param_info.param) ? "_merged" : "_binaryleaves");
                         });

class WideTraversal : public ::testing::TestWithParam<WideConfig> {
protected:
  void SetUp() override {
    if (GetParam().path == WideSimdPath::avx2 && !cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this CPU";
  }
};

TEST_P(WideTraversal, RayIntervalIsHonouredExactly) {
  const testing::ScopedWidePath path(GetParam());
  const TestMesh squares = testing::make_three_squares();
  const TriangleMesh view = squares.view();
  BuildOptions options;
  options.max_leaf_size = 1;
  WideCollapseOptions collapse;
  collapse.merge_leaf_size = 0;
  const testing::AnyWideBvh wide = testing::collapse_any(GetParam().width, build_bvh(BvhBuilder::sah, view, options),
                                                          view, collapse);
  testing::expect_ray_interval_honoured(trace_with(wide));
}

TEST_P(WideTraversal, MatchesTheBinaryTraversalOnALargeLeafOfTheNoneBuilder) {
  // The `none` builder's single leaf spans many blocks: block iteration and padding lanes.
  const testing::ScopedWidePath path(GetParam());
  const TestMesh soup = testing::make_random_soup(51, 203);  // not a multiple of 4 or 8
  const TriangleMesh view = soup.view();
  const testing::AnyWideBvh wide = testing::collapse_any(GetParam().width, build_bvh(BvhBuilder::none, view), view);
  const std::vector<Ray> rays = testing::make_random_rays(soup, 52, 4000);
  std::vector<Hit> hits(rays.size());
  testing::trace_closest_any_width(wide, rays, hits);
  size_t hit_count = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    ASSERT_TRUE(testing::same_closest_hit(testing::brute_force_closest(view, rays[i]), hits[i])) << i;
    hit_count += hits[i].valid() ? 1 : 0;
  }
  EXPECT_GT(hit_count, rays.size() / 5);
}

TEST_P(WideTraversal, EmptyBvhMissesEverything) {
  const testing::ScopedWidePath path(GetParam());
  const TestMesh empty;
  const TriangleMesh view = empty.view();
  const testing::AnyWideBvh wide = testing::collapse_any(GetParam().width, build_bvh(BvhBuilder::sah, view), view);
  const Ray ray;
  Hit hit;
  uint8_t occluded = 1;
  testing::trace_closest_any_width(wide, std::span(&ray, 1), std::span(&hit, 1));
  testing::trace_any_any_width(wide, std::span(&ray, 1), std::span(&occluded, 1));
  EXPECT_FALSE(hit.valid());
  EXPECT_EQ(occluded, 0);
}

TEST_P(WideTraversal, MismatchedSpansAreClearErrors) {
  const TestMesh soup = testing::make_random_soup(53, 50);
  const TriangleMesh view = soup.view();
  const testing::AnyWideBvh wide = testing::collapse_any(GetParam().width, build_bvh(BvhBuilder::sah, view), view);
  std::vector<Ray> rays(3);
  std::vector<Hit> hits(2);
  std::vector<uint8_t> occluded(4);
  EXPECT_THROW(testing::trace_closest_any_width(wide, rays, hits), Error);
  EXPECT_THROW(testing::trace_any_any_width(wide, rays, occluded), Error);
}

INSTANTIATE_TEST_SUITE_P(Accel, WideTraversal, ::testing::ValuesIn(testing::all_wide_configs()),
                         [](const ::testing::TestParamInfo<WideConfig>& param_info) {
                           return param_info.param.name();
                         });

TEST(WideSimdPathHook, ForcingAndRestoring) {
  force_wide_simd_path(WideSimdPath::sse);
  EXPECT_EQ(wide_simd_path(), WideSimdPath::sse);
  force_wide_simd_path(std::nullopt);
  EXPECT_EQ(wide_simd_path(), cpu_has_avx2() ? WideSimdPath::avx2 : WideSimdPath::sse);
  if (!cpu_has_avx2()) {
    EXPECT_THROW(force_wide_simd_path(WideSimdPath::avx2), Error);
  }
}

}  // namespace
}  // namespace glint::accel
