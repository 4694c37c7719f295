#include "accel/builders/builder.h"
#include "accel/trace.h"
#include "core/error.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>

namespace glint::accel {
namespace {

using testing::TestMesh;

using Reference = testing::BruteForceReference;

const Reference& soup_reference() {
  static const Reference reference = [] {
    TestMesh soup = testing::make_random_soup(21, 3000);
    std::vector<Ray> rays = testing::make_random_rays(soup, 22, 12000);
    return Reference(std::move(soup), std::move(rays));
  }();
  return reference;
}

const Reference& grid_reference() {
  static const Reference reference = [] {
    testing::StackedGrids grids = testing::make_stacked_grids(24, 23, 24);
    return Reference(std::move(grids.mesh), std::move(grids.rays));
  }();
  return reference;
}

const Reference& axis_reference() {
  static const Reference reference = [] {
    TestMesh soup = testing::make_random_soup(25, 2000);
    std::vector<Ray> rays = testing::make_axis_parallel_rays(soup, 26, 10000);
    return Reference(std::move(soup), std::move(rays));
  }();
  return reference;
}

using TraceParam = std::tuple<BvhBuilder, uint32_t>;

class TraversalMatchesBruteForce : public ::testing::TestWithParam<TraceParam> {
protected:
  void check(const Reference& reference, bool expect_all_hit) {
    const auto [builder, leaf_size] = GetParam();
    BuildOptions options;
    options.max_leaf_size = leaf_size;
    const TriangleMesh mesh = reference.mesh.view();
    const Bvh bvh = build_bvh(builder, mesh, options);
    std::vector<Hit> hits(reference.rays.size());
    std::vector<uint8_t> occluded(reference.rays.size());
    trace_closest(bvh, mesh, reference.rays, hits);
    trace_any(bvh, mesh, reference.rays, occluded);
    size_t failures = 0, hit_count = 0;
    for (size_t i = 0; i < reference.rays.size() && failures < 10; ++i) {
      const auto same = testing::same_closest_hit(reference.closest[i], hits[i]);
      EXPECT_TRUE(same) << "ray " << i;
      EXPECT_EQ(occluded[i], reference.occluded[i]) << "ray " << i;
      EXPECT_EQ(reference.occluded[i] != 0, reference.closest[i].valid()) << "ray " << i;
      if (expect_all_hit) {
        EXPECT_TRUE(hits[i].valid()) << "ray " << i << " slipped through";
      }
      failures += same ? 0 : 1;
      hit_count += hits[i].valid() ? 1 : 0;
    }
    EXPECT_GT(hit_count, reference.rays.size() / 4);  // the rays do test something
  }
};

TEST_P(TraversalMatchesBruteForce, RandomSoup) { check(soup_reference(), false); }
TEST_P(TraversalMatchesBruteForce, GridEdgesAndVerticesAreWatertight) { check(grid_reference(), true); }
TEST_P(TraversalMatchesBruteForce, AxisParallelRays) { check(axis_reference(), false); }

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
  // Three parallel squares at z = 1, 2, 3 (two triangles each), ray down the z axis.
  TestMesh mesh;
  for (float z : {1.0f, 2.0f, 3.0f}) {
    mesh.add_triangle(vec3(-1, -1, z), vec3(1, -1, z), vec3(1, 1, z));
    mesh.add_triangle(vec3(-1, -1, z), vec3(1, 1, z), vec3(-1, 1, z));
  }
  const TriangleMesh view = mesh.view();
  BuildOptions options;
  options.max_leaf_size = 1;
  const Bvh bvh = build_bvh(BvhBuilder::sah, view, options);
  const auto closest_t = [&](float t_min, float t_max) {
    const Ray ray{vec3(0.25f, 0.5f, 0.0f), t_min, vec3(0, 0, 1), t_max};
    Hit hit;
    trace_closest(bvh, view, std::span(&ray, 1), std::span(&hit, 1));
    uint8_t occluded = 0;
    trace_any(bvh, view, std::span(&ray, 1), std::span(&occluded, 1));
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
