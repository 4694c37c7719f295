#include "cuda/gpu_bvh_build.h"

#include "cuda/gpu_lbvh.cuh"
#include "cuda/gpu_ploc.cuh"

#include <algorithm>
#include <string>

namespace glint::cuda {

// Only the chosen builder's part ever gets memory (an unused DeviceBuffer holds none).
struct GpuBvhBuild::Scratch {
  detail::LbvhScratch lbvh;
  detail::PlocScratch ploc;
};

GpuBvhBuild::GpuBvhBuild(GpuBvhBuilder builder, const accel::BuildOptions& options)
    : builder_(builder), options_(options), scratch_(std::make_unique<Scratch>()) {
  if (builder != GpuBvhBuilder::lbvh && builder != GpuBvhBuilder::ploc)
    fail_message("GpuBvhBuild: invalid builder value " + std::to_string(static_cast<int>(builder)));
  if (builder == GpuBvhBuilder::ploc && options.ploc_radius < 1)
    fail_message("GpuBvhBuild: ploc_radius must be at least 1, got " + std::to_string(options.ploc_radius));
}

GpuBvhBuild::~GpuBvhBuild() = default;
GpuBvhBuild::GpuBvhBuild(GpuBvhBuild&&) noexcept = default;
GpuBvhBuild& GpuBvhBuild::operator=(GpuBvhBuild&&) noexcept = default;

GpuBvhBuilder GpuBvhBuild::builder() const { return builder_; }

void GpuBvhBuild::build(const Aabb* prim_boxes, uint32_t count, GpuBvh& out, cudaStream_t stream) {
  // Below 2^31 primitives: node counts (2 count - 1) fit 32 bits, and the LBVH depth bound holds.
  if (count >= (uint32_t{1} << 31))
    fail_message(std::string("GpuBvhBuild (") + std::string(gpu_builder_name(builder_)) + "): " + std::to_string(count) +
                 " primitives, at most 2^31 - 1");
  out.refittable = true;
  if (count == 0) {
    out.nodes.resize(0);
    out.prim_indices.resize(0);
    out.parents.resize(0);
    out.depth = 0;
    return;
  }
  out.nodes.resize(2 * std::size_t{count} - 1);
  out.prim_indices.resize(count);
  out.parents.resize(2 * std::size_t{count} - 1);
  // A tree over count leaves has at most count levels; each builder has its own bound besides.
  switch (builder_) {
    case GpuBvhBuilder::lbvh:
      detail::build_lbvh_gpu(prim_boxes, count, scratch_->lbvh, out, stream);
      out.depth = std::min(count, detail::kLbvhDepthBound);
      break;
    case GpuBvhBuilder::ploc:
      detail::build_ploc_gpu(prim_boxes, count, options_.ploc_radius, scratch_->ploc, out, stream);
      out.depth = std::min(count, accel::kMaxBvhDepth);
      break;
  }
}

}  // namespace glint::cuda
