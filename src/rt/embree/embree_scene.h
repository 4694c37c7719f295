#pragma once
// Embree 3 as a reference backend: one triangle geometry in one scene, built at one of Embree's
// quality levels, traced in TBB batches that return glint Hits. The same rays and the same Hit
// convention as glint's own structures, so they can be compared ray by ray.
#include "rt/embree/embree_device.h"
#include "accel/ray.h"
#include "accel/triangle_mesh.h"
#include "core/enum_names.h"

#include <embree3/rtcore.h>

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace glint::rt {

// low/medium/high: RTC_BUILD_QUALITY_LOW/MEDIUM/HIGH of a static scene (a vertex update rebuilds).
// refit: Embree's dynamic-scene pattern (RTC_SCENE_FLAG_DYNAMIC, geometry quality
// RTC_BUILD_QUALITY_REFIT): the first commit builds, every later commit after update_vertices refits.
enum class EmbreeQuality { low, medium, high, refit };

inline constexpr EnumNames<EmbreeQuality, 4> kEmbreeQualityNames{
    "Embree build quality",
    {{EmbreeQuality::low, "low"}, {EmbreeQuality::medium, "medium"}, {EmbreeQuality::high, "high"},
     {EmbreeQuality::refit, "refit"}}};

inline constexpr auto kAllEmbreeQualities = kEmbreeQualityNames.values();

inline std::string_view embree_quality_name(EmbreeQuality quality) { return kEmbreeQualityNames.name_of(quality); }
// Inverse of embree_quality_name; glint::Error listing the known names otherwise.
inline EmbreeQuality parse_embree_quality(std::string_view name) { return kEmbreeQualityNames.parse(name); }

class EmbreeScene {
public:
  // Builds over `mesh`. An indexed mesh's index buffer is shared with Embree (not copied), so it must
  // stay alive and unchanged while this scene lives; vertices are copied into an Embree-owned
  // buffer, because Embree reads the last vertex with a 16-byte load and a caller's tightly packed
  // vec3 array has no padding after it. A pre-gathered soup gets its own index buffer 0, 1, 2, ...
  EmbreeScene(const EmbreeDevice& device, const accel::TriangleMesh& mesh, EmbreeQuality quality);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // New positions for the same vertices (same count and index buffer as at construction: the
  // vertices of an indexed mesh, or 3 per triangle of a soup). With EmbreeQuality::refit the commit
  // refits; with the other qualities it rebuilds. Sets update_ms. glint::Error on a count mismatch.
  void update_vertices(std::span<const vec3> positions);

  // hits[i] = closest hit of rays[i] in [t_min, t_max]: t, instance 0, prim = Embree's primID (the
  // triangle's index in the mesh), u, v with point = (1 - u - v) v0 + u v1 + v v2 (Embree's
  // barycentrics are the same as glint's). Hit{} on a miss. TBB-parallel.
  void trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const;
  // occluded[i] = 1 when anything lies on rays[i] within [t_min, t_max].
  void trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const;

  EmbreeQuality quality() const { return quality_; }
  uint32_t triangle_count() const { return triangle_count_; }
  double build_ms() const { return build_ms_; }    // construction: buffers + first commit
  double update_ms() const { return update_ms_; }  // the last update_vertices (refit or rebuild)
  // Bytes Embree allocated for this scene's build (buffers and BVH), from the device's memory monitor.
  int64_t build_bytes() const { return build_bytes_; }
  Aabb bounds() const;

private:
  const EmbreeDevice& device_;
  EmbreeQuality quality_;
  RTCScene scene_ = nullptr;
  RTCGeometry geometry_ = nullptr;  // null for an empty mesh (Embree rejects zero-sized buffers)
  vec3* vertices_ = nullptr;        // Embree-owned vertex buffer of the geometry
  uint32_t vertex_count_ = 0;
  uint32_t triangle_count_ = 0;
  double build_ms_ = 0.0;
  double update_ms_ = 0.0;
  int64_t build_bytes_ = 0;
};

}  // namespace glint::rt
