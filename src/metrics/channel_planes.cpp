#include "metrics/channel_planes.h"

namespace glint::metrics {

Plane channel_plane(const ImageRgba8& image, Channel channel) {
  Plane plane(image.width, image.height);
  const auto c = static_cast<glm::length_t>(channel);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) plane.pixels[i] = image.pixels[i][c];
  return plane;
}

Plane luma_plane(const ImageRgba8& image) {
  Plane plane(image.width, image.height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const glm::u8vec4 p = image.pixels[i];
    plane.pixels[i] = kLumaRed * p.x + kLumaGreen * p.y + kLumaBlue * p.z;
  }
  return plane;
}

}  // namespace glint::metrics
