#include "accel/builders/builder.h"
#include "accel/bvh_validate.h"
#include "accel/refit.h"
#include "accel/tlas.h"
#include "accel/tlas_trace.h"
#include "accel/trace.h"
#include "core/error.h"
#include "test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

namespace glint::accel {
namespace {

using testing::TestMesh;

mat4 random_transform(std::mt19937& rng, bool mirror) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const vec3 axis = glm::normalize(vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f) + vec3(1e-3f));
  vec3 scale(0.5f + 1.5f * u(rng), 0.5f + 1.5f * u(rng), 0.5f + 1.5f * u(rng));
  if (mirror) scale.x = -scale.x;
  const vec3 translation = 6.0f * vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
  return glm::translate(mat4(1.0f), translation) * glm::rotate(mat4(1.0f), 6.28f * u(rng), axis) *
         glm::scale(mat4(1.0f), scale);
}

// Meshes, their BLASes and instances of them; and the same triangles transformed to world space
// in one flat mesh, with the flat index of each instance's first triangle.
struct TwoLevelScene {
  std::vector<TestMesh> meshes;
  std::vector<Bvh> blas_bvhs;
  std::vector<Blas> blases;
  std::vector<Instance> instances;
  TestMesh flat;
  std::vector<uint32_t> flat_offset;

  explicit TwoLevelScene(uint32_t seed) {
    meshes.push_back(testing::make_random_soup(seed, 800));
    meshes.push_back(testing::make_grid(10, true));
    // Triangles no smaller than ~0.05: world-space rounding must stay small next to their size
    // for the object-space and world-space answers to be comparable.
    TestMesh stretched = testing::make_random_soup(seed + 1, 1000);
    for (vec3& p : stretched.positions) p *= vec3(2.0f, 0.5f, 1.0f);
    meshes.push_back(std::move(stretched));
    meshes.push_back(TestMesh{});  // an empty BLAS, instanced too
    for (const TestMesh& mesh : meshes) blas_bvhs.push_back(build_bvh(BvhBuilder::sah, mesh.view()));
    for (size_t i = 0; i < meshes.size(); ++i) blases.push_back(make_blas(blas_bvhs[i], meshes[i].view()));

    std::mt19937 rng(seed);
    const uint32_t blas_of_instance[] = {0, 1, 2, 0, 1, 2, 0, 3, 2, 1};  // shared BLASes
    for (size_t i = 0; i < std::size(blas_of_instance); ++i)
      instances.push_back(make_instance(blas_of_instance[i], random_transform(rng, i == 4)));
    flatten();
  }

  void flatten() {
    flat = TestMesh{};
    flat_offset.clear();
    for (const Instance& instance : instances) {
      flat_offset.push_back(flat.triangle_count());
      const TestMesh& mesh = meshes[instance.blas];
      const auto base = static_cast<uint32_t>(flat.positions.size());
      for (const vec3& p : mesh.positions) flat.positions.push_back(vec3(instance.object_to_world * vec4(p, 1.0f)));
      for (uint32_t index : mesh.indices) flat.indices.push_back(base + index);
    }
  }
};

bool near_an_edge(const Hit& hit) { return std::min({hit.u, hit.v, 1.0f - hit.u - hit.v}) < 1e-3f; }

// The TLAS works in object space and the flat BVH in world space, so t and the edge tests round
// differently: hits must agree up to rounding, and disagree on which triangle only where the ray
// passes within rounding distance of an edge. Returns how many rays were such close calls.
size_t compare_with_flat(const TwoLevelScene& scene, const std::vector<Ray>& rays, const std::vector<Hit>& two_level,
                         const std::vector<Hit>& flat) {
  size_t close_calls = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const Hit& a = two_level[i];
    const Hit& b = flat[i];
    if (!a.valid() && !b.valid()) continue;
    if (a.valid() != b.valid()) {
      EXPECT_TRUE(near_an_edge(a.valid() ? a : b)) << "ray " << i << ": only one structure hits, far from an edge";
      ++close_calls;
      continue;
    }
    const uint32_t a_flat = scene.flat_offset[a.instance] + a.prim;
    const float tolerance = 1e-4f * std::max(1.0f, std::abs(b.t));
    if (a_flat == b.prim) {
      EXPECT_NEAR(a.t, b.t, tolerance) << "ray " << i;
      // Compare the points, not u, v: barycentrics of slivers amplify rounding.
      const Triangle tri = scene.flat.view().triangle(b.prim);
      const auto point = [&](const Hit& hit) { return (1.0f - hit.u - hit.v) * tri.v0 + hit.u * tri.v1 + hit.v * tri.v2; };
      // A grazing ray turns a tiny error across the plane into a large one along it.
      const vec3 normal = glm::normalize(glm::cross(tri.v1 - tri.v0, tri.v2 - tri.v0));
      const float cosine = std::abs(glm::dot(normal, glm::normalize(rays[i].direction)));
      EXPECT_LT(glm::length(point(a) - point(b)), 1e-4f * (1.0f + glm::length(point(b))) / std::max(cosine, 1e-3f))
          << "ray " << i << ": u, v " << a.u << ", " << a.v << " vs " << b.u << ", " << b.v << ", cosine " << cosine;
    } else if (std::abs(a.t - b.t) > tolerance) {
      EXPECT_TRUE(near_an_edge(a.t < b.t ? a : b)) << "ray " << i << ": different triangles at t " << a.t << " and "
                                                   << b.t;
      ++close_calls;
    }
  }
  return close_calls;
}

class AccelTlas : public ::testing::TestWithParam<BvhBuilder> {};

TEST_P(AccelTlas, SameHitsAsOneFlatBvhOverTransformedTriangles) {
  const TwoLevelScene scene(51);
  BuildOptions options;
  options.max_leaf_size = 1;
  const Tlas tlas = build_tlas(scene.blases, scene.instances, GetParam(), options);
  EXPECT_NO_THROW(validate_bvh(tlas.bvh, instance_world_boxes(scene.blases, tlas.instances),
                               GetParam() == BvhBuilder::none ? 10 : 1));

  const TriangleMesh flat_view = scene.flat.view();
  const Bvh flat_bvh = build_bvh(BvhBuilder::sah, flat_view);
  const std::vector<Ray> rays = testing::make_random_rays(scene.flat, 52, 12000);
  std::vector<Hit> two_level(rays.size()), flat(rays.size());
  trace_closest(tlas, scene.blases, rays, two_level);
  trace_closest(flat_bvh, flat_view, rays, flat);
  const size_t close_calls = compare_with_flat(scene, rays, two_level, flat);
  EXPECT_LE(close_calls, rays.size() / 500);
  std::printf("[ close    ] %zu of %zu rays hit different triangles within rounding of an edge\n", close_calls,
              rays.size());

  size_t hits = 0;
  std::vector<uint8_t> occluded(rays.size());
  trace_any(tlas, scene.blases, rays, occluded);
  for (size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(occluded[i] != 0, two_level[i].valid()) << "ray " << i;
    if (!two_level[i].valid()) continue;
    ++hits;
    ASSERT_LT(two_level[i].instance, scene.instances.size());
    EXPECT_NE(scene.instances[two_level[i].instance].blas, 3u);  // the empty BLAS is never hit
  }
  EXPECT_GT(hits, rays.size() / 4);
}

TEST_P(AccelTlas, RefitAfterMovingInstancesMatchesARebuild) {
  TwoLevelScene scene(53);
  Tlas refitted = build_tlas(scene.blases, scene.instances, GetParam());
  std::mt19937 rng(54);
  for (size_t i = 0; i < refitted.instances.size(); i += 2) {
    const Instance moved = make_instance(refitted.instances[i].blas, random_transform(rng, false));
    refitted.instances[i] = moved;
    scene.instances[i] = moved;
  }
  if (!refitted.bvh.refittable) {  // a spatial-split TLAS (sbvh) is rebuilt, never refitted
    EXPECT_THROW(refit_tlas(refitted, scene.blases), Error);
    return;
  }
  refit_tlas(refitted, scene.blases);
  EXPECT_NO_THROW(validate_bvh(refitted.bvh, instance_world_boxes(scene.blases, refitted.instances),
                               GetParam() == BvhBuilder::none ? 10 : 4));
  const Tlas rebuilt = build_tlas(scene.blases, scene.instances, GetParam());
  scene.flatten();
  const std::vector<Ray> rays = testing::make_random_rays(scene.flat, 55, 10000);
  std::vector<Hit> refit_hits(rays.size()), rebuilt_hits(rays.size());
  trace_closest(refitted, scene.blases, rays, refit_hits);
  trace_closest(rebuilt, scene.blases, rays, rebuilt_hits);
  // Same instances, same BLASes, same object-space rays: bit-identical answers.
  for (size_t i = 0; i < rays.size(); ++i)
    ASSERT_TRUE(testing::same_closest_hit(rebuilt_hits[i], refit_hits[i])) << "ray " << i;
}

TEST_P(AccelTlas, DeformingBlasRefitThenTlasRefitMatchesFullRebuild) {
  // The design's case: a deforming mesh refits its BLAS in place (the Blas view stays valid, the
  // node array is not reallocated), then the TLAS refits over the new BLAS root box.
  TwoLevelScene scene(57);
  Tlas tlas = build_tlas(scene.blases, scene.instances, GetParam());
  std::mt19937 rng(58);
  std::uniform_real_distribution<float> u(-0.3f, 0.3f);
  for (vec3& p : scene.meshes[0].positions) p += vec3(u(rng), u(rng), 2.0f * u(rng));
  refit(scene.blas_bvhs[0], scene.meshes[0].view());
  if (!tlas.bvh.refittable) {  // a spatial-split TLAS (sbvh) is rebuilt, never refitted
    EXPECT_THROW(refit_tlas(tlas, scene.blases), Error);
    return;
  }
  refit_tlas(tlas, scene.blases);

  std::vector<Bvh> rebuilt_bvhs;
  std::vector<Blas> rebuilt_blases;
  for (const TestMesh& mesh : scene.meshes) rebuilt_bvhs.push_back(build_bvh(BvhBuilder::sah, mesh.view()));
  for (size_t i = 0; i < scene.meshes.size(); ++i)
    rebuilt_blases.push_back(make_blas(rebuilt_bvhs[i], scene.meshes[i].view()));
  const Tlas rebuilt = build_tlas(rebuilt_blases, scene.instances, GetParam());

  scene.flatten();
  const std::vector<Ray> rays = testing::make_random_rays(scene.flat, 59, 10000);
  std::vector<Hit> refit_hits(rays.size()), rebuilt_hits(rays.size());
  trace_closest(tlas, scene.blases, rays, refit_hits);
  trace_closest(rebuilt, rebuilt_blases, rays, rebuilt_hits);
  size_t hits = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    ASSERT_TRUE(testing::same_closest_hit(rebuilt_hits[i], refit_hits[i])) << "ray " << i;
    hits += refit_hits[i].valid() ? 1 : 0;
  }
  EXPECT_GT(hits, rays.size() / 4);
}

INSTANTIATE_TEST_SUITE_P(Accel, AccelTlas, ::testing::ValuesIn(kAllBvhBuilders),
                         [](const ::testing::TestParamInfo<BvhBuilder>& param_info) {
                           return std::string(builder_name(param_info.param));
                         });

TEST(AccelTlasErrors, BadInstancesAreClearErrors) {
  EXPECT_THROW(make_instance(0, mat4(0.0f)), Error);
  mat4 nan_transform(1.0f);
  nan_transform[3][0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(make_instance(0, nan_transform), Error);
  const TestMesh soup = testing::make_random_soup(56, 10);
  const Bvh bvh = build_bvh(BvhBuilder::sah, soup.view());
  const std::vector<Blas> blases{make_blas(bvh, soup.view())};
  EXPECT_THROW(build_tlas(blases, {make_instance(1, mat4(1.0f))}, BvhBuilder::sah), Error);
  const TestMesh other = testing::make_random_soup(57, 11);
  EXPECT_THROW(make_blas(bvh, other.view()), Error);
}

TEST(AccelTlasErrors, HitInstanceAndPrimOfAKnownScene) {
  // One unit triangle instanced twice along z; a ray down -z hits the upper copy (instance 1).
  TestMesh mesh;
  mesh.add_triangle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0));
  const Bvh bvh = build_bvh(BvhBuilder::median, mesh.view());
  const std::vector<Blas> blases{make_blas(bvh, mesh.view())};
  const Tlas tlas = build_tlas(blases,
                               {make_instance(0, glm::translate(mat4(1.0f), vec3(0, 0, 1))),
                                make_instance(0, glm::translate(mat4(1.0f), vec3(0, 0, 3)) *
                                                     glm::scale(mat4(1.0f), vec3(2.0f)))},
                               BvhBuilder::sah);
  const Ray ray{vec3(0.5f, 0.25f, 10.0f), 0.0f, vec3(0, 0, -1), kInfinity};
  Hit hit;
  trace_closest(tlas, blases, std::span(&ray, 1), std::span(&hit, 1));
  ASSERT_TRUE(hit.valid());
  EXPECT_EQ(hit.instance, 1u);
  EXPECT_EQ(hit.prim, 0u);
  EXPECT_FLOAT_EQ(hit.t, 7.0f);
  EXPECT_FLOAT_EQ(hit.u, 0.25f);   // object-space barycentrics: (0.25, 0.125) in the scaled copy
  EXPECT_FLOAT_EQ(hit.v, 0.125f);
  const Ray limited{vec3(0.5f, 0.25f, 10.0f), 7.5f, vec3(0, 0, -1), kInfinity};
  trace_closest(tlas, blases, std::span(&limited, 1), std::span(&hit, 1));
  ASSERT_TRUE(hit.valid());
  EXPECT_EQ(hit.instance, 0u);
  EXPECT_FLOAT_EQ(hit.t, 9.0f);
}

}  // namespace
}  // namespace glint::accel
