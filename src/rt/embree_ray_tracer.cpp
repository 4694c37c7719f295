#include "rt/embree_ray_tracer.h"

#include "rt/embree/embree_ray.h"
#include "accel/trace.h"
#include "core/error.h"
#include "core/stopwatch.h"

#include <glm/gtc/type_ptr.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>

namespace glint::rt {
namespace {

// Rays per TBB task, the grain of accel's batches.
constexpr size_t kRayGrain = 64;

}  // namespace

EmbreeRayTracer::EmbreeRayTracer() : device_(std::make_unique<EmbreeDevice>()) {}

EmbreeRayTracer::~EmbreeRayTracer() { release(); }

void EmbreeRayTracer::release() {
  // Embree reference-counts: releasing the top scene and the instance geometries drops their
  // references to the mesh scenes, which are released after them.
  if (top_ != nullptr) rtcReleaseScene(top_);
  top_ = nullptr;
  for (RTCGeometry instance : instances_) rtcReleaseGeometry(instance);
  instances_.clear();
  for (MeshScene& mesh : meshes_) {
    if (mesh.geometry != nullptr) rtcReleaseGeometry(mesh.geometry);
    rtcReleaseScene(mesh.scene);
  }
  meshes_.clear();
}

void EmbreeRayTracer::require_built(const char* what) const {
  if (top_ == nullptr) fail("rt embree: {} before build()", what);
}

void EmbreeRayTracer::set_instance_transforms(const Scene& scene) {
  for (size_t i = 0; i < instances_.size(); ++i) {
    // glm stores matrices column by column, Embree's FLOAT4X4_COLUMN_MAJOR layout.
    rtcSetGeometryTransform(instances_[i], 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, glm::value_ptr(scene.instances[i].transform));
    rtcCommitGeometry(instances_[i]);
  }
  device_->check("instance transforms");
}

void EmbreeRayTracer::build(const Scene& scene, const AccelOptions& /*options: the cpu backend's builders*/) {
  scene.validate();
  const Stopwatch watch;
  release();
  shape_ = scene_shape(scene);
  const RTCDevice device = device_->handle();

  meshes_.resize(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& source = scene.meshes[m];
    MeshScene& mesh = meshes_[m];
    mesh.deformable = source.deformable;
    mesh.scene = rtcNewScene(device);
    device_->check("rtcNewScene");
    // ROBUST: Embree's default tests let rays slip through shared edges (see rt/embree/embree_scene.cpp).
    rtcSetSceneFlags(mesh.scene, (mesh.deformable ? RTC_SCENE_FLAG_DYNAMIC : RTC_SCENE_FLAG_NONE) | RTC_SCENE_FLAG_ROBUST);
    // A dynamic scene at scene quality MEDIUM is rebuilt by every commit (measured: refits cost as
    // much as rebuilds); at LOW, Embree honours the geometry's REFIT quality.
    rtcSetSceneBuildQuality(mesh.scene, mesh.deformable ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_MEDIUM);
    if (source.triangle_count() > 0) {
      mesh.geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
      device_->check("rtcNewGeometry");
      // A deformable mesh's first commit builds; later commits at REFIT refit (Embree's dynamic pattern).
      rtcSetGeometryBuildQuality(mesh.geometry, mesh.deformable ? RTC_BUILD_QUALITY_REFIT : RTC_BUILD_QUALITY_MEDIUM);
      // Embree-owned buffers: the caller's scene may change or go away, and Embree reads the last
      // vertex with a 16-byte load that a packed vec3 array does not pad for.
      mesh.vertices = static_cast<vec3*>(rtcSetNewGeometryBuffer(mesh.geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                 RTC_FORMAT_FLOAT3, sizeof(vec3), source.vertex_count()));
      auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
          mesh.geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), source.triangle_count()));
      device_->check("geometry buffers");
      std::memcpy(mesh.vertices, source.positions.data(), sizeof(vec3) * source.vertex_count());
      std::memcpy(indices, source.indices.data(), sizeof(uint32_t) * source.indices.size());
      rtcCommitGeometry(mesh.geometry);
      rtcAttachGeometryByID(mesh.scene, mesh.geometry, 0);
      device_->check("attach mesh geometry");
    }
    rtcCommitScene(mesh.scene);
    device_->check("commit mesh scene");
  }

  top_ = rtcNewScene(device);
  device_->check("rtcNewScene (top level)");
  // DYNAMIC: every update re-commits the instances; the top level is small, LOW builds it fastest.
  rtcSetSceneFlags(top_, RTC_SCENE_FLAG_DYNAMIC | RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(top_, RTC_BUILD_QUALITY_LOW);
  instances_.reserve(scene.instances.size());
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    device_->check("rtcNewGeometry (instance)");
    instances_.push_back(instance);
    rtcSetGeometryInstancedScene(instance, meshes_[scene.instances[i].mesh].scene);
    rtcSetGeometryTimeStepCount(instance, 1);
    // geomID = the Scene::instances index: Embree's instID[0] is then hit.instance.
    rtcAttachGeometryByID(top_, instance, static_cast<unsigned>(i));
  }
  set_instance_transforms(scene);
  rtcCommitScene(top_);
  device_->check("commit top-level scene");
  build_ms_ = watch.elapsed_ms();
  last_update_ms_ = 0.0;
  rebuilds_ = refits_ = 0;
}

void EmbreeRayTracer::update(const Scene& scene, std::span<const uint32_t> dirty_meshes, UpdatePolicy policy) {
  require_built("update()");
  check_update(name(), shape_, scene, dirty_meshes);
  const Stopwatch watch;
  for (uint32_t m : dirty_meshes) {
    MeshScene& mesh = meshes_[m];
    if (mesh.geometry != nullptr) {
      std::memcpy(mesh.vertices, scene.meshes[m].positions.data(), sizeof(vec3) * scene.meshes[m].vertex_count());
      rtcUpdateGeometryBuffer(mesh.geometry, RTC_BUFFER_TYPE_VERTEX, 0);
    }
    // Only a dynamic scene can be refitted; a static one is always built anew by its commit.
    const bool refit = mesh.deformable && policy != UpdatePolicy::rebuild;
    if (mesh.geometry != nullptr) {
      rtcSetGeometryBuildQuality(mesh.geometry, refit ? RTC_BUILD_QUALITY_REFIT : RTC_BUILD_QUALITY_MEDIUM);
      rtcCommitGeometry(mesh.geometry);
    }
    rtcCommitScene(mesh.scene);
    device_->check("commit updated mesh scene");
    ++(refit ? refits_ : rebuilds_);
  }
  // Instances of changed scenes must be committed again for the top level to see the new bounds;
  // re-reading every transform also follows moved instances.
  set_instance_transforms(scene);
  rtcCommitScene(top_);
  device_->check("commit top-level scene");
  last_update_ms_ = watch.elapsed_ms();
}

void EmbreeRayTracer::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const {
  require_built("trace_closest()");
  accel::check_batch_sizes(rays.size(), hits.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (size_t i = range.begin(); i != range.end(); ++i) {
      RTCRayHit query;
      query.ray = embree_ray(rays[i]);
      query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(top_, &context, &query);
      accel::Hit hit;
      if (query.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        // Embree transforms the ray into the instance's space unnormalised, so tfar is the world t.
        hit.t = query.ray.tfar;
        hit.instance = query.hit.instID[0];
        hit.prim = query.hit.primID;
        hit.u = query.hit.u;
        hit.v = query.hit.v;
      }
      hits[i] = hit;
    }
  });
  device_->check("trace_closest");
}

void EmbreeRayTracer::trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const {
  require_built("trace_any()");
  accel::check_batch_sizes(rays.size(), occluded.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (size_t i = range.begin(); i != range.end(); ++i) {
      RTCRay query = embree_ray(rays[i]);
      // Embree's occlusion query stops at the first hit and marks it by setting tfar to -infinity.
      rtcOccluded1(top_, &context, &query);
      occluded[i] = query.tfar == -accel::kInfinity ? 1 : 0;
    }
  });
  device_->check("trace_any");
}

RayTracerStats EmbreeRayTracer::stats() const {
  RayTracerStats stats;
  stats.backend = std::string(name());
  stats.build_ms = build_ms_;
  stats.last_update_ms = last_update_ms_;
  stats.rebuilds = rebuilds_;
  stats.refits = refits_;
  stats.memory_bytes = static_cast<uint64_t>(std::max<int64_t>(0, device_->allocated_bytes()));
  return stats;
}

}  // namespace glint::rt
