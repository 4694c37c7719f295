#pragma once
// Screen-space reach (issue 21, docs/hybrid.md "Screen-space reach"): how many of a frame's
// reflective pixels any screen-space method could answer at all. Each reflective pixel's exact
// mirror ray (from the G-buffer position and normal, as the ray list builds it) is traced with a
// RayTracer, and its closest hit is classified against the frame itself:
//   on_screen   the hit lies in the view frustum and the G-buffer shows that very surface there;
//   off_screen  outside the view frustum: beside the viewport, behind the camera, nearer than the
//               near plane or beyond the far one;
//   occluded    inside the frustum, but the frame shows another surface there: nearer geometry, the
//               hit surface's other side (the camera sees it from behind), or a sliver the raster
//               missed;
//   miss        nothing hit (the sky); miss_leaving_view counts those whose direction leaves the
//               view, so no screen-space march can prove the miss.
// off_screen + occluded is a lower bound on the rays a screen-space-first method must trace for an
// exact mirror image (misses need none only if it reports a miss correctly). Of those, the ones whose
// hit lies nearer than the resolve's fade end are the ones the final image shows (the others fade to
// nothing, so any answer at least that far away gives the same picture).
//
// "Shows that surface": the visibility id there equals the hit's {instance, triangle} (when the
// ids are given), or, in the pixel under the hit or one of its 8 neighbours, the surface's tangent
// plane (G-buffer position and normal) meets the camera ray through the hit within
// kReachDepthTolerance of the hit's view depth. Every test is a ratio of depths, so a scene scaled by
// 1000 or moved far from the origin classifies its pixels the same.
#include "core/image.h"
#include "render/frame_constants.h"
#include "rt/ray_tracer.h"
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace glint::render {

// How far the G-buffer's surface may be from the hit along the camera ray, as a fraction of the
// hit's view depth: SSR's default thickness (ssr_settings.h), float rounding and curvature within a pixel.
inline constexpr float kReachDepthTolerance = 0.01f;

enum class ReachClass : std::uint8_t { not_reflective, on_screen, off_screen, occluded, miss };

// A frame's G-buffer on the host, top row first (as RasterPipeline::read_rgbaf gives it), all the
// same size. Reflective pixels are those with world_position.w != 0 and albedo_reflectivity.a > 0
// (the ray list's rule).
struct ReachGBuffer {
  const ImageRgbaF& world_position;       // xyz world position, w = 1 where geometry was drawn
  const ImageRgbaF& world_normal;         // xyz shading normal as authored
  const ImageRgbaF& albedo_reflectivity;  // a = reflectivity
  // Optional (visibility G-buffer): x = instance + 1 (0 = background), y = triangle in its mesh.
  const ImageRgbaF* visibility_ids = nullptr;
};

struct ScreenSpaceReach {
  std::size_t reflective = 0;
  std::size_t on_screen = 0;
  std::size_t off_screen = 0;
  std::size_t occluded = 0;
  std::size_t miss = 0;
  std::size_t miss_leaving_view = 0;  // of miss
  std::size_t must_trace_within_fade = 0;  // of must_trace(): hits nearer than fade_end (all without a fade)
  std::vector<ReachClass> classes;    // per pixel, top row first

  // The lower bound: reflective pixels no screen-space method can answer from this frame.
  std::size_t must_trace() const { return off_screen + occluded; }
  // count / reflective in percent (0 without reflective pixels).
  double percent(std::size_t count) const;
};

// Traces the mirror ray of every reflective pixel with `tracer` (built over `scene` as it is this
// frame) from the G-buffer position moved `origin_offset` along the normal turned towards the camera
// (ray_origin_offset.h), and classifies it against `frame`'s camera (camera_position,
// relative_view_projection), which maps onto the images' size. `fade_end`: the resolve's distance
// fade end in world units (resolve_settings.h); <= 0: no fade. glint::Error when the images differ
// in size.
ScreenSpaceReach measure_screen_space_reach(const Scene& scene, const rt::RayTracer& tracer,
                                            const ReachGBuffer& gbuffer, const FrameConstants& frame,
                                            float origin_offset, float fade_end = 0.0f);

}  // namespace glint::render
