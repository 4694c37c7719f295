#include "rt/ray_tracer.h"

#include "core/error.h"
#include "cuda/cuda_ray_tracer.h"
#include "gl_rt/make_gl_ray_tracer.h"
#include "rt/cpu_ray_tracer.h"
#include "rt/embree_ray_tracer.h"
#if GLINT_HAVE_OPTIX
#include "optix/backend.h"
#endif

namespace glint::rt {

RayTracer::~RayTracer() = default;
DeviceTracing::~DeviceTracing() = default;
GlTracing::~GlTracing() = default;

HitAndShadowTickets DeviceTracing::trace_closest_and_hit_shadows_device(const accel::Ray*, accel::Hit*,
                                                                        const uint32_t*, uint32_t,
                                                                        const HitShadowRays&) {
  fail("this GPU backend traces the reflection hits' shadow rays only after a GL pass wrote them");
}

std::string_view update_policy_name(UpdatePolicy policy) {
  switch (policy) {
    case UpdatePolicy::rebuild: return "rebuild";
    case UpdatePolicy::refit: return "refit";
    case UpdatePolicy::automatic: return "auto";
  }
  return "?";
}

UpdatePolicy parse_update_policy(std::string_view name) {
  for (UpdatePolicy policy : kAllUpdatePolicies)
    if (update_policy_name(policy) == name) return policy;
  fail("unknown update policy \"{}\" (known: rebuild, refit, auto)", name);
}

void check_backend_built(std::string_view backend) {
#if !GLINT_HAVE_OPTIX
  if (backend == "optix")
    fail("the optix backend is not in this build: glint was built without OptiX (configure with "
         "-DOptiX_INSTALL_DIR=<OptiX SDK folder> and CUDA on; docs/optix.md)");
#else
  (void)backend;
#endif
}

bool is_gpu_backend(std::string_view backend) { return backend == "cuda" || backend == "optix"; }

std::unique_ptr<RayTracer> make_ray_tracer(std::string_view backend) {
  check_backend_built(backend);
  if (backend == "cpu") return std::make_unique<CpuRayTracer>();
  if (backend == "embree") return std::make_unique<EmbreeRayTracer>();
  if (backend == "cuda") return cuda::make_cuda_ray_tracer();
  if (backend == "gl") return gl_rt::make_gl_ray_tracer();
#if GLINT_HAVE_OPTIX
  if (backend == "optix") return std::make_unique<optix::OptixRayTracer>();
#endif
  fail("unknown ray tracing backend \"{}\" (known: cpu, embree, cuda, optix, gl)", backend);
}

}  // namespace glint::rt
