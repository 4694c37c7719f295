#include "accel/builders/builder.h"
#include "accel/wide/wide_bvh_collapse.h"
#include "accel/wide/wide_bvh_refit.h"
#include "accel/wide/wide_bvh_trace.h"
#include "accel/wide/wide_bvh_validate.h"
#include "core/error.h"
#include "accel/test_scenes.h"
#include "wide_bvh_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

namespace glint::accel {
namespace {

using testing::TestMesh;
using testing::WideConfig;

// The paper's sine deformer shape: every vertex moves along y by a wave over x (and a second,
// smaller one along z over y, so boxes change on every axis).
void displace(TestMesh& mesh, float phase) {
  for (vec3& p : mesh.positions) {
    const vec3 rest = p;
    p.y += 0.15f * std::sin(4.0f * rest.x + phase);
    p.z += 0.05f * std::sin(6.0f * rest.y + 2.0f * phase);
  }
}

using RefitParam = std::tuple<BvhBuilder, WideConfig>;

class WideBvhRefit : public ::testing::TestWithParam<RefitParam> {};

template <int N>
void refit_any(testing::AnyWideBvh& wide, const TriangleMesh& mesh) {
  refit(std::get<WideBvh<N>>(wide), mesh);
}

TEST_P(WideBvhRefit, GivesTheSameHitsAsAFreshBuild) {
  const auto [builder, config] = GetParam();
  if (config.path == WideSimdPath::avx2 && !cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this CPU";
  const testing::ScopedWidePath path(config);
  TestMesh mesh = testing::make_random_soup(71, 2500);
  testing::AnyWideBvh refitted = testing::collapse_any(config.width, build_bvh(builder, mesh.view()), mesh.view());
  const std::vector<Ray> rays = testing::make_random_rays(mesh, 72, 6000);  // aimed at the rest pose too

  for (const float phase : {0.7f, 2.1f}) {
    displace(mesh, phase);  // positions change in place; the index buffer stays
    const TriangleMesh moved = mesh.view();
    if (config.width == 4) {
      refit_any<4>(refitted, moved);
      EXPECT_NO_THROW(validate_wide_bvh(std::get<WideBvh4>(refitted), moved));
    } else {
      refit_any<8>(refitted, moved);
      EXPECT_NO_THROW(validate_wide_bvh(std::get<WideBvh8>(refitted), moved));
    }
    const testing::AnyWideBvh fresh = testing::collapse_any(config.width, build_bvh(builder, moved), moved);

    std::vector<Hit> refit_hits(rays.size()), fresh_hits(rays.size());
    std::vector<uint8_t> occluded(rays.size());
    testing::trace_closest_any_width(refitted, rays, refit_hits);
    testing::trace_closest_any_width(fresh, rays, fresh_hits);
    testing::trace_any_any_width(refitted, rays, occluded);
    size_t hit_count = 0, failures = 0;
    for (size_t i = 0; i < rays.size() && failures < 10; ++i) {
      const auto same_as_fresh = testing::same_closest_hit(fresh_hits[i], refit_hits[i]);
      const auto same_as_brute = testing::same_closest_hit(testing::brute_force_closest(moved, rays[i]), refit_hits[i]);
      EXPECT_TRUE(same_as_fresh) << "ray " << i << " phase " << phase;
      EXPECT_TRUE(same_as_brute) << "ray " << i << " phase " << phase;
      EXPECT_EQ(occluded[i] != 0, refit_hits[i].valid()) << "ray " << i;
      failures += same_as_fresh && same_as_brute ? 0 : 1;
      hit_count += refit_hits[i].valid() ? 1 : 0;
    }
    EXPECT_GT(hit_count, rays.size() / 5);
  }
}

std::vector<RefitParam> refit_params() {
  std::vector<RefitParam> params;
  for (const BvhBuilder builder : testing::collapsible_builders())
    for (const WideConfig& config : testing::all_wide_configs()) params.emplace_back(builder, config);
  return params;
}

INSTANTIATE_TEST_SUITE_P(Accel, WideBvhRefit, ::testing::ValuesIn(refit_params()),
                         [](const ::testing::TestParamInfo<RefitParam>& param_info) {
                           return std::string(builder_name(std::get<0>(param_info.param))) + "_" +
                                  std::get<1>(param_info.param).name();
                         });

TEST(WideBvhRefitErrors, RefusesNonRefittableAndMismatchedMeshes) {
  const TestMesh soup = testing::make_random_soup(73, 200);
  const TestMesh other = testing::make_random_soup(74, 150);
  Bvh bvh = build_bvh(BvhBuilder::sah, soup.view());
  WideBvh8 wide = collapse_to_wide<8>(bvh, soup.view());
  EXPECT_THROW(refit(wide, other.view()), Error);
  bvh.refittable = false;  // as a spatial-split builder marks it: such BVHs are not collapsed at all
  EXPECT_THROW(collapse_to_wide<4>(bvh, soup.view()), Error);
}

TEST(WideBvhRefitBounds, BoxesAreTightAfterRefit) {
  // After refit every leaf lane's box is exactly the box of its triangles, and the root box the
  // mesh's: a refit that only grew boxes would pass the hit tests but fail this.
  TestMesh mesh = testing::make_clustered(75, 1500);
  WideBvh8 wide = collapse_to_wide<8>(build_bvh(BvhBuilder::sah, mesh.view()), mesh.view());
  displace(mesh, 1.3f);
  refit(wide, mesh.view());
  const TriangleMesh view = mesh.view();
  Aabb all;
  for (uint32_t i = 0; i < view.triangle_count; ++i) all.extend(view.triangle(i).bounds());
  EXPECT_EQ(wide.bounds.min, all.min);
  EXPECT_EQ(wide.bounds.max, all.max);
  for (const WideNode<8>& node : wide.nodes) {
    for (int lane = 0; lane < 8; ++lane) {
      if (node.is_empty(lane) || !node.is_leaf(lane)) continue;
      Aabb leaf;
      for (uint32_t slot = 0; slot < node.prim_count[lane]; ++slot)
        leaf.extend(view.triangle(wide.blocks[node.child[lane] + slot / 8].prim[slot % 8]).bounds());
      EXPECT_EQ(node.child_bounds(lane).min, leaf.min);
      EXPECT_EQ(node.child_bounds(lane).max, leaf.max);
    }
  }
}

}  // namespace
}  // namespace glint::accel
