#pragma once
// Tunables of the raster passes. Shadow sizes are in cube-map texels at the receiver's distance, so
// they scale with distance from the light and with shadow_map_size (docs/render.md explains them).
namespace glint::render {

struct RasterSettings {
  int shadow_map_size = 1024;         // cube face side in texels
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
