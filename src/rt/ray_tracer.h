#pragma once
// The RayTracer interface: what the hybrid renderer calls with the rays of the pixels where
// screen-space reflections failed. Every backend (cpu: glint's own two-level BVH; embree: Embree 3
// instancing; cuda; optix) answers the same closest-hit query with the same hit convention, so the
// shading pass and the image are independent of the backend, and backends can be compared ray by ray;
// and the same occlusion (any-hit) query, for shadow rays.
//
// Hit convention (all backends): hit.instance is the index in Scene::instances, hit.prim the
// triangle's index within that instance's mesh (Scene::meshes[instances[instance].mesh], triangle
// indices[3 prim .. 3 prim + 2]), u, v its barycentrics (point = (1 - u - v) v0 + u v1 + v v2) and
// t is measured along the world ray's unnormalised direction. A miss is Hit{} (prim == kInvalidIndex).
#include "accel/builders/builder.h"
#include "accel/builders/build_options.h"
#include "accel/ray.h"
#include "core/enum_names.h"
#include "rt/blas_structure.h"
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace glint::rt {

// What update() does with the acceleration structure of a mesh whose vertices moved:
// rebuild: build it again from scratch (best traversal, slowest update);
// refit: keep its topology and recompute the boxes (fast, quality decays as the motion grows);
// automatic: refit, then rebuild when the refitted structure got too much worse (see AccelOptions).
enum class UpdatePolicy { rebuild, refit, automatic };

// CLI names (--update): "rebuild", "refit", "auto".
inline constexpr EnumNames<UpdatePolicy, 3> kUpdatePolicyNames{
    "update policy",
    {{UpdatePolicy::rebuild, "rebuild"}, {UpdatePolicy::refit, "refit"}, {UpdatePolicy::automatic, "auto"}}};

inline constexpr auto kAllUpdatePolicies = kUpdatePolicyNames.values();

inline std::string_view update_policy_name(UpdatePolicy policy) { return kUpdatePolicyNames.name_of(policy); }
// Inverse of update_policy_name; glint::Error listing the known names otherwise.
inline UpdatePolicy parse_update_policy(std::string_view name) { return kUpdatePolicyNames.parse(name); }

struct AccelOptions {
  // cpu backend: the builder of every BLAS (the TLAS over instances is always binned SAH: it is
  // small, and it must be refittable whatever the BLAS builder is).
  accel::BvhBuilder builder = accel::BvhBuilder::sah;
  // cpu and cuda backends: kdtree builds an SAH kd-tree per mesh instead of a BVH (`builder` unused;
  // it cannot be refitted, so updates need UpdatePolicy::rebuild); the other backends refuse it.
  BlasKind blas = BlasKind::bvh;
  BlasStructure structure() const { return {blas, builder}; }
  void set_structure(const BlasStructure& structure) {
    blas = structure.kind;
    builder = structure.builder;
  }
  accel::BuildOptions build;
  // UpdatePolicy::automatic (cpu backend): a deformable mesh's BLAS is refitted, and rebuilt when
  // its SAH cost after the refit exceeds this factor times its SAH cost at its last (re)build.
  float auto_rebuild_sah_ratio = 1.3f;
  // cpu backend: trace every BLAS through an 8-wide BVH collapsed from its binary one (SIMD
  // kernels, several times faster); false traces the binary BVHs (kept for comparison). Builders
  // whose BVH cannot be collapsed (sbvh: split references) trace the binary BVH either way.
  bool wide_traversal = true;
  // Backends that build their own structures and offer a choice of them (the backend registry's
  // Backend::structures, e.g. optix: "optix-fasttrace", "optix-fastbuild"): the one to build; empty
  // means the backend's default. Each backend parses its own names (optix/build_preference.h), so rt/
  // knows none of them. Options a backend takes that are no structure live in its own folder
  // (cuda/cuda_ray_tracer.h: the trace kernel).
  std::string backend_structure;
};

struct RayTracerStats {
  double build_ms = 0.0;        // the last build(): every BLAS and the TLAS
  double last_update_ms = 0.0;  // the last update(): dirty BLASes and the TLAS
  uint64_t memory_bytes = 0;    // structures plus the backend's own copy of the geometry
  size_t rebuilds = 0;          // BLAS rebuilds done by update() since build()
  size_t refits = 0;            // BLAS refits kept by update() since build()
  // Max over deformable meshes' BLASes of (SAH cost now) / (SAH cost at its last rebuild): how much
  // refitting has degraded the structures. Absent when there is no deformable mesh or the backend
  // cannot measure it (Embree does not expose its nodes).
  std::optional<double> blas_sah_drift;
  std::string backend;          // "cpu", "embree"
};

class DeviceTracing;
class GlTracing;

class RayTracer {
public:
  virtual ~RayTracer();

  // Builds the structures over every mesh and instance of `scene`, replacing any previous ones.
  // The backend copies what it needs: `scene` may change or go away afterwards.
  // glint::Error for an invalid scene (Scene::validate) or options.
  virtual void build(const Scene& scene, const AccelOptions& options) = 0;

  // After the vertices of `dirty_meshes` moved (same vertex and triangle counts, same indices, e.g.
  // the list SceneDeformers::apply returns), brings the structures up to date with `scene` by
  // `policy`; instance transforms are re-read too. glint::Error before build(), for a mesh index out
  // of range, a changed vertex/triangle count, or a refit of a structure that cannot be refitted.
  virtual void update(const Scene& scene, std::span<const uint32_t> dirty_meshes, UpdatePolicy policy) = 0;

  // hits[i] = closest hit of rays[i] within [t_min, t_max] (convention above). TBB-parallel.
  // glint::Error before build() or when the spans differ in size.
  virtual void trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const = 0;

  // The occlusion query (shadow rays): occluded[i] = 1 when rays[i] hits any triangle with t in
  // [t_min, t_max] (inclusive, as trace_closest), else 0. The traversal stops at the first hit it
  // finds, so which triangle is not known; occluded[i] == 1 exactly when trace_closest would find a
  // hit. TBB-parallel on CPU backends. Same glint::Error rules as trace_closest.
  virtual void trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const = 0;

  virtual RayTracerStats stats() const = 0;
  virtual std::string_view name() const = 0;

  // GPU backends (cuda) also trace rays that already live in GPU memory; CPU backends return null.
  virtual DeviceTracing* device_tracing() { return nullptr; }
  // The gl backend traces rays in GL buffers with OpenGL compute shaders; the others return null.
  virtual GlTracing* gl_tracing() { return nullptr; }
};

// The GL-resident side of the gl backend, which traverses its structures in OpenGL compute shaders
// on the current GL context: the renderer hands it the names of its GL buffers, and the traces are
// GL dispatches ordered with the renderer's other passes by GL itself, so a frame makes no GL-CUDA
// hand-over and the host never waits. Buffers are std430 arrays in accel's layouts (accel::Ray 32
// bytes, accel::Hit 20 bytes); `ray_count` is a GL buffer whose first uint is the number of rays,
// read on the GPU, of which at most `capacity` are traced; slots at or past it are not written.
// Each call ends with the shader-storage and buffer-update barriers its readers need.
class GlTracing {
public:
  virtual ~GlTracing();
  // hits[i] = closest hit of rays[i] (RayTracer::trace_closest's convention).
  virtual void trace_closest_gl(std::uint32_t rays, std::uint32_t hits, std::uint32_t ray_count,
                                std::uint32_t capacity) = 0;
  // occluded[i] = 1 when rays[i] hits anything within [t_min, t_max], else 0: one uint per ray.
  virtual void trace_any_gl(std::uint32_t rays, std::uint32_t occluded, std::uint32_t ray_count,
                            std::uint32_t capacity) = 0;
  // Inline tracing: a render pass's compute shader that includes shaders/include/gl_rt_traverse.glsl
  // walks the structures itself, with rays it makes and answers it uses in the same invocation (no
  // ray list between passes: RayTracedShadows, GlReflectionTrace). This binds the structures (storage
  // bindings 21..24, texture unit 20: above the renderer's) and the stack-overflow flag (28, read by
  // the backend's overflow check) and sets `program`'s tlas_node_count uniform; the caller binds its
  // own buffers, dispatches `program` next (before an update() of the tracer) and places its barriers.
  // glint::Error before the structures are built, or when `program` has no tlas_node_count uniform.
  virtual void bind_inline_tracing(std::uint32_t program) = 0;

  // Where mesh `mesh`'s object-space positions live in the tracer's GL vertex buffer: vertex_count
  // vec4s (w unused) from offset_bytes of buffer `buffer`. A GL-side deformer writes them there (e.g.
  // glCopyNamedBufferSubData of its own vec4 positions) before update_gl(). Ask again every frame: a
  // host update may lay the buffers out anew. glint::Error before build() or out of range.
  struct VertexRange {
    std::uint32_t buffer = 0;
    std::uint64_t offset_bytes = 0;
    std::uint32_t vertex_count = 0;
  };
  virtual VertexRange gl_positions(std::uint32_t mesh) = 0;
  // Like RayTracer::update, after a GL-side deformer rewrote gl_positions() of `dirty_meshes`; the
  // instances keep the transforms of the last build or update. refit: refitted on the GPU (GL compute,
  // enqueued; the host never waits and nothing is copied from the host). automatic: refitted so, the
  // SAH cost measured on the GPU and read back updates later; a mesh whose cost passed the ratio is
  // rebuilt on the host from its positions read back (the host waits for that read). rebuild: every
  // dirty mesh so (correct, slow). A structure that cannot be refitted takes rebuild only, as update().
  virtual void update_gl(std::span<const std::uint32_t> dirty_meshes, UpdatePolicy policy) = 0;
};

// A timed piece of GPU work a DeviceTracing call enqueued (a trace, an update): its GPU time is read
// with gpu_ms() once the GPU has done it, frames later. The backend keeps the work's timing until it
// is read, or let go with drop_ticket(), however much work comes after (cuda/gpu_span_pool.h).
using GpuTicket = std::uint64_t;

// The shadow rays of reflection hits, traced in the same enqueued work as the hits themselves (no GL
// pass between the two traces; see DeviceTracing::trace_closest_and_hit_shadows_device). For every
// slot i < *ray_count with a hit, shadow_rays[i] is the ray from the hit towards `light_position`
// by the rule of shaders/hit_shadow_rays.comp.glsl (the hit point offset by `origin_offset` along
// the triangle's geometric normal turned towards the reflection ray's origin; t in [0, 1 - 1e-4],
// the light at t = 1; an empty ray (t_min > t_max) for a miss or a hit facing away from the light),
// and occluded[i] its trace_any_device answer. Both are device pointers of `capacity` slots.
struct HitShadowRays {
  vec3 light_position{0.0f};
  float origin_offset = 0.0f;
  accel::Ray* shadow_rays = nullptr;
  uint32_t* occluded = nullptr;
};

// The tickets of trace_closest_and_hit_shadows_device: the closest-hit trace, then the shadow rays'
// generation and occlusion trace (each read or dropped, as every ticket).
struct [[nodiscard]] HitAndShadowTickets {
  GpuTicket closest = 0;
  GpuTicket shadows = 0;
};

// The device-resident side of a GPU backend: the hybrid renderer hands it GL buffers mapped into
// CUDA, so rays, hits and vertices never travel through the host during a frame. Every call is
// enqueued on the backend's CUDA stream (stream()) and returns without waiting for the GPU.
class DeviceTracing {
public:
  virtual ~DeviceTracing();

  // The backend's CUDA stream (a cudaStream_t), on which callers order their own GPU work.
  virtual void* stream() = 0;

  // hits[i] = closest hit of rays[i] for i < *ray_count (a device-memory counter, read on the GPU,
  // so the host never waits for it); rays, hits and ray_count are device pointers, and at most
  // `capacity` rays are traced. Same hit convention as RayTracer::trace_closest. The ticket is read
  // (gpu_ms) or dropped (drop_ticket), as every trace's: the backend keeps its timing until then.
  [[nodiscard]] virtual GpuTicket trace_closest_device(const accel::Ray* rays, accel::Hit* hits,
                                                       const uint32_t* ray_count, uint32_t capacity) = 0;
  // The occlusion query of RayTracer::trace_any on device memory: occluded[i] = 1 when rays[i] hits
  // any triangle within [t_min, t_max], else 0, for i < *ray_count (read on the GPU, at most
  // `capacity`), one uint32_t per ray so a GLSL shader reads it as a `uint` array through a shared
  // GL buffer. Slots at or past the count are not written. Enqueued like trace_closest_device.
  [[nodiscard]] virtual GpuTicket trace_any_device(const accel::Ray* rays, uint32_t* occluded,
                                                   const uint32_t* ray_count, uint32_t capacity) = 0;
  // Whether trace_closest_and_hit_shadows_device exists here; without it the caller writes the hits'
  // shadow rays in a GL pass and traces them with trace_any_device (one more GL-CUDA hand-over).
  virtual bool traces_hit_shadows() const { return false; }
  // trace_closest_device, then the hits' shadow rays (HitShadowRays) written and traced, all on the
  // stream. glint::Error where traces_hit_shadows() is false.
  virtual HitAndShadowTickets trace_closest_and_hit_shadows_device(const accel::Ray* rays, accel::Hit* hits,
                                                                   const uint32_t* ray_count, uint32_t capacity,
                                                                   const HitShadowRays& shadows);
  // GPU time in milliseconds of the work `ticket` names (a trace or an update; CUDA events). nullopt
  // while the GPU has not finished it and `wait` is false (wait: blocks until it has). Also reports
  // what the work found wrong (a traversal stack overflow) as glint::Error. A time is read once: the
  // read that returns it frees the ticket's timing, and asking again is glint::Error (as for a
  // ticket never issued or dropped), except for the last update's, which stays until the next.
  virtual std::optional<double> gpu_ms(GpuTicket ticket, bool wait) = 0;
  // The caller will not read `ticket`'s time (a trace it does not time): the backend lets it go.
  // glint::Error for a ticket never issued, read or dropped.
  virtual void drop_ticket(GpuTicket ticket) = 0;

  // Object-space positions of mesh `mesh` in device memory (vertex_count vec3, the backend's own
  // copy), for a GPU deformer to overwrite before update_device(); glint::Error out of range.
  virtual vec3* device_positions(uint32_t mesh) = 0;
  // Like RayTracer::update, after a GPU deformer rewrote device_positions() of `dirty_meshes`:
  // nothing is copied from the host.
  virtual void update_device(std::span<const uint32_t> dirty_meshes, UpdatePolicy policy) = 0;
  // The ticket of the last update or update_device (its GPU time through gpu_ms), or nullopt before
  // the first or when the backend does not time it. The host time of those calls is only their
  // enqueueing. Asking takes the ticket: its timing is kept until read (or dropped); an update whose
  // ticket nobody took is let go at the next (stats() reports the last one's time either way).
  virtual std::optional<GpuTicket> last_update() { return std::nullopt; }
};

// The backends themselves (names, factories, which this binary has) are listed in one place above
// rt/, cuda/, optix/ and gl_rt/: backends/registry.h (backends::make_ray_tracer). rt/ knows none.

}  // namespace glint::rt
