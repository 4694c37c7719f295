// backends::check_backend_runnable, the one check render, the Python module's render and the viewer
// make before they build anything: a backend this binary lacks says how to build it in, a CUDA
// backend on a machine without a CUDA GPU says so with the flag's name, and CPU backends run.
#include "backends/registry.h"
#include "cuda/device_query.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

namespace glint::backends {
namespace {

Backend test_backend(std::string name, Device device, std::string missing = "") {
  Backend backend;
  backend.name = std::move(name);
  backend.device = device;
  backend.missing_from_build = std::move(missing);
  backend.help = backend.name + " (a test's backend)";
  backend.make = [] { return make_ray_tracer("cpu"); };
  return backend;
}

TEST(BackendRunnable, SaysWhatAMissingBackendOrAMissingGpuIs) {
  EXPECT_NO_THROW(check_backend_runnable("cpu"));
  EXPECT_NO_THROW(check_backend_runnable("embree"));
  EXPECT_NE(testing::error_of([] { check_backend_runnable("sideways"); }).find("unknown ray tracing backend"),
            std::string::npos);

  const ScopedBackendRegistration absent(test_backend("absent", Device::cpu, "configure with -DABSENT=ON"));
  EXPECT_EQ(testing::error_of([] { check_backend_runnable("absent"); }),
            "the absent backend is not in this build: configure with -DABSENT=ON");

  const ScopedBackendRegistration on_gpu(test_backend("on-gpu", Device::cuda));
  if (cuda_gpu_present()) {
    EXPECT_NO_THROW(check_backend_runnable("on-gpu"));
  } else {
    EXPECT_EQ(testing::error_of([] { check_backend_runnable("on-gpu"); }).rfind("--backend on-gpu needs a CUDA GPU: ", 0),
              0u);
  }
}

}  // namespace
}  // namespace glint::backends
