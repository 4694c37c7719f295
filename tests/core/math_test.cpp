#include "core/math.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(Aabb, StartsEmptyAndGrowsToContainEveryPoint) {
  Aabb box;
  EXPECT_TRUE(box.empty());
  EXPECT_EQ(box.extent(), vec3(0.0f));
  box.extend(vec3(1, 2, 3));
  box.extend(vec3(-1, 5, 0));
  EXPECT_FALSE(box.empty());
  EXPECT_EQ(box.min, vec3(-1, 2, 0));
  EXPECT_EQ(box.max, vec3(1, 5, 3));
  EXPECT_EQ(box.center(), vec3(0, 3.5f, 1.5f));
  EXPECT_TRUE(box.contains(vec3(0, 3, 1)));
  EXPECT_FALSE(box.contains(vec3(0, 6, 1)));
}

TEST(Aabb, TransformedBoxBoundsTheTransformedCorners) {
  Aabb box;
  box.extend(vec3(-1, -1, -1));
  box.extend(vec3(1, 1, 1));
  const mat4 m = glm::translate(mat4(1.0f), vec3(10, 0, 0)) * glm::rotate(mat4(1.0f), glm::radians(45.0f), vec3(0, 1, 0));
  const Aabb moved = transform_aabb(m, box);
  const float r = std::sqrt(2.0f);
  EXPECT_NEAR(moved.min.x, 10 - r, 1e-5f);
  EXPECT_NEAR(moved.max.x, 10 + r, 1e-5f);
  EXPECT_NEAR(moved.min.y, -1, 1e-5f);
  EXPECT_NEAR(moved.max.z, r, 1e-5f);
  EXPECT_TRUE(transform_aabb(m, Aabb{}).empty());
}

}  // namespace
}  // namespace glint
