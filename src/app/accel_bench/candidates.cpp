#include "app/accel_bench/candidates.h"

#include "accel/builder.h"
#include "accel/bvh_stats.h"
#include "accel/embree_scene.h"
#include "accel/refit.h"
#include "accel/trace.h"
#include "core/error.h"

#include <chrono>
#include <memory>

namespace glint::accel_bench {
namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::string embree_name(accel::EmbreeQuality quality) {
  std::string name = "embree-";
  name += accel::embree_quality_name(quality);
  return name;
}

Candidate bvh_candidate(accel::BvhBuilder builder) {
  struct State {
    accel::Bvh bvh;
    accel::TriangleMesh mesh;
    bool built = false;
  };
  auto state = std::make_shared<State>();
  Candidate candidate;
  candidate.name = std::string(accel::builder_name(builder));
  candidate.brute_force = builder == accel::BvhBuilder::none;
  candidate.build = [state, builder](const accel::TriangleMesh& mesh) {
    state->bvh = accel::build_bvh(builder, mesh);
    state->mesh = mesh;
    state->built = true;
    return state->bvh.build_ms;
  };
  candidate.refit = [state](const accel::TriangleMesh& mesh) -> std::optional<double> {
    if (!state->built) fail("accel-bench: refit before build");
    if (!state->bvh.refittable) return std::nullopt;
    const auto start = std::chrono::steady_clock::now();
    accel::refit(state->bvh, mesh);
    state->mesh = mesh;
    return ms_since(start);
  };
  candidate.trace_closest = [state](std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
    if (!state->built) fail("accel-bench: trace before build");
    accel::trace_closest(state->bvh, state->mesh, rays, hits);
  };
  candidate.stats = [state] {
    const accel::BvhStats stats = accel::compute_stats(state->bvh);
    return CandidateStats{stats.nodes, stats.memory_bytes, stats.sah_cost};
  };
  return candidate;
}

Candidate embree_candidate(const accel::EmbreeDevice& device, accel::EmbreeQuality quality) {
  auto scene = std::make_shared<std::unique_ptr<accel::EmbreeScene>>();
  Candidate candidate;
  candidate.name = embree_name(quality);
  candidate.build = [scene, &device, quality](const accel::TriangleMesh& mesh) {
    scene->reset();  // free the old BVH first so the memory monitor counts only the new one
    *scene = std::make_unique<accel::EmbreeScene>(device, mesh, quality);
    return (*scene)->build_ms();
  };
  candidate.refit = [scene, quality](const accel::TriangleMesh& mesh) -> std::optional<double> {
    if (!*scene) fail("accel-bench: refit before build");
    // Only the dynamic-scene quality refits; an update of the others would be a rebuild.
    if (quality != accel::EmbreeQuality::refit) return std::nullopt;
    (*scene)->update_vertices(std::span(mesh.positions, mesh.indices ? mesh.vertex_count : 3 * mesh.triangle_count));
    return (*scene)->update_ms();
  };
  candidate.trace_closest = [scene](std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
    if (!*scene) fail("accel-bench: trace before build");
    (*scene)->trace_closest(rays, hits);
  };
  candidate.stats = [scene] {
    CandidateStats stats;
    if (*scene) stats.memory_bytes = static_cast<size_t>(std::max<int64_t>(0, (*scene)->build_bytes()));
    return stats;
  };
  return candidate;
}

}  // namespace

std::vector<CandidateEntry> candidate_menu(const accel::EmbreeDevice& device) {
  std::vector<CandidateEntry> menu;
  for (const accel::BvhBuilder builder : accel::kAllBvhBuilders)
    menu.push_back({std::string(accel::builder_name(builder)), [builder] { return bvh_candidate(builder); }});
  for (const accel::EmbreeQuality quality : accel::kAllEmbreeQualities)
    menu.push_back({embree_name(quality), [&device, quality] { return embree_candidate(device, quality); }});
  return menu;
}

std::vector<std::string> embree_candidate_names() {
  std::vector<std::string> names;
  for (const accel::EmbreeQuality quality : accel::kAllEmbreeQualities) names.push_back(embree_name(quality));
  return names;
}

std::vector<std::string> candidate_names() {
  std::vector<std::string> names;
  for (const accel::BvhBuilder builder : accel::kAllBvhBuilders) names.emplace_back(accel::builder_name(builder));
  for (std::string& name : embree_candidate_names()) names.push_back(std::move(name));
  return names;
}

}  // namespace glint::accel_bench
