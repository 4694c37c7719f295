#include "app/bench/backend_availability.h"

#include "backends/registry.h"
#include "cuda/device_query.h"

namespace glint::bench {

std::optional<std::string> backend_unavailable_reason(const std::string& name) {
  const backends::Backend& backend = backends::find_backend(name);
  if (!backend.built()) return "not in this build: " + backend.missing_from_build;
  if (backend.device == backends::Device::cuda) {
    std::string why_none;
    if (query_cuda_devices(&why_none).empty())
      return why_none.empty() ? std::string("no CUDA GPU") : why_none;
  }
  return std::nullopt;
}

}  // namespace glint::bench
