#pragma once
// The frame's tone map and sRGB encoding on the CPU: the very functions of the resolve shader
// (shaders/include/tone_map.glsl, compiled here as C++), so a linear image (an EXR of `glint render
// --format exr`) becomes the 8-bit picture the renderer would have written for it, up to the GPU's
// float rounding (within one 8-bit level). `glint compare` uses it to compare EXRs as PNGs.
#include "core/image.h"
#include "core/math.h"
#include "render/resolve_settings.h"

#include <string_view>

namespace glint::render {

// The EXR string attribute (core/exr_image.h) in which `glint render --format exr` records its frames'
// tone map ("aces", ...), so `glint compare` maps them as the renderer did.
inline constexpr std::string_view kExrToneMapAttribute = "glintToneMap";

// srgb_encode(tone_map(linear)), each channel in [0, 1]. `linear` already carries the exposure.
vec3 tone_mapped_srgb(const vec3& linear, ToneMap tone_map);
// Every pixel through tone_mapped_srgb, quantised to 8 bits as the GPU's RGBA8 store does; a = 255.
ImageRgba8 tone_map_to_rgba8(const ImageRgbaF& linear, ToneMap tone_map);

}  // namespace glint::render
