#pragma once
// One channel of an 8-bit image as a plane of doubles, the form every metric works on. Values stay
// on the 0..255 scale of the file (no linearisation): the metrics compare what a viewer is shown.
#include "core/image.h"

namespace glint::metrics {

using Plane = Image<double>;  // width * height values, top row first, 0..255

enum class Channel { red = 0, green = 1, blue = 2 };
inline constexpr Channel kColourChannels[] = {Channel::red, Channel::green, Channel::blue};
inline constexpr const char* channel_name(Channel c) {
  return c == Channel::red ? "R" : c == Channel::green ? "G" : "B";
}

// Rec. 709 luma weights, applied to the sRGB-encoded 8-bit values as they are stored (this is Y',
// not the relative luminance Y of linear values; it matches what SSIM implementations do on PNGs).
inline constexpr double kLumaRed = 0.2126;
inline constexpr double kLumaGreen = 0.7152;
inline constexpr double kLumaBlue = 0.0722;

Plane channel_plane(const ImageRgba8& image, Channel channel);
// Y' = 0.2126 R + 0.7152 G + 0.0722 B, per pixel, 0..255 (not rounded).
Plane luma_plane(const ImageRgba8& image);

}  // namespace glint::metrics
