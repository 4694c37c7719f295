#include "app/accel_bench/candidates.h"

#include "accel/builders/builder.h"
#include "accel/bvh_stats.h"
#include "rt/embree/embree_scene.h"
#include "accel/kdtree/kdtree.h"
#include "accel/kdtree/kdtree_stats.h"
#include "accel/kdtree/kdtree_trace.h"
#include "accel/refit.h"
#include "accel/trace.h"
#include "accel/wide/wide_bvh.h"
#include "accel/wide/wide_bvh_collapse.h"
#include "accel/wide/wide_bvh_refit.h"
#include "accel/wide/wide_bvh_trace.h"
#include "app/accel_bench/candidates_optix.h"
#include "core/error.h"
#include "core/stopwatch.h"
#include "cuda/gpu_bench_kdtree.h"
#include "cuda/gpu_bench_structure.h"

#include <memory>

namespace glint::accel_bench {
namespace {

std::string embree_name(rt::EmbreeQuality quality) {
  std::string name = "embree-";
  name += rt::embree_quality_name(quality);
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
    const Stopwatch watch;
    accel::refit(state->bvh, mesh);
    state->mesh = mesh;
    return watch.elapsed_ms();
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

// A binary BVH from `builder` collapsed to N wide with SIMD traversal. Build time is the binary build
// plus the collapse; refit updates the wide boxes and triangle blocks directly. Its SAH is left out:
// the AKL formula in bvh_stats is defined for binary nodes.
template <int N>
Candidate wide_candidate(accel::BvhBuilder builder) {
  struct State {
    accel::WideBvh<N> wide;
    bool refittable = false;
    bool built = false;
  };
  auto state = std::make_shared<State>();
  Candidate candidate;
  candidate.name = wide_candidate_name(builder, N);
  candidate.build = [state, builder](const accel::TriangleMesh& mesh) {
    const accel::Bvh binary = accel::build_bvh(builder, mesh);
    state->wide = accel::collapse_to_wide<N>(binary, mesh);
    state->refittable = binary.refittable;
    state->built = true;
    return binary.build_ms + state->wide.collapse_ms;
  };
  candidate.refit = [state](const accel::TriangleMesh& mesh) -> std::optional<double> {
    if (!state->built) fail("accel-bench: refit before build");
    if (!state->refittable) return std::nullopt;
    const Stopwatch watch;
    accel::refit(state->wide, mesh);
    return watch.elapsed_ms();
  };
  candidate.trace_closest = [state](std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
    if (!state->built) fail("accel-bench: trace before build");
    accel::trace_closest(state->wide, rays, hits);
  };
  candidate.stats = [state] {
    CandidateStats stats;
    stats.nodes = state->wide.nodes.size();
    stats.memory_bytes = state->wide.nodes.size() * sizeof(accel::WideNode<N>) +
                         state->wide.blocks.size() * sizeof(accel::TriangleBlock<N>);
    return stats;
  };
  return candidate;
}

// The SAH kd-tree (Wald & Havran 2006). Not refittable; its SAH (over cells, kd cost constants) is
// not comparable with the BVHs' and is left out of the table.
Candidate kdtree_candidate() {
  struct State {
    accel::KdTree tree;
    accel::TriangleMesh mesh;
    bool built = false;
  };
  auto state = std::make_shared<State>();
  Candidate candidate;
  candidate.name = "kdtree";
  candidate.build = [state](const accel::TriangleMesh& mesh) {
    state->tree = accel::build_kdtree(mesh);
    state->mesh = mesh;
    state->built = true;
    return state->tree.build_ms;
  };
  candidate.refit = [](const accel::TriangleMesh&) -> std::optional<double> { return std::nullopt; };
  candidate.trace_closest = [state](std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
    if (!state->built) fail("accel-bench: trace before build");
    accel::trace_closest(state->tree, state->mesh, rays, hits);
  };
  candidate.stats = [state] {
    const accel::KdTreeStats stats = accel::compute_stats(state->tree);
    CandidateStats result;
    result.nodes = stats.nodes;
    result.memory_bytes = stats.memory_bytes;
    return result;
  };
  return candidate;
}

Candidate embree_candidate(const rt::EmbreeDevice& device, rt::EmbreeQuality quality) {
  auto scene = std::make_shared<std::unique_ptr<rt::EmbreeScene>>();
  Candidate candidate;
  candidate.name = embree_name(quality);
  candidate.build = [scene, &device, quality](const accel::TriangleMesh& mesh) {
    scene->reset();  // free the old BVH first so the memory monitor counts only the new one
    *scene = std::make_unique<rt::EmbreeScene>(device, mesh, quality);
    return (*scene)->build_ms();
  };
  candidate.refit = [scene, quality](const accel::TriangleMesh& mesh) -> std::optional<double> {
    if (!*scene) fail("accel-bench: refit before build");
    // Only the dynamic-scene quality refits; an update of the others would be a rebuild.
    if (quality != rt::EmbreeQuality::refit) return std::nullopt;
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

std::string cuda_name(accel::BvhBuilder builder) { return "cuda-" + std::string(accel::builder_name(builder)); }

// The same structure traced by the other kernel (cuda/trace_kernel.h), for comparing the two.
std::string cuda_persistent_name(accel::BvhBuilder builder) { return cuda_name(builder) + "-persistent"; }

// A structure on the GPU, traced by the cuda backend's kernel; its times are GPU times (what they
// include: cuda/gpu_bench_structure.h).
// The structures also traced with the persistent kernel: the GPU-built one and the best-SAH one.
constexpr accel::BvhBuilder kPersistentKernelSources[] = {accel::BvhBuilder::lbvh, accel::BvhBuilder::sah};

Candidate cuda_candidate(accel::BvhBuilder builder, cuda::TraceKernel kernel = cuda::kDefaultTraceKernel) {
  auto structure = std::make_shared<std::optional<cuda::GpuBenchStructure>>();
  Candidate candidate;
  candidate.name = kernel == cuda::TraceKernel::persistent ? cuda_persistent_name(builder) : cuda_name(builder);
  candidate.brute_force = builder == accel::BvhBuilder::none;
  candidate.build = [structure, builder, kernel](const accel::TriangleMesh& mesh) {
    if (!*structure) structure->emplace(builder, accel::BuildOptions{}, kernel);
    return (*structure)->build(mesh);
  };
  candidate.refit = [structure](const accel::TriangleMesh& mesh) -> std::optional<double> {
    if (!*structure) fail("accel-bench: refit before build");
    return (*structure)->refit(mesh);
  };
  candidate.trace_closest_timed = [structure](std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
    if (!*structure) fail("accel-bench: trace before build");
    return (*structure)->trace_closest(rays, hits) * 1e-3;
  };
  candidate.trace_closest = [timed = candidate.trace_closest_timed](std::span<const accel::Ray> rays,
                                                                    std::span<accel::Hit> hits) { timed(rays, hits); };
  candidate.stats = [structure] {
    CandidateStats stats;
    if (!*structure) return stats;
    const accel::Bvh bvh = (*structure)->download();
    const accel::BvhStats bvh_stats = accel::compute_stats(bvh);
    stats.nodes = bvh_stats.nodes;
    stats.memory_bytes = (*structure)->memory_bytes();
    stats.sah = bvh_stats.sah_cost;
    return stats;
  };
  return candidate;
}

// The kd-tree built on the CPU and traced on the GPU (cuda/gpu_bench_kdtree.h); not refittable, and
// its SAH (over cells) is left out like the CPU kd-tree's.
Candidate cuda_kdtree_candidate() {
  auto tree = std::make_shared<std::optional<cuda::GpuBenchKdTree>>();
  Candidate candidate;
  candidate.name = "cuda-kdtree";
  candidate.build = [tree](const accel::TriangleMesh& mesh) {
    if (!*tree) tree->emplace();
    return (*tree)->build(mesh);
  };
  candidate.refit = [](const accel::TriangleMesh&) -> std::optional<double> { return std::nullopt; };
  candidate.trace_closest_timed = [tree](std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
    if (!*tree) fail("accel-bench: trace before build");
    return (*tree)->trace_closest(rays, hits) * 1e-3;
  };
  candidate.trace_closest = [timed = candidate.trace_closest_timed](std::span<const accel::Ray> rays,
                                                                    std::span<accel::Hit> hits) { timed(rays, hits); };
  candidate.stats = [tree] {
    CandidateStats stats;
    if (!*tree) return stats;
    const accel::KdTreeStats kd = accel::compute_stats((*tree)->tree());
    stats.nodes = kd.nodes;
    stats.memory_bytes = kd.memory_bytes;
    return stats;
  };
  return candidate;
}

}  // namespace

std::string wide_candidate_name(accel::BvhBuilder builder, int width) {
  std::string name(accel::builder_name(builder));
  name += "-wide";
  name += std::to_string(width);
  return name;
}

std::vector<CandidateEntry> candidate_menu(const rt::EmbreeDevice& device) {
  std::vector<CandidateEntry> menu;
  for (const accel::BvhBuilder builder : accel::kAllBvhBuilders)
    menu.push_back({std::string(accel::builder_name(builder)), [builder] { return bvh_candidate(builder); }});
  menu.push_back({"kdtree", [] { return kdtree_candidate(); }});
  for (const accel::BvhBuilder builder : kWideSources) {
    menu.push_back({wide_candidate_name(builder, 4), [builder] { return wide_candidate<4>(builder); }});
    menu.push_back({wide_candidate_name(builder, 8), [builder] { return wide_candidate<8>(builder); }});
  }
  for (const rt::EmbreeQuality quality : rt::kAllEmbreeQualities)
    menu.push_back({embree_name(quality), [&device, quality] { return embree_candidate(device, quality); }});
  for (const accel::BvhBuilder builder : accel::kAllBvhBuilders)
    menu.push_back({cuda_name(builder), [builder] { return cuda_candidate(builder); }});
  menu.push_back({"cuda-kdtree", [] { return cuda_kdtree_candidate(); }});
  for (const accel::BvhBuilder builder : kPersistentKernelSources)
    menu.push_back(
        {cuda_persistent_name(builder), [builder] { return cuda_candidate(builder, cuda::TraceKernel::persistent); }});
  for (CandidateEntry& entry : optix_candidate_menu()) menu.push_back(std::move(entry));
  return menu;
}

std::vector<std::string> embree_candidate_names() {
  std::vector<std::string> names;
  for (const rt::EmbreeQuality quality : rt::kAllEmbreeQualities) names.push_back(embree_name(quality));
  return names;
}

std::vector<std::string> candidate_names() {
  std::vector<std::string> names;
  for (const accel::BvhBuilder builder : accel::kAllBvhBuilders) names.emplace_back(accel::builder_name(builder));
  names.emplace_back("kdtree");
  for (const accel::BvhBuilder builder : kWideSources) {
    names.push_back(wide_candidate_name(builder, 4));
    names.push_back(wide_candidate_name(builder, 8));
  }
  for (std::string& name : embree_candidate_names()) names.push_back(std::move(name));
  for (std::string& name : cuda_candidate_names()) names.push_back(std::move(name));
  for (std::string& name : optix_candidate_names()) names.push_back(std::move(name));
  return names;
}

std::vector<std::string> cuda_candidate_names() {
  std::vector<std::string> names;
  for (const accel::BvhBuilder builder : accel::kAllBvhBuilders) names.push_back(cuda_name(builder));
  names.emplace_back("cuda-kdtree");
  for (const accel::BvhBuilder builder : kPersistentKernelSources) names.push_back(cuda_persistent_name(builder));
  return names;
}

}  // namespace glint::accel_bench
