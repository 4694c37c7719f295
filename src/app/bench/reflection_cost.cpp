#include "app/bench/reflection_cost.h"

#include "app/bench/backend_availability.h"
#include "app/bench_command.h"
#include "backends/registry.h"
#include "core/error.h"

namespace glint::bench {

ReflectionCost reflection_cost(const FrameMeasurement& frame) {
  ReflectionCost cost;
  for (const PassTime& pass : frame.times.passes) {
    if (pass.name == "ssr") cost.ssr_ms += pass.milliseconds;
    if (pass.name == "ray_list") cost.ray_list_ms += pass.milliseconds;
    if (pass.name == "hit_shade") cost.hit_shade_ms += pass.milliseconds;
    if (pass.name == "classify") cost.classify_ms += pass.milliseconds;
    if (pass.name == "resolve") cost.resolve_ms += pass.milliseconds;
    cost.gpu_total_ms += pass.milliseconds;
  }
  if (frame.ray_stats) {
    cost.trace_ms = frame.ray_stats->trace_ms;
    cost.rays = frame.ray_stats->rays_traced;
  }
  cost.reflective = frame.adaptive     ? frame.adaptive->reflective_pixels
                    : frame.ssr_counts ? frame.ssr_counts->reflective
                    : frame.ray_stats  ? frame.ray_stats->reflective_pixels
                                       : 0.0;
  return cost;
}

std::string first_available_backend(const std::string& backends) {
  for (const std::string& backend : parse_name_list("--backends", backends, backends::backend_names()))
    if (!backend_unavailable_reason(backend)) return backend;
  fail("--backends: none of {} can run here", backends);
}

}  // namespace glint::bench
