#pragma once
// The gl backend: glint's own two-level structure traversed in OpenGL compute shaders on the GL
// context the renderer already uses, so a frame's traces are GL dispatches ordered with its other
// passes by GL itself: no CUDA, no GL-CUDA hand-over, and it runs wherever OpenGL 4.5 does (NVIDIA,
// AMD, Intel, Mesa's llvmpipe). docs/ray-tracer.md "gl".
//
// Structures: one BLAS per mesh built on the CPU with AccelOptions::builder and a binned-SAH TLAS
// over Scene::instances, as the cpu backend (mesh_blases.h), flattened into GL buffers
// (gl_structure_buffers.h). update() rebuilds or refits the dirty BLASes on the CPU by policy, builds
// the TLAS again and uploads only the dirty meshes' ranges and the TLAS. update_gl() (GlTracing), after
// a GL-side deformer wrote the positions into gl_positions(), refits the BLASes and the TLAS on the GPU
// instead (gl_refit.h): no host refit, no upload, nothing waits. Under the automatic policy the GPU
// also measures each refitted BLAS's SAH cost (gl_sah_cost.h), read back updates later without a
// wait (gl_sah_readback.h); the update that finds a cost past the ratio reads that mesh's positions
// back and rebuilds it on the host, as the rebuild policy does every update.
//
// Tracing: shaders/gl_rt_closest.comp.glsl and gl_rt_any.comp.glsl, one invocation per ray, walking
// the TLAS and each BLAS entered the way accel/traverse.h does with accel's watertight triangle test
// (shaders/include/gl_rt_traverse.glsl), so hits follow RayTracer's convention and equal the cpu
// backend's up to rounding. GlTracing (gl_tracing()) traces rays already in GL buffers; the host
// trace_closest/trace_any stage the rays through scratch GL buffers and read the results back (for
// tests and benchmarks).
//
// Every call needs the GL context that was current when the tracer was made, current again (so the
// host-side traces, though const, are for one thread at a time); GL objects die with the tracer,
// which must die before that context. A trace binds shader-storage
// buffers at bindings 20..28 (gl_rt_bindings.h) and its program; the renderer's bindings are lower.
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "gl_rt/gl_refit.h"
#include "gl_rt/gl_sah_cost.h"
#include "gl_rt/gl_sah_readback.h"
#include "gl_rt/gl_structure_buffers.h"
#include "gl_rt/mesh_blases.h"
#include "rt/ray_tracer.h"
#include "rt/scene_shape.h"

#include <cstdint>
#include <optional>

namespace glint::gl_rt {

class GlRayTracer final : public rt::RayTracer, public rt::GlTracing {
public:
  // GL guarantees at least this many work groups per dispatch; a longer ray list takes several.
  static constexpr std::uint32_t kMaxGroupsPerDispatch = 65535;

  // Compiles the two kernels on the current context; glint::Error ("--backend gl needs an OpenGL
  // 4.5 context: ...") when no OpenGL 4.5 context is current on this thread. A trace dispatches at
  // most `max_groups_per_dispatch` work groups (of the kernel's local size) at a time (tests lower it to split short
  // lists too).
  explicit GlRayTracer(std::uint32_t max_groups_per_dispatch = kMaxGroupsPerDispatch);

  void build(const Scene& scene, const rt::AccelOptions& options) override;
  // The host path (--deform-on cpu). Meshes refitted on the GPU since their last host update are
  // updated from `scene` too, dirty or not: the host's copy of their BVHs is older than the GPU's.
  void update(const Scene& scene, std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) override;
  // Stage the rays in a scratch GL buffer, dispatch, read back (the host waits for the GPU). Also
  // glint::Error when a traversal stack overflowed in this or an unchecked earlier GL-side trace.
  void trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const override;
  void trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const override;
  rt::RayTracerStats stats() const override;
  std::string_view name() const override { return "gl"; }
  rt::GlTracing* gl_tracing() override { return this; }

  // rt::GlTracing: dispatches only (the host never waits); capacity 0 does nothing.
  void trace_closest_gl(std::uint32_t rays, std::uint32_t hits, std::uint32_t ray_count,
                        std::uint32_t capacity) override;
  void trace_any_gl(std::uint32_t rays, std::uint32_t occluded, std::uint32_t ray_count,
                    std::uint32_t capacity) override;
  void bind_inline_tracing(std::uint32_t program) override;
  // rt::GlTracing: the vertex range of `mesh`; update_gl by policy (a duplicate in the list counts
  // once): refit enqueues the GPU refit (GlRefit) of the dirty meshes' BLASes and the TLAS; automatic
  // refits the same way and measures each refitted BLAS's SAH cost on the GPU, and rebuilds a mesh
  // whose cost, measured one or more updates before (the latest the GPU had finished: never waited
  // for), passed auto_rebuild_sah_ratio x its cost right after its last build; rebuild rebuilds every
  // dirty mesh. A rebuild reads the mesh's positions back (the host waits for the GPU), builds with
  // AccelOptions::builder on the host and uploads it; rebuild builds the TLAS anew too, automatic refits
  // it on the GPU. stats() counts GPU refits and host rebuilds; last_update_ms is the host's part
  // (enqueueing, and any rebuild's read, build and upload).
  VertexRange gl_positions(std::uint32_t mesh) override;
  void update_gl(std::span<const std::uint32_t> dirty_meshes, rt::UpdatePolicy policy) override;

  // Reads the stack-overflow flag the GL-side traces since the last check set (waits for them) and
  // clears it: glint::Error when a walk would have pushed past 64 entries (a BVH deeper than
  // accel::kMaxBvhDepth; glint's builders stay within it, so this is a safety net).
  void check_stack_overflow() const;

  // The GL buffers and where each BLAS lives in them: for tests, which read the nodes back.
  const GlStructureBuffers& structures() const { return structures_; }

private:
  // A compiled kernel and its uniforms' locations.
  struct Kernel {
    ShaderProgram program;
    GLint ray_base = -1, ray_capacity = -1, tlas_node_count = -1;
    GLuint group_size = 0;  // the shader's local_size_x: rays per work group
  };
  static Kernel make_kernel(const char* name);

  void require_built(const char* what) const;
  // update_gl's host rebuild of GPU-posed meshes: their positions read back, BLASes built with the
  // configured builder, uploaded. With `new_tlas`, also a TLAS built anew, where every BLAS's boxes are
  // on the host; returns whether it was (else the caller refits the TLAS on the GPU).
  bool rebuild_from_gl_positions(std::span<const std::uint32_t> meshes, bool new_tlas);
  // RayTracerStats::blas_sah_drift: the host's BVHs measured on the host, GPU-refitted ones on the GPU.
  std::optional<double> sah_drift() const;
  void set_tlas_node_count();
  // Binds the structures and the call's buffers and dispatches `kernel` over `capacity` rays (in
  // pieces of at most max_groups_per_dispatch_ work groups), then the barriers the results' readers
  // need.
  void dispatch(const Kernel& kernel, GLuint rays, GLuint results, GLuint ray_count, std::uint32_t capacity) const;
  // Host-side traces: uploads `rays`, dispatches, reads `result_bytes` per ray into `results`.
  void trace_host(const Kernel& kernel, std::span<const accel::Ray> rays, std::size_t result_bytes, void* results) const;

  std::uint32_t max_groups_per_dispatch_;
  Kernel closest_;
  Kernel any_;
  GlBuffer flag_;  // one uint: a stack overflowed
  GlRefit refit_;
  mutable GlSahCost sah_;       // stats() measures with it too
  GlSahReadback sah_readback_;  // automatic: the GPU's costs of refitted BLASes, read updates late
  rt::AccelOptions options_;
  rt::SceneShape shape_;
  MeshBlases blases_;
  accel::Tlas tlas_;
  GlStructureBuffers structures_;
  // Per mesh: refitted on the GPU since its last host upload (its host BVH and positions are stale).
  std::vector<bool> refitted_on_gpu_;
  std::size_t gpu_refits_ = 0;  // BLAS refits by update_gl since build()
  bool built_ = false;
  double build_ms_ = 0.0;
  double last_update_ms_ = 0.0;
  // Scratch buffers of the host-side traces, grown as needed.
  mutable GlBuffer scratch_rays_, scratch_results_, scratch_count_;
  mutable std::size_t scratch_capacity_ = 0;  // rays
};

}  // namespace glint::gl_rt
