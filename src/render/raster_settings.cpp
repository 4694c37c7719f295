#include "render/raster_settings.h"

#include "core/error.h"

#include <cmath>

namespace glint::render {
namespace {

void require_non_negative(float value, const char* field) {
  if (!(std::isfinite(value) && value >= 0.0f)) fail("raster settings: {} = {} must be finite and >= 0", field, value);
}

}  // namespace

std::string_view shadow_cube_draw_name(ShadowCubeDraw draw) {
  switch (draw) {
    case ShadowCubeDraw::per_face: return "per-face";
    case ShadowCubeDraw::layered: return "layered";
  }
  return "unknown";
}

ShadowCubeDraw parse_shadow_cube_draw(std::string_view name) {
  for (const ShadowCubeDraw draw : {ShadowCubeDraw::per_face, ShadowCubeDraw::layered})
    if (shadow_cube_draw_name(draw) == name) return draw;
  fail("raster settings: unknown shadow cube draw '{}' (known: per-face, layered)", name);
}

std::string_view gbuffer_method_name(GBufferMethod method) {
  switch (method) {
    case GBufferMethod::raster: return "raster";
    case GBufferMethod::visibility: return "visibility";
  }
  return "unknown";
}

GBufferMethod parse_gbuffer_method(std::string_view name) {
  for (const GBufferMethod method : {GBufferMethod::raster, GBufferMethod::visibility})
    if (gbuffer_method_name(method) == name) return method;
  fail("raster settings: unknown G-buffer method '{}' (known: raster, visibility)", name);
}

std::string_view primary_visibility_name(PrimaryVisibility primary) {
  switch (primary) {
    case PrimaryVisibility::raster: return "raster";
    case PrimaryVisibility::rt: return "rt";
    case PrimaryVisibility::compute: return "compute";
  }
  return "unknown";
}

PrimaryVisibility parse_primary_visibility(std::string_view name) {
  for (const PrimaryVisibility primary : {PrimaryVisibility::raster, PrimaryVisibility::rt, PrimaryVisibility::compute})
    if (primary_visibility_name(primary) == name) return primary;
  fail("raster settings: unknown primary visibility '{}' (known: raster, rt, compute)", name);
}

void RasterSettings::validate() const {
  if (shadow_map_size < 1) fail("raster settings: shadow_map_size = {} must be at least 1", shadow_map_size);
  if (max_texture_layer_size < 1)
    fail("raster settings: max_texture_layer_size = {} must be at least 1", max_texture_layer_size);
  if (primary == PrimaryVisibility::rt && gbuffer != GBufferMethod::visibility)
    fail("raster settings: ray-traced primary visibility needs the visibility G-buffer (--gbuffer visibility)");
  if (primary == PrimaryVisibility::compute && gbuffer != GBufferMethod::visibility)
    fail("raster settings: compute-rasterised primary visibility needs the visibility G-buffer (--gbuffer visibility)");
  require_non_negative(pcf_radius_texels, "pcf_radius_texels");
  require_non_negative(constant_bias_texels, "constant_bias_texels");
  require_non_negative(slope_bias_texels, "slope_bias_texels");
  require_non_negative(normal_offset_texels, "normal_offset_texels");
  require_non_negative(ambient_fraction, "ambient_fraction");
}

}  // namespace glint::render
