#include "app/accel_bench/candidates_optix.h"

#include "backends/registry.h"
#include "core/error.h"
#include "optix/build_preference.h"
#if GLINT_HAVE_OPTIX
#include "optix/mesh_tracer.h"
#endif

#include <memory>

namespace glint::accel_bench {
namespace {

#if GLINT_HAVE_OPTIX
// Build and refit report the OptiX GAS's own milliseconds; the geometry upload is not timed (glint's
// CPU builders read host memory in place). Nodes and SAH are unknown: OptiX hides its nodes.
Candidate optix_candidate(optix::BuildPreference preference) {
  auto tracer = std::make_shared<optix::OptixMeshTracer>(preference);
  Candidate candidate;
  candidate.name = std::string(optix::kBuildPreferenceNames.name_of(preference));
  candidate.build = [tracer](const accel::TriangleMesh& mesh) { return tracer->build(mesh); };
  candidate.refit = [tracer](const accel::TriangleMesh& mesh) -> std::optional<double> { return tracer->refit(mesh); };
  candidate.trace_closest_timed = [tracer](std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
    return tracer->trace_closest(rays, hits) * 1e-3;
  };
  candidate.trace_closest = [tracer](std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
    (void)tracer->trace_closest(rays, hits);
  };
  candidate.stats = [tracer] {
    CandidateStats stats;
    stats.memory_bytes = tracer->structure_bytes();
    return stats;
  };
  return candidate;
}
#endif

}  // namespace

std::vector<std::string> optix_candidate_names() {
  return optix::kBuildPreferenceNames.names();
}

bool optix_candidates_built() { return GLINT_HAVE_OPTIX != 0; }

std::vector<CandidateEntry> optix_candidate_menu() {
  std::vector<CandidateEntry> menu;
#if GLINT_HAVE_OPTIX
  for (const optix::BuildPreference preference : optix::kAllBuildPreferences)
    menu.push_back({std::string(optix::kBuildPreferenceNames.name_of(preference)),
                    [preference] { return optix_candidate(preference); }});
#else
  // Known names in every build; making one says how to enable OptiX.
  for (const std::string& name : optix_candidate_names())
    menu.push_back({name, []() -> Candidate {
                      backends::check_backend_built("optix");
                      return {};
                    }});
#endif
  return menu;
}

}  // namespace glint::accel_bench
