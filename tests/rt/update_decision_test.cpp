// The one update-policy rule the cpu and cuda backends share (rt/update_decision.h) and the menu of
// structure names (rt/blas_structure.h).
#include "rt/update_decision.h"

#include "support/error_of.h"

#include <gtest/gtest.h>

namespace glint::rt {
namespace {

TEST(UpdateDecision, RebuildAndRefitAreWhatTheySay) {
  for (const std::optional<double> sah : {std::optional<double>(), std::optional<double>(100.0)}) {
    EXPECT_EQ(decide_blas_update(UpdatePolicy::rebuild, sah, 1.0, 1.3), BlasUpdate::rebuild);
    EXPECT_EQ(decide_blas_update(UpdatePolicy::refit, sah, 1.0, 1.3), BlasUpdate::refit);
  }
}

TEST(UpdateDecision, AutomaticRebuildsOnlyPastTheRatio) {
  EXPECT_EQ(decide_blas_update(UpdatePolicy::automatic, 1.29, 1.0, 1.3), BlasUpdate::refit);
  EXPECT_EQ(decide_blas_update(UpdatePolicy::automatic, 1.3, 1.0, 1.3), BlasUpdate::refit);
  EXPECT_EQ(decide_blas_update(UpdatePolicy::automatic, 1.31, 1.0, 1.3), BlasUpdate::rebuild);
  // Ratio 1: any degradation rebuilds.
  EXPECT_EQ(decide_blas_update(UpdatePolicy::automatic, 1.0001, 1.0, 1.0), BlasUpdate::rebuild);
  // Unknown cost (the cuda backend before its first measured refit) or no reference: refit.
  EXPECT_EQ(decide_blas_update(UpdatePolicy::automatic, std::nullopt, 1.0, 1.0), BlasUpdate::refit);
  EXPECT_EQ(decide_blas_update(UpdatePolicy::automatic, 5.0, 0.0, 1.0), BlasUpdate::refit);
}

TEST(UpdateDecision, StructuresThatCannotBeRefittedRefuseRefitAndAuto) {
  const BlasStructure kdtree{BlasKind::kdtree, accel::BvhBuilder::sah};
  const BlasStructure sbvh{BlasKind::bvh, accel::BvhBuilder::sbvh};
  for (UpdatePolicy policy : {UpdatePolicy::refit, UpdatePolicy::automatic}) {
    const std::string kd = update_refusal("cpu", policy, kdtree, "sheet");
    EXPECT_NE(kd.find("rt cpu: update policy '" + std::string(update_policy_name(policy)) + "'"), std::string::npos)
        << kd;
    EXPECT_NE(kd.find("kdtree structure cannot be refitted"), std::string::npos) << kd;
    EXPECT_NE(kd.find("mesh 'sheet'"), std::string::npos) << kd;
    const std::string split = update_refusal("cuda", policy, sbvh, "sheet");
    EXPECT_NE(split.find("sbvh builder's BVHs cannot be refitted"), std::string::npos) << split;
  }
  EXPECT_EQ(update_refusal("cpu", UpdatePolicy::rebuild, kdtree, "sheet"), "");
  EXPECT_EQ(update_refusal("cpu", UpdatePolicy::rebuild, sbvh, "sheet"), "");
  for (accel::BvhBuilder builder : accel::kAllBvhBuilders) {
    if (builder != accel::BvhBuilder::sbvh) {
      EXPECT_EQ(update_refusal("cpu", UpdatePolicy::automatic, {BlasKind::bvh, builder}, "m"), "");
    }
  }
}

TEST(BlasStructureNames, EveryBuilderThenKdTreeRoundTrip) {
  const std::vector<std::string> names = blas_structure_names();
  ASSERT_EQ(names.size(), std::size(accel::kAllBvhBuilders) + 1);
  EXPECT_EQ(names.back(), "kdtree");
  for (const std::string& name : names) EXPECT_EQ(blas_structure_name(parse_blas_structure(name)), name);
  EXPECT_EQ(parse_blas_structure("kdtree").kind, BlasKind::kdtree);
  EXPECT_EQ(parse_blas_structure("ploc").builder, accel::BvhBuilder::ploc);
  const std::string error = testing::error_of([] { (void)parse_blas_structure("octree"); });
  EXPECT_NE(error.find("\"octree\""), std::string::npos) << error;
  EXPECT_NE(error.find("kdtree"), std::string::npos) << error;
}

}  // namespace
}  // namespace glint::rt
