#pragma once
// The structures accel-bench compares, as a list of entries with one uniform interface. A new
// structure (a kd-tree, a wide BVH, a GPU builder) is one more entry in candidate_menu(); BVH
// builders come from accel::kAllBvhBuilders, so a builder added there appears here unasked.
#include "accel/builders/builder.h"
#include "rt/embree/embree_device.h"
#include "accel/ray.h"
#include "accel/triangle_mesh.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace glint::accel_bench {

struct CandidateStats {
  std::optional<size_t> nodes;   // unknown for Embree, which hides its nodes
  size_t memory_bytes = 0;       // the structure itself (nodes + indices; Embree: what it allocated)
  std::optional<double> sah;     // accel::compute_stats' SAH cost; unknown for Embree
};

// One built structure. The mesh given to build() must stay alive (and keep its index buffer) until
// the next build; refit and trace use it.
struct Candidate {
  std::string name;
  // Tracing tests every triangle: the bench skips timing it when rays x triangles is huge.
  bool brute_force = false;
  // (Re)builds over the mesh; returns the build time in ms.
  std::function<double(const accel::TriangleMesh&)> build;
  // Refits the last build to the mesh's moved vertices (same triangles); returns ms, or nullopt when
  // this structure cannot refit (then the bench only rebuilds it).
  std::function<std::optional<double>(const accel::TriangleMesh&)> refit;
  std::function<void(std::span<const accel::Ray>, std::span<accel::Hit>)> trace_closest;
  // GPU structures time their own kernel (CUDA events, rays resident on the device) and return its
  // seconds; the bench then uses those instead of the wall time of trace_closest. Empty for CPU ones.
  std::function<double(std::span<const accel::Ray>, std::span<accel::Hit>)> trace_closest_timed;
  std::function<CandidateStats()> stats;
};

// A named way to make fresh, unbuilt candidates (the deformation benchmark needs two of each: one
// refitted, one rebuilt every frame).
struct CandidateEntry {
  std::string name;
  std::function<Candidate()> make;
};

// Every known structure: each accel::kAllBvhBuilders builder by its builder_name, "kdtree", the wide
// BVHs, "embree-low", "embree-medium", "embree-high", "embree-refit", then the GPU structures
// "cuda-<builder>" for every builder (cuda/gpu_bench_structure.h) and "cuda-kdtree"
// (cuda/gpu_bench_kdtree.h; making one fails with one clear line without CUDA or a GPU), then
// "optix-fasttrace" and "optix-fastbuild" (candidates_optix.h).
// `device` must outlive the candidates.
std::vector<CandidateEntry> candidate_menu(const rt::EmbreeDevice& device);

// The names candidate_menu() has, without needing a device (for validating command lines).
// The binary builders whose BVHs the menu also offers collapsed to 4 and 8 wide ("sah-wide8", ...):
// the best-quality refittable ones, so the wide rows answer "how fast can glint trace".
inline constexpr accel::BvhBuilder kWideSources[] = {accel::BvhBuilder::sah, accel::BvhBuilder::trbvh};
std::string wide_candidate_name(accel::BvhBuilder builder, int width);

std::vector<std::string> candidate_names();
// "cuda-<builder>" for every accel::kAllBvhBuilders builder, "cuda-kdtree", then
// "cuda-lbvh-persistent" and "cuda-sah-persistent" (the same BVHs traced by the persistent-threads
// kernel, cuda/trace_kernel.h): what `--backend cuda --builders all` runs.
std::vector<std::string> cuda_candidate_names();
std::vector<std::string> embree_candidate_names();

}  // namespace glint::accel_bench
