#include "render/raster_targets.h"

#include "core/error.h"
#include "render/render_targets.h"

namespace glint::render {
namespace {

// Passes read these with texelFetch (one texel per pixel); nearest filtering keeps any sampler
// lookup from blending positions or ids of different surfaces. Immutable storage
// (create_texture_2d), so compute passes can bind them as images (shadow mask, lighting).
GlTexture make_target(GLenum format, int width, int height) {
  GlTexture texture = create_texture_2d(format, width, height);
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

}  // namespace

RasterTargets::RasterTargets(int width_, int height_, bool visibility_ids) : width(width_), height(height_) {
  if (width <= 0 || height <= 0) fail("raster targets: invalid size {}x{}", width, height);
  albedo_reflectivity = make_target(kAlbedoReflectivityFormat, width, height);
  world_position = make_target(kWorldPositionFormat, width, height);
  world_normal_roughness = make_target(kWorldNormalRoughnessFormat, width, height);
  material_id = make_target(kMaterialIdFormat, width, height);
  depth = make_target(kDepthFormat, width, height);
  shadow_mask = make_target(kShadowMaskFormat, width, height);
  lit = make_target(kLitFormat, width, height);
  if (visibility_ids) visibility_id = make_target(kVisibilityIdFormat, width, height);
}

}  // namespace glint::render
