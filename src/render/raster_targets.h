#pragma once
// The full-screen images the raster passes write (formats and meanings in render_targets.h), all
// width x height. Later passes (SSR, resolve) read them by texture id.
#include "gl/gl_objects.h"

namespace glint::render {

struct RasterTargets {
  // Throws glint::Error for a non-positive size. `visibility_ids`: also make visibility_id (only the
  // visibility G-buffer writes it).
  RasterTargets(int width, int height, bool visibility_ids = false);

  int width = 0;
  int height = 0;
  GlTexture albedo_reflectivity;     // kAlbedoReflectivityFormat
  GlTexture world_position;          // kWorldPositionFormat
  GlTexture world_normal_roughness;  // kWorldNormalRoughnessFormat
  GlTexture material_id;             // kMaterialIdFormat
  GlTexture depth;                   // kDepthFormat
  GlTexture shadow_mask;             // kShadowMaskFormat
  GlTexture lit;                     // kLitFormat
  GlTexture visibility_id;           // kVisibilityIdFormat; id 0 unless made with visibility_ids
};

}  // namespace glint::render
