// How the optix backend refuses to start where it cannot run (any machine): a build without OptiX,
// or an OptiX build on a machine without a CUDA GPU, is one line that says what is missing.
#include "rt/ray_tracer.h"
#include "backends/registry.h"

#include "app/accel_bench/candidates_optix.h"
#include "cuda/device_query.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace glint::rt {
namespace {

bool one_line(const std::string& text) { return !text.empty() && std::count(text.begin(), text.end(), '\n') == 0; }

TEST(OptixBackend, BuildWithoutOptixSaysHowToEnableIt) {
  if (GLINT_HAVE_OPTIX) GTEST_SKIP() << "this build has OptiX";
  EXPECT_FALSE(accel_bench::optix_candidates_built());
  for (const std::string& error : {testing::error_of([] { (void)backends::make_ray_tracer("optix"); }),
                                   testing::error_of([] { backends::check_backend_built("optix"); }),
                                   testing::error_of([] { (void)accel_bench::optix_candidate_menu().front().make(); })}) {
    EXPECT_TRUE(one_line(error)) << error;
    EXPECT_NE(error.find("built without OptiX"), std::string::npos) << error;
    EXPECT_NE(error.find("OptiX_INSTALL_DIR"), std::string::npos) << error;
  }
  backends::check_backend_built("cpu");  // the others are unaffected
  backends::check_backend_built("embree");
}

TEST(OptixBackend, OptixBuildWithoutAGpuIsOneClearLine) {
  if (!GLINT_HAVE_OPTIX) GTEST_SKIP() << "glint was built without OptiX";
  if (cuda_gpu_present()) GTEST_SKIP() << "this machine has a CUDA GPU (the backend starts instead)";
  EXPECT_TRUE(accel_bench::optix_candidates_built());
  backends::check_backend_built("optix");  // built: only the missing GPU stops it
  const std::string error = testing::error_of([] { (void)backends::make_ray_tracer("optix"); });
  EXPECT_TRUE(one_line(error)) << error;
  EXPECT_NE(error.find("the optix backend needs a CUDA GPU"), std::string::npos) << error;
}

TEST(OptixBackend, UnknownBackendListsOptix) {
  const std::string error = testing::error_of([] { (void)backends::make_ray_tracer("optix9"); });
  EXPECT_NE(error.find("cpu, embree, cuda, optix"), std::string::npos) << error;
}

}  // namespace
}  // namespace glint::rt
