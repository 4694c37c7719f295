#include "scene/gltf_materials.h"

#include "core/error.h"
#include "core/untrusted_text.h"
#include "scene/texture_io.h"

#include <algorithm>
#include <cstring>

namespace glint {

MetallicRoughnessMean metallic_roughness_mean(const Texture& texture) {
  const std::size_t texels = texture.rgba.size() / 4;
  if (texels == 0) return {};
  double green = 0.0, blue = 0.0;  // sums of up to 2^28 bytes: exact in a double
  for (std::size_t t = 0; t < texels; ++t) {
    green += texture.rgba[t * 4 + 1];
    blue += texture.rgba[t * 4 + 2];
  }
  const double scale = 1.0 / (255.0 * static_cast<double>(texels));
  return {static_cast<float>(green * scale), static_cast<float>(blue * scale)};
}

Material convert_gltf_material(const tinygltf::Material& material, int index, const MetallicRoughnessMean& texture_mean) {
  Material out;
  out.name = material.name.empty() ? fmt::format("materials[{}]", index) : material.name;
  const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() >= 3)
    out.diffuse = vec3(static_cast<float>(pbr.baseColorFactor[0]), static_cast<float>(pbr.baseColorFactor[1]),
                       static_cast<float>(pbr.baseColorFactor[2]));
  const float metallic = std::clamp(static_cast<float>(pbr.metallicFactor) * texture_mean.metallic, 0.0f, 1.0f);
  const float roughness = std::clamp(static_cast<float>(pbr.roughnessFactor) * texture_mean.roughness, 0.0f, 1.0f);
  // Roughness widens the reflection (the GGX lobe of --glossy on) and keeps its energy: weakening
  // the mirror term by it as well would count it twice.
  out.reflectivity = metallic;
  out.roughness = roughness;
  out.specular = glm::mix(vec3(0.04f), out.diffuse, metallic);
  out.specular_exponent = specular_exponent_from_roughness(roughness);
  if (material.emissiveFactor.size() >= 3)
    out.emissive = vec3(static_cast<float>(material.emissiveFactor[0]), static_cast<float>(material.emissiveFactor[1]),
                        static_cast<float>(material.emissiveFactor[2]));
  return out;
}

Texture convert_gltf_image(const tinygltf::Image& image, const std::string& name, const std::string& where) {
  const int channels = image.component;
  const int bytes_per_channel = image.bits == 16 ? 2 : 1;
  if (image.width <= 0 || image.height <= 0 || image.image.empty())
    fail("{}: the image could not be loaded{}", where, image.uri.empty() ? "" : fmt::format(" (\"{}\")", untrusted_text(image.uri)));
  if (channels < 1 || channels > 4 || (image.bits != 8 && image.bits != 16))
    fail("{}: unsupported pixel format ({} channels of {} bits)", where, channels, image.bits);
  const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  if (image.image.size() < pixels * static_cast<std::size_t>(channels * bytes_per_channel))
    fail("{}: {} bytes of pixel data for a {}x{} image", where, image.image.size(), image.width, image.height);

  Texture texture;
  texture.name = name;
  texture.width = image.width;
  texture.height = image.height;
  texture.rgba.resize(pixels * 4);
  // Channel c of pixel p, reduced to 8 bits (16-bit samples keep their high byte).
  const auto channel = [&](std::size_t p, int c) -> std::uint8_t {
    const std::size_t offset = (p * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)) *
                               static_cast<std::size_t>(bytes_per_channel);
    if (bytes_per_channel == 1) return image.image[offset];
    std::uint16_t value;
    std::memcpy(&value, &image.image[offset], 2);  // stb gives native-endian 16-bit samples
    return static_cast<std::uint8_t>(value >> 8);
  };
  for (std::size_t p = 0; p < pixels; ++p) {
    std::uint8_t* out = &texture.rgba[p * 4];
    if (channels <= 2) {  // grey, or grey + alpha
      out[0] = out[1] = out[2] = channel(p, 0);
      out[3] = channels == 2 ? channel(p, 1) : 255;
    } else {
      out[0] = channel(p, 0);
      out[1] = channel(p, 1);
      out[2] = channel(p, 2);
      out[3] = channels == 4 ? channel(p, 3) : 255;
    }
  }
  return texture;
}

bool decode_gltf_image(tinygltf::Image* image, int image_index, std::string* /*error*/, std::string* /*warning*/,
                       int /*required_width*/, int /*required_height*/, const unsigned char* bytes, int size,
                       void* user_data) {
  try {
    const Texture texture =
        decode_texture(std::span<const unsigned char>(bytes, size > 0 ? static_cast<std::size_t>(size) : 0u), image->uri);
    image->width = texture.width;
    image->height = texture.height;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = texture.rgba;
  } catch (const Error& e) {
    image->image.clear();
    static_cast<GltfImageFailures*>(user_data)->reasons[image_index] = e.what();
  }
  return true;
}

}  // namespace glint
