// Every builder of the menu (kAllBvhBuilders) on the same three larger scenes and 100k rays each:
// a random soup, a degenerate-heavy soup and a piece of the atrium. Brute force over 100k rays x 50k
// triangles takes minutes on two cores, so the reference is the `sah` BVH's answers, and the `none`
// case of the menu checks exactly that reference against brute force on the first 10k rays.
#include "accel/builders/builder.h"
#include "accel/bvh_stats.h"
#include "accel/bvh_validate.h"
#include "accel/builders/primitive_bounds.h"
#include "accel/trace.h"
#include "scene/presets.h"
#include "accel/test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <tuple>

namespace glint::accel {
namespace {

using testing::TestMesh;

constexpr size_t kRayCount = 100000;
constexpr size_t kBruteForceRayCount = 10000;

// A few instances of the built-in atrium-simple (arcades, beams, a dinosaur, two armadillos),
// flattened to world space: 52,204 triangles of real architecture and creatures.
TestMesh make_atrium_piece() {
  const Scene scene = make_preset("atrium-simple");
  TestMesh soup;
  for (const glint::Instance& instance : scene.instances) {
    const std::string& name = instance.name;
    if (name != "arcades" && name != "beams" && name != "dinosaur-0" && name != "armadillo-0" &&
        name != "armadillo-1")
      continue;
    const Mesh& mesh = scene.meshes[instance.mesh];
    const auto world = [&](uint32_t index) { return vec3(instance.transform * vec4(mesh.positions[index], 1.0f)); };
    for (size_t i = 0; i < mesh.indices.size(); i += 3)
      soup.add_triangle(world(mesh.indices[i]), world(mesh.indices[i + 1]), world(mesh.indices[i + 2]));
  }
  return soup;
}

struct MenuScene {
  TestMesh mesh;
  std::vector<Ray> rays;
  std::vector<Hit> reference;  // sah's closest hits
};

const MenuScene& menu_scene(const std::string& name) {
  static std::map<std::string, std::unique_ptr<MenuScene>> scenes;
  std::unique_ptr<MenuScene>& scene = scenes[name];
  if (!scene) {
    scene = std::make_unique<MenuScene>();
    if (name == "random") scene->mesh = testing::make_random_soup(101, 12000);
    if (name == "degenerate") scene->mesh = testing::make_degenerate_soup(102, 12000);
    if (name == "atrium") scene->mesh = make_atrium_piece();
    scene->rays = testing::make_random_rays(scene->mesh, 103, kRayCount);
    const TriangleMesh view = scene->mesh.view();
    const Bvh sah = build_bvh(BvhBuilder::sah, view);
    scene->reference.resize(kRayCount);
    trace_closest(sah, view, scene->rays, scene->reference);
  }
  return *scene;
}

// Same hit or miss; on a hit the same triangle with the same t (every BVH runs the same triangle
// test on the same ray), or another triangle at a t within 1e-4 relative: a tie (duplicates,
// shared edges, coplanar overlaps), where either answer is right.
::testing::AssertionResult same_hit(const Hit& expected, const Hit& actual) {
  if (expected.valid() != actual.valid())
    return ::testing::AssertionFailure() << (expected.valid() ? "missed prim " : "hit prim ")
                                         << (expected.valid() ? expected.prim : actual.prim);
  if (!expected.valid()) return ::testing::AssertionSuccess();
  const float tolerance = 1e-4f * std::abs(expected.t);
  if (expected.prim == actual.prim && expected.t != actual.t)
    return ::testing::AssertionFailure() << "prim " << actual.prim << " at t " << actual.t << " instead of "
                                         << expected.t;
  if (std::abs(expected.t - actual.t) > tolerance)
    return ::testing::AssertionFailure() << "prim " << actual.prim << " at t " << actual.t << " instead of prim "
                                         << expected.prim << " at t " << expected.t;
  return ::testing::AssertionSuccess();
}

using MenuParam = std::tuple<BvhBuilder, std::string>;

class BuilderMenu : public ::testing::TestWithParam<MenuParam> {};

TEST_P(BuilderMenu, ClosestAndAnyHitsMatchTheReference) {
  const auto& [builder, scene_name] = GetParam();
  const MenuScene& scene = menu_scene(scene_name);
  const TriangleMesh view = scene.mesh.view();
  const PrimitiveBounds bounds = triangle_bounds(view);
  const Bvh bvh = build_bvh(builder, bounds.input());
  const uint32_t leaf_limit = builder == BvhBuilder::none ? scene.mesh.triangle_count() : BuildOptions{}.max_leaf_size;
  // validate_bvh checks that every primitive is referenced once; structures that split references
  // (refittable == false, e.g. SBVH) bring their own validation, and the hits below still apply.
  if (bvh.refittable) {
    ASSERT_NO_THROW(validate_bvh(bvh, bounds.boxes, leaf_limit));
  }

  const size_t count = builder == BvhBuilder::none ? kBruteForceRayCount : kRayCount;
  const std::span<const Ray> rays(scene.rays.data(), count);
  std::vector<Hit> hits(count);
  std::vector<uint8_t> occluded(count);
  trace_closest(bvh, view, rays, hits);
  trace_any(bvh, view, rays, occluded);
  size_t mismatches = 0, any_mismatches = 0, hit_count = 0, ties = 0;
  for (size_t i = 0; i < count; ++i) {
    const auto same = same_hit(scene.reference[i], hits[i]);
    if (!same && ++mismatches <= 5) ADD_FAILURE() << "ray " << i << ": " << same.message();
    if ((occluded[i] != 0) != hits[i].valid() && ++any_mismatches <= 5)
      ADD_FAILURE() << "ray " << i << ": any-hit says " << int{occluded[i]} << ", closest-hit "
                    << (hits[i].valid() ? "hits" : "misses");
    hit_count += hits[i].valid() ? 1 : 0;
    ties += same && hits[i].valid() && hits[i].prim != scene.reference[i].prim ? 1 : 0;
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(any_mismatches, 0u);
  EXPECT_GT(hit_count, count / 4);  // the rays do test something
  // The soups are full of duplicates and coplanar overlaps, where ties are expected; the atrium
  // has none of those, so there a tie must stay the exception rather than a loophole.
  if (scene_name == "atrium") {
    EXPECT_LT(ties, count / 100);
  }
}

std::vector<MenuParam> menu_params() {
  std::vector<MenuParam> params;
  for (const BvhBuilder builder : kAllBvhBuilders)
    for (const char* scene : {"random", "degenerate", "atrium"}) params.emplace_back(builder, scene);
  return params;
}

INSTANTIATE_TEST_SUITE_P(Accel, BuilderMenu, ::testing::ValuesIn(menu_params()),
                         [](const ::testing::TestParamInfo<MenuParam>& param_info) {
                           return std::string(builder_name(std::get<0>(param_info.param))) + "_" + std::get<1>(param_info.param);
                         });

double sah_cost(BvhBuilder builder, const PrimitiveBounds& bounds) {
  return compute_stats(build_bvh(builder, bounds.input())).sah_cost;
}

// Measured: clustered 3.46 -> 3.22, atrium piece 23.48 -> 19.69. Restructuring only accepts cheaper
// treelets, so this holds up to rounding (1e-9 relative).
TEST(BuilderMenuQuality, TreeletRestructuringNeverLosesToLbvh) {
  const TestMesh clustered = testing::make_clustered(104, 30000);
  const TestMesh* scenes[] = {&clustered, &menu_scene("atrium").mesh};
  for (const TestMesh* scene : scenes) {
    const PrimitiveBounds bounds = triangle_bounds(scene->view());
    const double lbvh = sah_cost(BvhBuilder::lbvh, bounds);
    const double trbvh = sah_cost(BvhBuilder::trbvh, bounds);
    EXPECT_LE(trbvh, lbvh * (1.0 + 1e-9)) << scene->triangle_count() << " triangles";
    std::printf("[ SAH      ] %u triangles: lbvh %.2f, trbvh %.2f\n", scene->triangle_count(), lbvh, trbvh);
  }
}

// Measured (CPU, 2 cores): sah 18.82, ploc 21.58 on this atrium piece (ratio 1.15); 1.3 leaves a
// margin. Greedy clustering by merged-box area is not the SAH, so PLOC need not reach binned SAH.
TEST(BuilderMenuQuality, PlocIsCloseToBinnedSahOnTheAtrium) {
  const PrimitiveBounds bounds = triangle_bounds(menu_scene("atrium").mesh.view());
  const double sah = sah_cost(BvhBuilder::sah, bounds);
  const double ploc = sah_cost(BvhBuilder::ploc, bounds);
  std::printf("[ SAH      ] atrium piece: sah %.2f, ploc %.2f\n", sah, ploc);
  EXPECT_LE(ploc, 1.3 * sah);
}

}  // namespace
}  // namespace glint::accel
