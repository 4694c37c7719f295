#include "accel/builders/builder.h"
#include "accel/trace.h"
#include "core/error.h"
#include "accel/brute_force_check.h"

#include <gtest/gtest.h>

#include <span>
#include <string>
#include <tuple>

namespace glint::accel {
namespace {

using testing::TestMesh;

using TraceParam = std::tuple<BvhBuilder, uint32_t>;

class TraversalMatchesBruteForce : public ::testing::TestWithParam<TraceParam> {
protected:
  void check(const testing::BruteForceReference& reference, const testing::BruteForceExpectations& expectations) {
    const auto [builder, leaf_size] = GetParam();
    BuildOptions options;
    options.max_leaf_size = leaf_size;
    const TriangleMesh mesh = reference.mesh.view();
    const Bvh bvh = build_bvh(builder, mesh, options);
    testing::expect_brute_force_answers(
        reference,
        [&](std::span<const Ray> rays, std::span<Hit> hits, std::span<uint8_t> occluded) {
          trace_closest(bvh, mesh, rays, hits);
          trace_any(bvh, mesh, rays, occluded);
        },
        expectations);
  }
};

TEST_P(TraversalMatchesBruteForce, RandomSoup) {
  check(testing::built_once([] { return testing::make_soup_reference(21, 3000, 12000); }), {});
}
TEST_P(TraversalMatchesBruteForce, GridEdgesAndVerticesAreWatertight) {
  check(testing::built_once([] { return testing::make_grids_reference(24, 23); }), {.every_ray_hits = true});
}
TEST_P(TraversalMatchesBruteForce, AxisParallelRays) {
  check(testing::built_once([] { return testing::make_axis_parallel_reference(25, 2000, 10000); }), {});
}

// Every builder at every leaf size, except brute force, whose single leaf ignores the leaf size.
std::vector<TraceParam> trace_params() {
  std::vector<TraceParam> params;
  for (const BvhBuilder builder : kAllBvhBuilders)
    for (const unsigned leaf_size : {1u, 4u, 8u})
      if (builder != BvhBuilder::none || leaf_size == 1u) params.emplace_back(builder, leaf_size);
  return params;
}

INSTANTIATE_TEST_SUITE_P(Accel, TraversalMatchesBruteForce, ::testing::ValuesIn(trace_params()),
                         [](const ::testing::TestParamInfo<TraceParam>& param_info) {
                           return std::string(builder_name(std::get<0>(param_info.param))) + "_leaf" +
                                  std::to_string(std::get<1>(param_info.param));
                         });

TEST(Traversal, RayIntervalIsHonoured) {
  const TestMesh squares = testing::make_three_squares();
  const TriangleMesh view = squares.view();
  BuildOptions options;
  options.max_leaf_size = 1;
  const Bvh bvh = build_bvh(BvhBuilder::sah, view, options);
  testing::expect_ray_interval_honoured([&](std::span<const Ray> rays, std::span<Hit> hits, std::span<uint8_t> occluded) {
    trace_closest(bvh, view, rays, hits);
    trace_any(bvh, view, rays, occluded);
  });
}

TEST(Traversal, HitReportsOriginalTriangleIndexAndInstanceZero) {
  const TestMesh soup = testing::make_random_soup(31, 500);
  const TriangleMesh view = soup.view();
  const Bvh bvh = build_bvh(BvhBuilder::sah, view);
  const std::vector<Ray> rays = testing::make_random_rays(soup, 32, 1000);
  std::vector<Hit> hits(rays.size());
  trace_closest(bvh, view, rays, hits);
  for (const Hit& hit : hits) {
    if (!hit.valid()) {
      EXPECT_EQ(hit.t, kInfinity);
      EXPECT_EQ(hit.instance, Hit::kInvalidIndex);
      continue;
    }
    EXPECT_EQ(hit.instance, 0u);
    EXPECT_LT(hit.prim, view.triangle_count);
  }
}

TEST(Traversal, PreGatheredSoupGivesTheSameHitsAsIndexed) {
  const TestMesh indexed = testing::make_random_soup(35, 1500);
  std::vector<vec3> gathered;
  for (uint32_t index : indexed.indices) gathered.push_back(indexed.positions[index]);
  const TriangleMesh soup = make_triangle_soup(gathered);
  ASSERT_EQ(soup.triangle_count, indexed.triangle_count());
  const Bvh bvh = build_bvh(BvhBuilder::sah, soup);
  const std::vector<Ray> rays = testing::make_random_rays(indexed, 36, 10000);
  std::vector<Hit> hits(rays.size());
  trace_closest(bvh, soup, rays, hits);
  const TriangleMesh indexed_view = indexed.view();
  for (size_t i = 0; i < rays.size(); ++i)
    ASSERT_TRUE(testing::same_closest_hit(testing::brute_force_closest(indexed_view, rays[i]), hits[i])) << i;
  EXPECT_THROW(make_triangle_soup(std::span(gathered).first(4)), Error);
}

TEST(Traversal, EmptyBvhMissesEverything) {
  const TestMesh empty;
  const TriangleMesh view = empty.view();
  const Bvh bvh = build_bvh(BvhBuilder::sah, view);
  const Ray ray;
  Hit hit;
  trace_closest(bvh, view, std::span(&ray, 1), std::span(&hit, 1));
  EXPECT_FALSE(hit.valid());
}

TEST(Traversal, MismatchedInputsAreClearErrors) {
  const TestMesh soup = testing::make_random_soup(33, 50);
  const TestMesh other = testing::make_random_soup(34, 60);
  const Bvh bvh = build_bvh(BvhBuilder::median, soup.view());
  std::vector<Ray> rays(3);
  std::vector<Hit> hits(2);
  EXPECT_THROW(trace_closest(bvh, soup.view(), rays, hits), Error);
  hits.resize(3);
  EXPECT_THROW(trace_closest(bvh, other.view(), rays, hits), Error);
  EXPECT_NO_THROW(trace_closest(bvh, soup.view(), rays, hits));
}

}  // namespace
}  // namespace glint::accel
