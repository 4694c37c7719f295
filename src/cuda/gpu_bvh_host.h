#pragma once
// The GPU BVH builders (cuda/gpu_bvh_build.h) from plain C++: host meshes in, host BVHs out, for
// tests and benchmarks. No CUDA headers; a build without CUDA throws one clear glint::Error from
// everything that needs the GPU (the builder names work everywhere).
#include "accel/builders/build_options.h"
#include "accel/bvh.h"
#include "accel/triangle_mesh.h"
#include "core/enum_names.h"

#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace glint::cuda {

enum class GpuBvhBuilder {
  lbvh,  // Karras 2012: 30-bit Morton codes with the primitive index as tie-break, CUB radix sort, radix tree
  ploc,  // Meister & Bittner 2018: parallel locally-ordered clustering in Morton order
};

inline constexpr EnumNames<GpuBvhBuilder, 2> kGpuBvhBuilderNames{
    "GPU BVH builder", {{GpuBvhBuilder::lbvh, "lbvh"}, {GpuBvhBuilder::ploc, "ploc"}}};

inline constexpr auto kAllGpuBvhBuilders = kGpuBvhBuilderNames.values();

// "lbvh", "ploc".
inline std::string_view gpu_builder_name(GpuBvhBuilder builder) { return kGpuBvhBuilderNames.name_of(builder); }
// Inverse of gpu_builder_name; glint::Error listing the known names otherwise.
inline GpuBvhBuilder parse_gpu_builder(std::string_view name) { return kGpuBvhBuilderNames.parse(name); }

// A GPU builder with its mesh, boxes, scratch and output kept on the GPU between calls, so repeated
// builds and refits allocate nothing once the sizes were seen (what a per-frame rebuild does).
class GpuBvhSession {
public:
  // Needs a CUDA GPU (glint::Error otherwise); options.ploc_radius >= 1.
  explicit GpuBvhSession(GpuBvhBuilder builder, const accel::BuildOptions& options = {});
  ~GpuBvhSession();
  GpuBvhSession(const GpuBvhSession&) = delete;
  GpuBvhSession& operator=(const GpuBvhSession&) = delete;

  // Uploads `host_mesh`, computes its triangle boxes on the GPU and builds over them; returns the
  // GPU time of the build alone (CUDA events, milliseconds). Waits for the GPU.
  double build(const accel::TriangleMesh& host_mesh);
  // Uploads `bvh` (any builder of the menu; it must be refittable) in place of the last build, so
  // refit() can update it.
  void upload(const accel::Bvh& bvh);
  // Uploads the moved vertices (same triangle count and indices as the mesh the structure was
  // built over) and refits on the GPU, the leaves boxed from the triangles in the same launch
  // (refit_meshes_gpu); returns that launch's GPU time (ms).
  double refit(const accel::TriangleMesh& moved_host_mesh);
  // The current structure copied to the host, with its depth measured on the GPU.
  accel::Bvh download() const;

private:
  struct State;
  std::unique_ptr<State> state_;
};

// One-shot forms of the session, for tests: build over the triangles of a host mesh; refit a
// (CPU- or GPU-built) BVH to moved triangles; the depth of a BVH measured by measure_depth().
accel::Bvh build_bvh_on_gpu(GpuBvhBuilder builder, const accel::TriangleMesh& host_mesh,
                            const accel::BuildOptions& options = {});
accel::Bvh refit_on_gpu(const accel::Bvh& bvh, const accel::TriangleMesh& moved_host_mesh);
// What refit_together_on_gpu leaves: the BVHs after the last pose and each one's arrival counters
// (one per node) as the last refit left them, all 0 when every climb set its counters back (a test
// reads them: a counter left at 1 would only sometimes give a wrong box at the next refit).
struct RefitTogetherResult {
  std::vector<accel::Bvh> bvhs;
  std::vector<std::vector<uint32_t>> arrival_counters;
};
// refit_on_gpu of several BVHs together: for each pose in order, bvhs[i] refitted to pose[i], all in
// one launch of refit_meshes_gpu (later poses reuse the counters the earlier ones left).
RefitTogetherResult refit_together_on_gpu(std::span<const accel::Bvh> bvhs,
                                          std::span<const std::vector<accel::TriangleMesh>> poses);
uint32_t measure_depth_on_gpu(const accel::Bvh& bvh);

}  // namespace glint::cuda
