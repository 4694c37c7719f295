#include "app/bench/backend_availability.h"

#include "core/error.h"
#include "cuda/device_query.h"
#include "rt/ray_tracer.h"

namespace glint::bench {

std::optional<std::string> backend_unavailable_reason(const std::string& backend) {
  if (rt::is_gpu_backend(backend)) {
    std::string why_none;
    if (query_cuda_devices(&why_none).empty())
      return why_none.empty() ? std::string("no CUDA GPU") : why_none;
  }
  if (backend == "gl") return std::nullopt;  // made on the cells' GL context; it has no other need
  try {
    (void)rt::make_ray_tracer(backend);
  } catch (const Error& error) {
    return std::string("not in this build: ") + error.what();
  }
  return std::nullopt;
}

}  // namespace glint::bench
