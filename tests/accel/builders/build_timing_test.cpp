// Who times a build: the builders return the structure only, and build_bvh (the menu's entry point,
// accel/builders/builder.h) times them once, the mesh overload including the triangles' bounds; accel-bench,
// the stats and the GPU upload read that one number.
#include "accel/builders/build_lbvh.h"
#include "accel/builders/build_median.h"
#include "accel/builders/build_none.h"
#include "accel/builders/build_ploc.h"
#include "accel/builders/build_sah.h"
#include "accel/builders/build_sbvh.h"
#include "accel/builders/build_trbvh.h"
#include "accel/builders/builder.h"
#include "accel/builders/primitive_bounds.h"
#include "accel/test_scenes.h"

#include <gtest/gtest.h>

#include <vector>

namespace glint::accel {
namespace {

TEST(BuildTiming, BuildersReturnDataAndBuildBvhTimesThemOnce) {
  const testing::TestMesh mesh = testing::make_random_soup(5, 4000);
  const PrimitiveBounds bounds = triangle_bounds(mesh.view());
  const std::vector<Bvh> untimed = {build_none(bounds.input()),  build_median(bounds.input()),
                                    build_sah(bounds.input()),   build_sbvh(mesh.view()),
                                    build_lbvh(bounds.input()),  build_trbvh(bounds.input()),
                                    build_ploc(bounds.input())};
  for (const Bvh& bvh : untimed) EXPECT_EQ(bvh.build_ms, 0.0) << bvh.builder << " timed itself";
  for (const BvhBuilder builder : kAllBvhBuilders) {
    EXPECT_GT(build_bvh(builder, mesh.view()).build_ms, 0.0) << builder_name(builder);
    EXPECT_GT(build_bvh(builder, bounds.input()).build_ms, 0.0) << builder_name(builder);
  }
}

}  // namespace
}  // namespace glint::accel
