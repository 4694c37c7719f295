#include "accel/builders/builder.h"
#include "accel/wide/wide_bvh_collapse.h"
#include "accel/wide/wide_bvh_trace.h"
#include "core/error.h"
#include "accel/test_scenes.h"
#include "wide_bvh_test_support.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>

namespace glint::accel {
namespace {

using testing::TestMesh;
using testing::WideConfig;

using WideReference = testing::BruteForceReference;

const WideReference& soup_reference() {
  static const WideReference reference = [] {
    TestMesh soup = testing::make_random_soup(41, 3000);
    std::vector<Ray> rays = testing::make_random_rays(soup, 42, 12000);
    return WideReference(std::move(soup), std::move(rays));
  }();
  return reference;
}

const WideReference& clustered_reference() {
  static const WideReference reference = [] {
    TestMesh clustered = testing::make_clustered(43, 4000);
    std::vector<Ray> rays = testing::make_random_rays(clustered, 44, 8000);
    return WideReference(std::move(clustered), std::move(rays));
  }();
  return reference;
}

const WideReference& grid_reference() {
  static const WideReference reference = [] {
    testing::StackedGrids grids = testing::make_stacked_grids(24, 45, 46);
    return WideReference(std::move(grids.mesh), std::move(grids.rays));
  }();
  return reference;
}

const WideReference& axis_reference() {
  static const WideReference reference = [] {
    TestMesh soup = testing::make_random_soup(47, 2000);
    std::vector<Ray> rays = testing::make_axis_parallel_rays(soup, 48, 10000);
    return WideReference(std::move(soup), std::move(rays));
  }();
  return reference;
}

const WideReference& interval_reference() {
  static const WideReference reference = [] {
    TestMesh soup = testing::make_random_soup(49, 2500);
    testing::RayOptions options;
    options.limited_fraction = 1.0f;  // every ray a random [t_min, t_max] segment
    std::vector<Ray> rays = testing::make_random_rays(soup, 50, 10000, options);
    return WideReference(std::move(soup), std::move(rays));
  }();
  return reference;
}

// builder, binary leaf size, width + SIMD path, merge small subtrees into one leaf or not.
using WideParam = std::tuple<BvhBuilder, uint32_t, WideConfig, bool>;

class WideTraversalMatchesBruteForce : public ::testing::TestWithParam<WideParam> {
protected:
  void check(const WideReference& reference, bool expect_all_hit) {
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
    std::vector<Hit> hits(reference.rays.size());
    std::vector<uint8_t> occluded(reference.rays.size());
    testing::trace_closest_any_width(wide, reference.rays, hits);
    testing::trace_any_any_width(wide, reference.rays, occluded);
    size_t failures = 0, hit_count = 0;
    for (size_t i = 0; i < reference.rays.size() && failures < 10; ++i) {
      const auto same = testing::same_closest_hit(reference.closest[i], hits[i]);
      EXPECT_TRUE(same) << "ray " << i;
      EXPECT_EQ(occluded[i], reference.occluded[i]) << "ray " << i;
      // Any-hit agrees with closest-hit.
      EXPECT_EQ(occluded[i] != 0, hits[i].valid()) << "ray " << i;
      if (hits[i].valid()) {
        EXPECT_EQ(hits[i].instance, 0u);
      }
      if (expect_all_hit) {
        EXPECT_TRUE(hits[i].valid()) << "ray " << i << " slipped through";
      }
      failures += same && occluded[i] == reference.occluded[i] ? 0 : 1;
      hit_count += hits[i].valid() ? 1 : 0;
    }
    EXPECT_GT(hit_count, reference.rays.size() / 5);  // the rays do test something
  }
};

TEST_P(WideTraversalMatchesBruteForce, RandomSoup) { check(soup_reference(), false); }
TEST_P(WideTraversalMatchesBruteForce, Clustered) { check(clustered_reference(), false); }
TEST_P(WideTraversalMatchesBruteForce, GridEdgesAndVerticesAreWatertight) { check(grid_reference(), true); }
TEST_P(WideTraversalMatchesBruteForce, AxisParallelRays) { check(axis_reference(), false); }
TEST_P(WideTraversalMatchesBruteForce, RayIntervals) { check(interval_reference(), false); }

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
  // Three parallel squares at z = 1, 2, 3, ray down the z axis.
  TestMesh mesh;
  for (float z : {1.0f, 2.0f, 3.0f}) {
    mesh.add_triangle(vec3(-1, -1, z), vec3(1, -1, z), vec3(1, 1, z));
    mesh.add_triangle(vec3(-1, -1, z), vec3(1, 1, z), vec3(-1, 1, z));
  }
  const TriangleMesh view = mesh.view();
  BuildOptions options;
  options.max_leaf_size = 1;
  WideCollapseOptions collapse;
  collapse.merge_leaf_size = 0;
  const testing::AnyWideBvh wide = testing::collapse_any(GetParam().width, build_bvh(BvhBuilder::sah, view, options),
                                                          view, collapse);
  const auto closest_t = [&](float t_min, float t_max) {
    const Ray ray{vec3(0.25f, 0.5f, 0.0f), t_min, vec3(0, 0, 1), t_max};
    Hit hit;
    testing::trace_closest_any_width(wide, std::span(&ray, 1), std::span(&hit, 1));
    uint8_t occluded = 0;
    testing::trace_any_any_width(wide, std::span(&ray, 1), std::span(&occluded, 1));
    EXPECT_EQ(occluded != 0, hit.valid());
    return hit.valid() ? hit.t : -1.0f;
  };
  EXPECT_EQ(closest_t(0.0f, kInfinity), 1.0f);
  EXPECT_EQ(closest_t(1.5f, kInfinity), 2.0f);
  EXPECT_EQ(closest_t(2.0f, kInfinity), 2.0f);  // t_min inclusive
  EXPECT_EQ(closest_t(2.5f, 2.9f), -1.0f);
  EXPECT_EQ(closest_t(2.5f, 3.0f), 3.0f);       // t_max inclusive
  EXPECT_EQ(closest_t(3.5f, kInfinity), -1.0f);
  EXPECT_EQ(closest_t(0.0f, 0.5f), -1.0f);
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
