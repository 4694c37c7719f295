// The optix builder names (any machine): what --accel and accel-bench accept for the optix backend.
#include "rt/gas_build_preference.h"

#include "app/accel_bench/candidates_optix.h"
#include "rt/ray_tracer.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

namespace glint::rt {
namespace {

TEST(OptixBuildPreference, NamesRoundTripAndOthersAreRefused) {
  EXPECT_EQ(optix_accel_name(OptixBuildPreference::fast_trace), "optix-fasttrace");
  EXPECT_EQ(optix_accel_name(OptixBuildPreference::fast_build), "optix-fastbuild");
  for (const OptixBuildPreference preference : kAllOptixBuildPreferences) {
    EXPECT_EQ(parse_optix_accel(optix_accel_name(preference)), preference);
    EXPECT_TRUE(is_optix_accel_name(optix_accel_name(preference)));
  }
  for (const char* other : {"sah", "optix", "fasttrace", "optix-fasttrace ", ""}) {
    EXPECT_FALSE(is_optix_accel_name(other)) << other;
    const std::string error = testing::error_of([&] { (void)parse_optix_accel(other); });
    EXPECT_NE(error.find("optix-fasttrace, optix-fastbuild"), std::string::npos) << error;
  }
}

TEST(OptixBuildPreference, AccelOptionsDefaultToFastTraceAndCandidatesUseTheSameNames) {
  EXPECT_EQ(AccelOptions{}.optix_build, OptixBuildPreference::fast_trace);
  const std::vector<std::string> names = accel_bench::optix_candidate_names();
  ASSERT_EQ(names.size(), std::size(kAllOptixBuildPreferences));
  for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(names[i], optix_accel_name(kAllOptixBuildPreferences[i]));
}

}  // namespace
}  // namespace glint::rt
