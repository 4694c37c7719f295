#include "accel/intersect_box.h"
#include "accel/intersect_triangle.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

namespace glint::accel {
namespace {

using testing::brute_force_closest;

const Triangle kTriangle{vec3(0, 0, 0), vec3(2, 0, 0), vec3(0, 2, 0)};

bool hit_triangle(const Ray& ray, const Triangle& tri, TriangleHit& hit) {
  return intersect_triangle(make_watertight_ray(ray.origin, ray.direction), tri, ray.t_min, ray.t_max, hit);
}

TEST(AccelTriangle, HitReportsTAndBarycentricsOfThePoint) {
  const Ray ray{vec3(0.5f, 0.25f, 3.0f), 0.0f, vec3(0, 0, -2), kInfinity};
  TriangleHit hit;
  ASSERT_TRUE(hit_triangle(ray, kTriangle, hit));
  EXPECT_FLOAT_EQ(hit.t, 1.5f);
  // point = (1 - u - v) v0 + u v1 + v v2 = (2u, 2v, 0)
  EXPECT_FLOAT_EQ(hit.u, 0.25f);
  EXPECT_FLOAT_EQ(hit.v, 0.125f);
}

TEST(AccelTriangle, BarycentricsReconstructTheHitPointForRandomRays) {
  const testing::TestMesh soup = testing::make_random_soup(7, 200);
  const TriangleMesh mesh = soup.view();
  const std::vector<Ray> rays = testing::make_random_rays(soup, 8, 2000);
  int hits = 0;
  for (const Ray& ray : rays) {
    const Hit hit = brute_force_closest(mesh, ray);
    if (!hit.valid()) continue;
    ++hits;
    const Triangle tri = mesh.triangle(hit.prim);
    const vec3 on_triangle = (1.0f - hit.u - hit.v) * tri.v0 + hit.u * tri.v1 + hit.v * tri.v2;
    const vec3 on_ray = ray.origin + hit.t * ray.direction;
    EXPECT_NEAR(glm::length(on_triangle - on_ray), 0.0f, 1e-4f * (1.0f + glm::length(on_ray)));
    EXPECT_GE(hit.u, 0.0f);
    EXPECT_GE(hit.v, 0.0f);
    EXPECT_LE(hit.u + hit.v, 1.0f + 1e-6f);
  }
  EXPECT_GT(hits, 500);
}

TEST(AccelTriangle, BothSidesAreHit) {
  TriangleHit hit;
  EXPECT_TRUE(hit_triangle({vec3(0.5f, 0.5f, 1), 0, vec3(0, 0, -1), kInfinity}, kTriangle, hit));
  EXPECT_TRUE(hit_triangle({vec3(0.5f, 0.5f, -1), 0, vec3(0, 0, 1), kInfinity}, kTriangle, hit));
}

TEST(AccelTriangle, RayInterval) {
  TriangleHit hit;
  const vec3 origin(0.5f, 0.5f, 1.0f), down(0, 0, -1);
  EXPECT_TRUE(hit_triangle({origin, 0.0f, down, 1.0f}, kTriangle, hit));   // t_max inclusive
  EXPECT_TRUE(hit_triangle({origin, 1.0f, down, 5.0f}, kTriangle, hit));   // t_min inclusive
  EXPECT_FALSE(hit_triangle({origin, 0.0f, down, 0.999f}, kTriangle, hit));
  EXPECT_FALSE(hit_triangle({origin, 1.001f, down, 5.0f}, kTriangle, hit));
  EXPECT_FALSE(hit_triangle({origin, 0.0f, -down, kInfinity}, kTriangle, hit));  // behind the origin
}

TEST(AccelTriangle, MissesOutsideAndInThePlane) {
  TriangleHit hit;
  EXPECT_FALSE(hit_triangle({vec3(1.5f, 1.5f, 1), 0, vec3(0, 0, -1), kInfinity}, kTriangle, hit));
  EXPECT_FALSE(hit_triangle({vec3(-1, 0.5f, 0), 0, vec3(1, 0, 0), kInfinity}, kTriangle, hit));
  const Triangle degenerate{vec3(0), vec3(1, 1, 1), vec3(2, 2, 2)};
  EXPECT_FALSE(hit_triangle({vec3(1, 1, 0), 0, vec3(0, 0, 1), kInfinity}, degenerate, hit));
}

TEST(AccelTriangle, SharedEdgesAndVerticesOfAGridAreWatertight) {
  for (bool tilted : {false, true}) {
    const uint32_t cells = 12;
    const testing::TestMesh grid = testing::make_grid(cells, tilted);
    const std::vector<Ray> rays = testing::make_grid_edge_rays(grid, cells, 3);
    for (const Ray& ray : rays) {
      const Hit hit = brute_force_closest(grid.view(), ray);
      EXPECT_TRUE(hit.valid()) << "ray slipped through at " << ray.origin.x + ray.direction.x << ", "
                               << ray.origin.y + ray.direction.y << (tilted ? " (tilted)" : "");
    }
  }
}

TEST(AccelBox, ZeroDirectionComponentsAndFlatBoxes) {
  BvhNode flat;
  flat.set_bounds(Aabb{vec3(0, 0, 1), vec3(1, 1, 1)});  // zero thickness in z
  float t = 0.0f;
  // Straight down through it.
  EXPECT_TRUE(intersect_box(make_box_ray(vec3(0.5f, 0.5f, 3), vec3(0, 0, -1)), flat, 0, kInfinity, t));
  EXPECT_FLOAT_EQ(t, 2.0f);
  // Parallel to it, inside its plane and on its edge: conservatively a hit.
  EXPECT_TRUE(intersect_box(make_box_ray(vec3(-1, 0.5f, 1), vec3(1, 0, 0)), flat, 0, kInfinity, t));
  EXPECT_TRUE(intersect_box(make_box_ray(vec3(-1, 0, 1), vec3(1, 0, 0)), flat, 0, kInfinity, t));
  // Parallel to it, off its plane: a miss.
  EXPECT_FALSE(intersect_box(make_box_ray(vec3(-1, 0.5f, 1.5f), vec3(1, 0, 0)), flat, 0, kInfinity, t));
  // Negative zero direction components behave as positive ones.
  EXPECT_TRUE(intersect_box(make_box_ray(vec3(0.5f, 0.5f, 3), vec3(-0.0f, -0.0f, -1)), flat, 0, kInfinity, t));
  // Interval honoured.
  EXPECT_FALSE(intersect_box(make_box_ray(vec3(0.5f, 0.5f, 3), vec3(0, 0, -1)), flat, 0, 1.5f, t));
  EXPECT_FALSE(intersect_box(make_box_ray(vec3(0.5f, 0.5f, 3), vec3(0, 0, -1)), flat, 2.5f, kInfinity, t));
}

}  // namespace
}  // namespace glint::accel
