// The optix structure names (any machine): what --accel and accel-bench accept for the optix backend,
// the backend registry's list of its structures, and what the backend reads from AccelOptions.
#include "optix/build_preference.h"

#include "app/accel_bench/candidates_optix.h"
#include "backends/registry.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

namespace glint::optix {
namespace {

TEST(OptixBuildPreference, NamesRoundTripAndOthersAreRefused) {
  EXPECT_EQ(kBuildPreferenceNames.name_of(BuildPreference::fast_trace), "optix-fasttrace");
  EXPECT_EQ(kBuildPreferenceNames.name_of(BuildPreference::fast_build), "optix-fastbuild");
  for (const BuildPreference preference : kAllBuildPreferences) {
    EXPECT_EQ(kBuildPreferenceNames.parse(kBuildPreferenceNames.name_of(preference)), preference);
    EXPECT_EQ(build_preference_of(kBuildPreferenceNames.name_of(preference)), preference);
  }
  for (const char* other : {"sah", "optix", "fasttrace", "optix-fasttrace ", ""}) {
    EXPECT_FALSE(kBuildPreferenceNames.contains(other)) << other;
    const std::string error = testing::error_of([&] { (void)kBuildPreferenceNames.parse(other); });
    EXPECT_NE(error.find("optix-fasttrace, optix-fastbuild"), std::string::npos) << error;
  }
}

TEST(OptixBuildPreference, DefaultIsFastTraceAndRegistryAndCandidatesUseTheSameNames) {
  EXPECT_EQ(build_preference_of(rt::AccelOptions{}.backend_structure), BuildPreference::fast_trace);
  EXPECT_EQ(accel_bench::optix_candidate_names(), kBuildPreferenceNames.names());
  EXPECT_EQ(backends::find_backend("optix").structures, kBuildPreferenceNames.names());
  EXPECT_EQ(backends::structure_owner("optix-fastbuild"), &backends::find_backend("optix"));
}

}  // namespace
}  // namespace glint::optix
