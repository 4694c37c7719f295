#pragma once
// The atrium's textures, synthesised at load time from tileable noise (scene/procedural/noise.h).
// All are square, RGBA8, sRGB-encoded, top row first (the Texture conventions of scene/scene.h),
// and deterministic. Tiling textures (stone, brick, marble, plaster, wood) wrap seamlessly; the
// fabric texture is meant to cover one whole banner (it has a border and an emblem).
#include "core/math.h"
#include "scene/scene.h"

#include <cstdint>

namespace glint::procedural {

// Polished floor: a 2 x 2 checker of light and darker marble tiles with veins and thin grout lines.
Texture make_marble_texture(int size);
// Ashlar masonry: courses of dressed stone blocks with mortar joints.
Texture make_stone_texture(int size);
// Running-bond brickwork.
Texture make_brick_texture(int size);
// Warm, blotchy lime plaster.
Texture make_plaster_texture(int size);
// Planks with growth-ring grain along u.
Texture make_wood_texture(int size);
// Woven cloth in `base` with an `accent` border and emblem (colours are sRGB in 0..1).
Texture make_fabric_texture(int size, vec3 base, vec3 accent, std::uint32_t seed);

}  // namespace glint::procedural
