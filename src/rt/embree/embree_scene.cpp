#include "rt/embree/embree_scene.h"

#include "core/error.h"
#include "core/stopwatch.h"

#include <cstring>
#include <numeric>

namespace glint::rt {
namespace {

RTCBuildQuality build_quality(EmbreeQuality quality) {
  switch (quality) {
    case EmbreeQuality::low: return RTC_BUILD_QUALITY_LOW;
    case EmbreeQuality::medium: return RTC_BUILD_QUALITY_MEDIUM;
    case EmbreeQuality::high: return RTC_BUILD_QUALITY_HIGH;
    case EmbreeQuality::refit: return RTC_BUILD_QUALITY_REFIT;
  }
  return RTC_BUILD_QUALITY_MEDIUM;
}

}  // namespace

EmbreeScene::EmbreeScene(const EmbreeDevice& device, const accel::TriangleMesh& mesh, EmbreeQuality quality)
    : device_(device), quality_(quality), triangle_count_(mesh.triangle_count) {
  const Stopwatch watch;
  const int64_t bytes_before = device.allocated_bytes();
  const bool indexed = mesh.indices != nullptr;
  vertex_count_ = indexed ? mesh.vertex_count : 3 * mesh.triangle_count;
  if (mesh.triangle_count > 0 && mesh.positions == nullptr) fail("embree: mesh has triangles but no positions");

  scene_ = rtcNewScene(device.handle());
  device.check("rtcNewScene");
  // A dynamic scene keeps its BVH layout refittable; static scenes get the faster-to-trace layout.
  // ROBUST: without it Embree's box and triangle tests let rays through shared edges and vertices
  // (hundreds of the grid edge rays in tests/rt/embree/embree_scene_test.cpp), while glint's own
  // traversal is watertight; the reference must answer the same question.
  rtcSetSceneFlags(scene_, (quality == EmbreeQuality::refit ? RTC_SCENE_FLAG_DYNAMIC : RTC_SCENE_FLAG_NONE) |
                               RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, quality == EmbreeQuality::refit ? RTC_BUILD_QUALITY_LOW : build_quality(quality));

  if (mesh.triangle_count > 0) {
    geometry_ = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
    device.check("rtcNewGeometry");
    rtcSetGeometryBuildQuality(geometry_, build_quality(quality));
    vertices_ = static_cast<vec3*>(rtcSetNewGeometryBuffer(geometry_, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           sizeof(vec3), vertex_count_));
    device.check("vertex buffer");
    std::memcpy(vertices_, mesh.positions, sizeof(vec3) * vertex_count_);
    if (indexed) {
      rtcSetSharedGeometryBuffer(geometry_, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices, 0,
                                 3 * sizeof(uint32_t), mesh.triangle_count);
      device.check("shared index buffer");
    } else {
      auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry_, RTC_BUFFER_TYPE_INDEX, 0,
                                                                     RTC_FORMAT_UINT3, 3 * sizeof(uint32_t),
                                                                     mesh.triangle_count));
      device.check("index buffer");
      std::iota(indices, indices + 3 * static_cast<size_t>(mesh.triangle_count), 0u);
    }
    rtcCommitGeometry(geometry_);
    // geomID 0: the only geometry, so Hit.instance is always 0.
    rtcAttachGeometryByID(scene_, geometry_, 0);
    device.check("attach geometry");
  }
  rtcCommitScene(scene_);
  device.check("rtcCommitScene");
  build_bytes_ = device.allocated_bytes() - bytes_before;
  build_ms_ = watch.elapsed_ms();
}

EmbreeScene::~EmbreeScene() {
  if (geometry_ != nullptr) rtcReleaseGeometry(geometry_);
  rtcReleaseScene(scene_);
}

void EmbreeScene::update_vertices(std::span<const vec3> positions) {
  if (positions.size() != vertex_count_)
    fail("embree: update with {} vertices for a geometry of {}", positions.size(), vertex_count_);
  const Stopwatch watch;
  if (geometry_ != nullptr) {
    std::memcpy(vertices_, positions.data(), sizeof(vec3) * vertex_count_);
    rtcUpdateGeometryBuffer(geometry_, RTC_BUFFER_TYPE_VERTEX, 0);
    rtcCommitGeometry(geometry_);
    rtcCommitScene(scene_);
    device_.check("update vertices");
  }
  update_ms_ = watch.elapsed_ms();
}

Aabb EmbreeScene::bounds() const {
  Aabb box;
  if (geometry_ == nullptr) return box;
  RTCBounds b;
  rtcGetSceneBounds(scene_, &b);
  box.extend(vec3(b.lower_x, b.lower_y, b.lower_z));
  box.extend(vec3(b.upper_x, b.upper_y, b.upper_z));
  return box;
}

}  // namespace glint::rt
