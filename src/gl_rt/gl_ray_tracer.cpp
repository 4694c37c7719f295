#include "gl_rt/gl_ray_tracer.h"

#include "accel/builders/builder.h"
#include "accel/bvh_stats.h"
#include "core/error.h"
#include "core/stopwatch.h"
#include "gl/gl_check.h"
#include "gl_rt/gl_rt_bindings.h"
#include "gl_rt/make_gl_ray_tracer.h"
#include "rt/update_decision.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <dlfcn.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace glint::gl_rt {
namespace {

// The tracer compiles shaders and makes buffers on the current context, so it needs one: checked
// before the first GL call, which without a context would crash rather than fail.
void require_gl45_context() {
  // No libEGL in the process: no context was ever made (and epoxy would abort loading it).
  void* egl = dlopen("libEGL.so.1", RTLD_LAZY | RTLD_NOLOAD);
  if (egl == nullptr) fail("--backend gl needs an OpenGL 4.5 context: none was created in this process");
  dlclose(egl);
  if (eglGetCurrentContext() == EGL_NO_CONTEXT)
    fail("--backend gl needs an OpenGL 4.5 context: none is current on this thread");
  if (epoxy_gl_version() < 45) {
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    fail("--backend gl needs an OpenGL 4.5 context: the current one is OpenGL {}", version ? version : "?");
  }
  GLint bindings = 0;
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &bindings);
  if (bindings <= static_cast<GLint>(kHighestBinding))
    fail("--backend gl needs {} shader-storage buffer bindings; this OpenGL has {}", kHighestBinding + 1, bindings);
}

std::vector<accel::Instance> make_instances(const Scene& scene) {
  std::vector<accel::Instance> instances;
  instances.reserve(scene.instances.size());
  for (const Instance& instance : scene.instances) instances.push_back(accel::make_instance(instance.mesh, instance.transform));
  return instances;
}

uint32_t checked_ray_count(std::size_t count) {
  if (count > std::numeric_limits<std::uint32_t>::max()) fail("rt gl: {} rays in one trace, more than 2^32 - 1", count);
  return static_cast<uint32_t>(count);
}

GlBuffer make_flag_buffer() {
  const std::uint32_t zero = 0;
  return create_buffer(sizeof(zero), &zero, GL_DYNAMIC_STORAGE_BIT);
}

}  // namespace

std::unique_ptr<rt::RayTracer> make_gl_ray_tracer() { return std::make_unique<GlRayTracer>(); }

GlRayTracer::Kernel GlRayTracer::make_kernel(const char* name) {
  Kernel kernel{ShaderProgram::from_embedded({name})};
  kernel.ray_base = kernel.program.uniform_location("ray_base");
  kernel.ray_capacity = kernel.program.uniform_location("ray_capacity");
  kernel.tlas_node_count = kernel.program.uniform_location("tlas_node_count");
  // The shader's layout(local_size_x) is the one place the work-group size is set.
  GLint size[3] = {0, 0, 0};
  glGetProgramiv(kernel.program.id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
  if (size[0] < 1 || size[1] != 1 || size[2] != 1)
    fail("rt gl: {} has work groups of {}x{}x{}; the dispatch needs Nx1x1", name, size[0], size[1], size[2]);
  kernel.group_size = static_cast<GLuint>(size[0]);
  return kernel;
}

// The context is checked before the first member touches GL.
GlRayTracer::GlRayTracer(std::uint32_t max_groups_per_dispatch)
    : max_groups_per_dispatch_(max_groups_per_dispatch),
      closest_((require_gl45_context(), make_kernel("gl_rt_closest.comp.glsl"))),
      any_(make_kernel("gl_rt_any.comp.glsl")),
      flag_(make_flag_buffer()) {
  if (max_groups_per_dispatch < 1 || max_groups_per_dispatch > kMaxGroupsPerDispatch)
    fail("rt gl: {} work groups per dispatch; 1 to {} are guaranteed", max_groups_per_dispatch, kMaxGroupsPerDispatch);
  check_gl("rt gl: set-up");
}

void GlRayTracer::require_built(const char* what) const {
  if (!built_) fail("rt gl: {} before build()", what);
}

void GlRayTracer::set_tlas_node_count() {
  for (const Kernel* kernel : {&closest_, &any_})
    glProgramUniform1ui(kernel->program.id(), kernel->tlas_node_count, structures_.tlas_node_count());
}

void GlRayTracer::build(const Scene& scene, const rt::AccelOptions& options) {
  scene.validate();
  if (!(options.auto_rebuild_sah_ratio >= 1.0f))
    fail("rt gl: auto_rebuild_sah_ratio must be >= 1 (got {})", options.auto_rebuild_sah_ratio);
  if (options.blas != rt::BlasKind::bvh) fail("rt gl: the gl backend traces BVHs only; kdtree is a cpu and cuda structure");
  const Stopwatch watch;
  built_ = false;
  options_ = options;
  shape_ = rt::scene_shape(scene);
  blases_.build(scene, options);
  refitted_on_gpu_.assign(scene.meshes.size(), false);
  sah_readback_.reset(scene.meshes.size());
  gpu_refits_ = 0;
  // Binned SAH like the cpu backend's TLAS, whatever the BLAS builder.
  tlas_ = accel::build_tlas(blases_.blases(), make_instances(scene), accel::BvhBuilder::sah, options_.build);
  structures_.upload_all(blases_, tlas_);
  set_tlas_node_count();
  build_ms_ = watch.elapsed_ms();
  last_update_ms_ = 0.0;
  built_ = true;
}

void GlRayTracer::update(const Scene& scene, std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) {
  require_built("update()");
  // Meshes the GPU refitted since their last upload join the dirty ones: their host BVHs and positions
  // are older than the GL buffers', from which the TLAS is built here.
  std::vector<uint32_t> updated(dirty_meshes.begin(), dirty_meshes.end());
  for (uint32_t m = 0; m < refitted_on_gpu_.size(); ++m)
    if (refitted_on_gpu_[m] && std::find(updated.begin(), updated.end(), m) == updated.end()) updated.push_back(m);
  rt::check_update(name(), shape_, scene, updated);
  blases_.check_refittable(updated, policy, name());
  const Stopwatch watch;
  const std::vector<bool> rebuilt = blases_.update(scene, updated, policy);
  // The TLAS is small: built again over the new BLAS boxes and the current transforms (the
  // walkthrough's moving instances), rather than refitted.
  tlas_ = accel::build_tlas(blases_.blases(), make_instances(scene), accel::BvhBuilder::sah, options_.build);
  structures_.upload_update(blases_, updated, rebuilt, tlas_);
  set_tlas_node_count();
  for (uint32_t m : updated) {
    refitted_on_gpu_[m] = false;
    // The host decided on its own measurement; the GPU's, of boxes now replaced, no longer apply.
    sah_readback_.forget(m);
  }
  last_update_ms_ = watch.elapsed_ms();
}

rt::GlTracing::VertexRange GlRayTracer::gl_positions(std::uint32_t mesh) {
  require_built("gl_positions()");
  if (mesh >= structures_.mesh_count())
    fail("rt gl: mesh index {} out of range ({} meshes)", mesh, structures_.mesh_count());
  const GlStructureBuffers::BlasRegion& region = structures_.region(mesh);
  return {structures_.vertices(), std::uint64_t{region.vertex_offset} * sizeof(vec4), region.vertex_count};
}

void GlRayTracer::update_gl(std::span<const std::uint32_t> dirty_meshes, rt::UpdatePolicy policy) {
  require_built("update_gl()");
  std::vector<std::uint32_t> meshes;
  meshes.reserve(dirty_meshes.size());
  std::vector<bool> listed(structures_.mesh_count(), false);
  for (const std::uint32_t m : dirty_meshes) {
    if (m >= structures_.mesh_count())
      fail("rt gl: dirty mesh index {} out of range ({} meshes)", m, structures_.mesh_count());
    // Twice in one dispatch would make four arrivals at its nodes.
    if (!listed[m]) meshes.push_back(m);
    listed[m] = true;
  }
  blases_.check_refittable(meshes, policy, name());
  const Stopwatch watch;
  // automatic: the costs of earlier updates' refits the GPU has measured by now (never waited for).
  if (policy == rt::UpdatePolicy::automatic) sah_readback_.collect();
  std::vector<std::uint32_t> refitted, rebuilt;
  for (const std::uint32_t m : meshes) {
    const rt::BlasUpdate action = rt::decide_blas_update(
        policy, sah_readback_.cost(m), blases_.meshes()[m].sah_at_rebuild, options_.auto_rebuild_sah_ratio);
    (action == rt::BlasUpdate::rebuild ? rebuilt : refitted).push_back(m);
  }
  // Unless the host built a new TLAS over the rebuilt BLASes, the GPU refits it (after rebuilds alone
  // too: its leaves take the rebuilt BLASes' root boxes) with the refitted BLASes.
  const bool new_tlas = rebuild_from_gl_positions(rebuilt, policy == rt::UpdatePolicy::rebuild);
  if (!new_tlas) refit_.refit(structures_, refitted);
  for (const std::uint32_t m : refitted) refitted_on_gpu_[m] = true;
  gpu_refits_ += refitted.size();
  if (policy == rt::UpdatePolicy::automatic)
    (void)sah_readback_.measure(sah_, structures_, refitted, accel::sah_costs(options_.build));
  last_update_ms_ = watch.elapsed_ms();
}

bool GlRayTracer::rebuild_from_gl_positions(std::span<const std::uint32_t> meshes, bool new_tlas) {
  if (meshes.empty()) return false;
  for (const std::uint32_t m : meshes) {
    // A blocking read (the host waits for the deformer's dispatch): rebuild policy pays it every update,
    // automatic only when a cost passed the ratio.
    blases_.rebuild_at(m, structures_.read_positions(m));
    refitted_on_gpu_[m] = false;
    sah_readback_.forget(m);
  }
  // A new TLAS needs every BLAS's box on the host: not while another mesh's boxes live only on the GPU.
  new_tlas = new_tlas && std::find(refitted_on_gpu_.begin(), refitted_on_gpu_.end(), true) == refitted_on_gpu_.end();
  if (new_tlas) tlas_ = accel::build_tlas(blases_.blases(), tlas_.instances, accel::BvhBuilder::sah, options_.build);
  // The rebuilt BLASes' nodes, leaf slots and links, and the TLAS: the new one, or the last one the host
  // built, whose topology the GPU refit keeps (it rewrites every box). Only an sbvh BVH outgrows its
  // region and makes upload_update lay everything out again from the host's copies; sbvh is never
  // refitted, so no mesh then has boxes only on the GPU.
  structures_.upload_update(blases_, meshes, std::vector<bool>(meshes.size(), true), tlas_);
  set_tlas_node_count();
  return new_tlas;
}

void GlRayTracer::dispatch(const Kernel& kernel, GLuint rays, GLuint results, GLuint ray_count,
                           std::uint32_t capacity) const {
  structures_.bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRayBinding, rays);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kResultBinding, results);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRayCountBinding, ray_count);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFlagBinding, flag_.id());
  glProgramUniform1ui(kernel.program.id(), kernel.ray_capacity, capacity);
  kernel.program.use();
  // Launched for the capacity: invocations at or past the count read on the GPU return at once.
  const std::uint64_t rays_per_dispatch = std::uint64_t{max_groups_per_dispatch_} * kernel.group_size;
  for (std::uint64_t base = 0; base < capacity; base += rays_per_dispatch) {
    const std::uint64_t rays_here = std::min<std::uint64_t>(rays_per_dispatch, capacity - base);
    glProgramUniform1ui(kernel.program.id(), kernel.ray_base, static_cast<GLuint>(base));
    glDispatchCompute(static_cast<GLuint>((rays_here + kernel.group_size - 1) / kernel.group_size), 1, 1);
  }
  // Results are read by later passes' shaders, copied or read back (buffer update), or read through
  // a persistent mapping after a fence (client mapped).
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
}

void GlRayTracer::trace_closest_gl(std::uint32_t rays, std::uint32_t hits, std::uint32_t ray_count,
                                   std::uint32_t capacity) {
  require_built("trace_closest_gl()");
  if (capacity == 0) return;
  dispatch(closest_, rays, hits, ray_count, capacity);
  check_gl("rt gl: trace_closest_gl");
}

void GlRayTracer::trace_any_gl(std::uint32_t rays, std::uint32_t occluded, std::uint32_t ray_count,
                               std::uint32_t capacity) {
  require_built("trace_any_gl()");
  if (capacity == 0) return;
  dispatch(any_, rays, occluded, ray_count, capacity);
  check_gl("rt gl: trace_any_gl");
}

void GlRayTracer::bind_inline_tracing(std::uint32_t program) {
  require_built("bind_inline_tracing()");
  // Looked up per call (a name lookup a pass a frame): the caller's program is not the tracer's to
  // remember, and the count changes with every update's TLAS.
  const GLint location = glGetUniformLocation(program, "tlas_node_count");
  if (location < 0)
    fail("rt gl: program {} traces inline but has no tlas_node_count uniform (include gl_rt_traverse.glsl)", program);
  glProgramUniform1ui(program, location, structures_.tlas_node_count());
  structures_.bind();
  // Inline walks set the same flag as the tracer's kernels: check_stack_overflow() covers them too.
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFlagBinding, flag_.id());
  check_gl("rt gl: bind_inline_tracing");
}

void GlRayTracer::check_stack_overflow() const {
  std::uint32_t flag = 0;
  glGetNamedBufferSubData(flag_.id(), 0, sizeof(flag), &flag);
  if (flag == 0) return;
  const std::uint32_t zero = 0;
  glNamedBufferSubData(flag_.id(), 0, sizeof(zero), &zero);
  fail("rt gl: a traversal stack overflowed (a BVH deeper than {} levels, builder {}): those rays' results are "
       "incomplete",
       accel::kMaxBvhDepth, accel::builder_name(options_.builder));
}

void GlRayTracer::trace_host(const Kernel& kernel, std::span<const accel::Ray> rays, std::size_t result_bytes,
                             void* results) const {
  const std::uint32_t count = checked_ray_count(rays.size());
  if (count == 0) return;
  if (count > scratch_capacity_) {
    // Grown by half again, so a series of slightly larger batches does not reallocate every time.
    scratch_capacity_ = std::max<std::size_t>(count, scratch_capacity_ + scratch_capacity_ / 2);
    scratch_rays_ = create_buffer(scratch_capacity_ * sizeof(accel::Ray), nullptr, GL_DYNAMIC_STORAGE_BIT);
    scratch_results_ = create_buffer(scratch_capacity_ * sizeof(accel::Hit), nullptr, GL_DYNAMIC_STORAGE_BIT);
    if (!scratch_count_) scratch_count_ = create_buffer(sizeof(count), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  glNamedBufferSubData(scratch_rays_.id(), 0, static_cast<GLsizeiptr>(rays.size_bytes()), rays.data());
  glNamedBufferSubData(scratch_count_.id(), 0, sizeof(count), &count);
  dispatch(kernel, scratch_rays_.id(), scratch_results_.id(), scratch_count_.id(), count);
  glGetNamedBufferSubData(scratch_results_.id(), 0, static_cast<GLsizeiptr>(count * result_bytes), results);
  check_gl("rt gl: host-side trace");
  check_stack_overflow();
}

void GlRayTracer::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const {
  require_built("trace_closest()");
  if (rays.size() != hits.size()) fail("rt gl: {} rays but room for {} results", rays.size(), hits.size());
  // accel::Hit is the kernel's std430 Hit record (20 bytes, five 4-byte fields).
  trace_host(closest_, rays, sizeof(accel::Hit), hits.data());
}

void GlRayTracer::trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const {
  require_built("trace_any()");
  if (rays.size() != occluded.size()) fail("rt gl: {} rays but {} occlusion results", rays.size(), occluded.size());
  std::vector<std::uint32_t> flags(rays.size());
  trace_host(any_, rays, sizeof(std::uint32_t), flags.data());
  std::transform(flags.begin(), flags.end(), occluded.begin(), [](std::uint32_t flag) { return static_cast<uint8_t>(flag != 0 ? 1 : 0); });
}

std::optional<double> GlRayTracer::sah_drift() const {
  // The meshes whose boxes only the GPU has are measured there, now (the host waits: stats() is read
  // at the end of a run, as the cuda backend's); the host measures its own BVHs.
  std::vector<std::uint32_t> on_gpu;
  for (std::uint32_t m = 0; m < refitted_on_gpu_.size(); ++m)
    if (refitted_on_gpu_[m] && blases_.meshes()[m].deformable) on_gpu.push_back(m);
  std::vector<std::optional<double>> measured(refitted_on_gpu_.size());
  const std::vector<double> costs = sah_.measure_now(structures_, on_gpu, accel::sah_costs(options_.build));
  for (std::size_t i = 0; i < on_gpu.size(); ++i) measured[on_gpu[i]] = costs[i];
  return blases_.sah_drift(measured);
}

rt::RayTracerStats GlRayTracer::stats() const {
  rt::RayTracerStats stats;
  stats.backend = std::string(name());
  stats.build_ms = build_ms_;
  stats.last_update_ms = last_update_ms_;
  stats.rebuilds = blases_.rebuilds();
  stats.refits = blases_.refits() + gpu_refits_;
  stats.blas_sah_drift = sah_drift();
  // GPU memory: the structure buffers, the GPU refit's included (the host keeps its own copy of the
  // BVHs and meshes too).
  stats.memory_bytes = structures_.bytes();
  return stats;
}

}  // namespace glint::gl_rt
