#include "render/raster_settings.h"

#include "core/error.h"

#include <cmath>

namespace glint::render {
namespace {

void require_non_negative(float value, const char* field) {
  if (!(std::isfinite(value) && value >= 0.0f)) fail("raster settings: {} = {} must be finite and >= 0", field, value);
}

}  // namespace

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
