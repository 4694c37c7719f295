#pragma once
// Scene textures as layers of one square texture array: every texture resampled to the same size so
// any shader can sample any material's texture by layer index alone.
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace glint::render {

// The array's layer side: the largest width or height of any texture, clamped to `max_size`
// (1 when there are no textures). Throws glint::Error when max_size < 1.
int texture_layer_size(const std::vector<Texture>& textures, int max_size);

// `texture` resampled to size x size RGBA8 (filtered in linear light, since the texels are
// sRGB-encoded), rows bottom first as glTextureSubImage3D expects, so v = 0 is the image's bottom
// row (scene.h's convention). Throws glint::Error for a texture whose pixel data does not match its size.
std::vector<std::uint8_t> texture_layer_texels(const Texture& texture, int size);

}  // namespace glint::render
