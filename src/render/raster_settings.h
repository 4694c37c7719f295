#pragma once
// Tunables of the raster passes. Shadow sizes are in cube-map texels at the receiver's distance, so
// they scale with distance from the light and with shadow_map_size (docs/render.md explains them).
#include "core/enum_names.h"

#include <string_view>

namespace glint::render {

// How the shadow cube map's six faces are drawn (both give the same depths, tests check it):
//   per_face  six draws of the scene, each into one face with that face's projection
//   layered   one draw; a geometry shader sends each triangle to the faces it may touch
// per_face is the default: on the H100, geometry-shader amplification cost more than drawing the
// scene six times (docs/perf.md, "Shadow cube map").
enum class ShadowCubeDraw { per_face, layered };

inline constexpr EnumNames<ShadowCubeDraw, 2> kShadowCubeDrawNames{
    "shadow cube draw", {{ShadowCubeDraw::per_face, "per-face"}, {ShadowCubeDraw::layered, "layered"}}};

// "per-face", "layered"; parse_shadow_cube_draw is the inverse (glint::Error naming the known ones).
inline std::string_view shadow_cube_draw_name(ShadowCubeDraw draw) { return kShadowCubeDrawNames.name_of(draw); }
inline ShadowCubeDraw parse_shadow_cube_draw(std::string_view name) { return kShadowCubeDrawNames.parse(name); }

// How the G-buffer is made (both give the same images; tests/render/visibility_gbuffer_test.cpp):
//   raster      one draw whose fragment shader interpolates, samples textures and writes every image
//   visibility  one draw writing only depth and a {instance, triangle} id, then one compute pass that
//               rebuilds every image from the ids and the scene buffers (docs/render.md)
// RasterSettings keeps raster, the paper's pipeline (glint bench's default too); glint render defaults
// to visibility, the faster one on both machines: 1.16 against 1.98 ms on the H100 (atrium,
// 1280x720), 40 against 64 ms on llvmpipe (atrium-simple, 320x180); docs/perf.md, "GPU-first frame".
enum class GBufferMethod { raster, visibility };

inline constexpr EnumNames<GBufferMethod, 2> kGBufferMethodNames{
    "G-buffer method", {{GBufferMethod::raster, "raster"}, {GBufferMethod::visibility, "visibility"}}};

// "raster", "visibility"; parse_gbuffer_method is the inverse (glint::Error naming the known ones).
inline std::string_view gbuffer_method_name(GBufferMethod method) { return kGBufferMethodNames.name_of(method); }
inline GBufferMethod parse_gbuffer_method(std::string_view name) { return kGBufferMethodNames.parse(name); }

// How the visibility G-buffer's ids are made (only with GBufferMethod::visibility):
//   raster     VisibilityIdPass draws every instance
//   rt         one camera ray per pixel centre through the frame's ray tracer (PrimaryRayPass), whose
//              closest hits become the ids; the depth target is not written (no frame pass reads it).
//              An experiment (issue 19 item 4): on the H100 the G-buffer pass took 0.86 instead of
//              1.16 ms, but the frame was not faster at 1280x720 (the camera rays add a CUDA-GL
//              hand-over; docs/render.md, "Ray-traced primary visibility")
//   compute    a compute-shader rasteriser (ComputeVisibilityPass) writes the same ids and depth:
//              compute work runs on every SM, vertex/fragment work on few of the H100's (docs/render.md,
//              "Compute-rasterised primary visibility")
//   automatic  raster or compute, whichever makes this scene's ids faster on this GL device: on a GPU
//              both are timed on the first frame and compute must win by a quarter; Mesa's software
//              rasterisers keep the id draw untimed (primary_visibility_choice.h says why). On the
//              H100 compute wins (0.17 against 1.16 ms, atrium 1280x720) because only 4 of its 132
//              SMs run fragment shaders. glint render's default.
enum class PrimaryVisibility { raster, rt, compute, automatic };

inline constexpr EnumNames<PrimaryVisibility, 4> kPrimaryVisibilityNames{
    "primary visibility",
    {{PrimaryVisibility::raster, "raster"},
     {PrimaryVisibility::rt, "rt"},
     {PrimaryVisibility::compute, "compute"},
     {PrimaryVisibility::automatic, "auto"}}};

// "raster", "rt", "compute", "auto"; parse_primary_visibility is the inverse (glint::Error naming the known ones).
inline std::string_view primary_visibility_name(PrimaryVisibility primary) {
  return kPrimaryVisibilityNames.name_of(primary);
}
inline PrimaryVisibility parse_primary_visibility(std::string_view name) { return kPrimaryVisibilityNames.parse(name); }

struct RasterSettings {
  int shadow_map_size = 1024;         // cube face side in texels
  ShadowCubeDraw shadow_cube_draw = ShadowCubeDraw::per_face;
  GBufferMethod gbuffer = GBufferMethod::raster;
  // rt, compute: need gbuffer visibility (rt: and a tracer); automatic: chooses with gbuffer visibility,
  // means nothing with raster (RasterSettings keeps raster: the same ids on every machine)
  PrimaryVisibility primary = PrimaryVisibility::raster;
  // Also write the G-buffer's world motion of the deforming meshes (SurfaceMotion, surface_motion.h):
  // the reflection denoiser's reprojection; FramePipeline turns it on with --denoise on.
  bool surface_motion = false;
  float pcf_radius_texels = 1.5f;     // 0 = one shadow sample (hard edges), else 20-sample PCF
  float constant_bias_texels = 0.5f;  // distance bias at normal incidence
  float slope_bias_texels = 1.0f;     // times tan(angle between normal and light) x (1 + PCF radius)
  float normal_offset_texels = 1.0f;  // receivers move this far along their normal first
  float ambient_fraction = 0.15f;     // ambient = ambient_fraction * sky colour * albedo
  int max_texture_layer_size = 1024;  // material texture array layer side limit

  // Throws glint::Error naming the first out-of-range field.
  void validate() const;
};

}  // namespace glint::render
