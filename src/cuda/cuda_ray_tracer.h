#pragma once
// The cuda backend of rt::RayTracer: glint's own two-level structure in GPU memory, traced by a CUDA
// kernel, and its rt::DeviceTracing side for the hybrid renderer (rays, hits and the ray count stay
// in GL buffers shared with CUDA; deformed vertices arrive from the GPU deformer).
//
// Structures (AccelOptions::builder): lbvh and ploc are built on the GPU (cuda/gpu_bvh_build.h)
// from the mesh's device vertices, so a deforming mesh is rebuilt without leaving the GPU; every
// other builder of the menu (none, median, sah, sbvh, trbvh) is built on the CPU and uploaded in the
// same node layout (after a GPU deformation its vertices are read back for that, once per rebuild).
// Refit runs on the GPU for every refittable structure. The TLAS over instances is an LBVH built on
// the GPU from the instances' world boxes at build(), refitted by update() (rebuilt when the
// policy is rebuild). Automatic policy: refit, and rebuild a mesh when its SAH cost, measured on the
// GPU after its previous refit and read back one update later (so the host never waits for it),
// exceeded auto_rebuild_sah_ratio x its cost at its last rebuild.
//
// Plain C++ (no CUDA headers). A build without CUDA, or a machine without a CUDA GPU, gets one
// glint::Error from make_cuda_ray_tracer().
#include "cuda/trace_kernel.h"
#include "rt/ray_tracer.h"

#include <memory>

namespace glint::cuda {

// The cuda backend's own options (rt::AccelOptions holds what every backend of glint's builders takes).
struct CudaTracerOptions {
  TraceKernel trace_kernel = kDefaultTraceKernel;  // which closest-hit kernel traces the ray lists
};

std::unique_ptr<rt::RayTracer> make_cuda_ray_tracer(const CudaTracerOptions& options = {});

}  // namespace glint::cuda
