#pragma once
// glTF metallic-roughness materials and images -> glint's Blinn-Phong + mirror materials and RGBA8
// textures. Internal to the scene module (it exposes tinygltf types). The mapping, documented in
// docs/scene-format.md ("glTF files"), with metallic = metallicFactor and roughness =
// roughnessFactor, each times the mean of metallicRoughnessTexture's channel (B, G) when it has one:
//   diffuse            = baseColorFactor.rgb (times baseColorTexture)
//   reflectivity       = metallic: metals mirror, dielectrics do not (as an MTL's `Pm`); roughness
//                        only widens the reflection (roughness, --glossy on), it does not weaken it
//   specular           = mix(0.04, diffuse, metallic): the usual F0 of dielectrics and metals
//   specular_exponent  = specular_exponent_from_roughness(roughness)
//   roughness          = roughness; emissive = emissiveFactor
#include "scene/scene.h"
#include "scene/specular_roughness.h"

#include <tiny_gltf.h>

#include <map>
#include <string>

namespace glint {

// The means of a metallicRoughnessTexture's channels, linear 0..1 (glTF: G = roughness, B =
// metallic). glint's material has one roughness and one reflectivity, not a texture of them, so a
// texture's mean stands for it. 1 and 1 (the factors alone) for a material without one.
struct MetallicRoughnessMean {
  float roughness = 1.0f;
  float metallic = 1.0f;
};
MetallicRoughnessMean metallic_roughness_mean(const Texture& texture);

// The material without its texture (diffuse_texture stays -1; the loader links textures);
// `texture_mean` multiplies metallicFactor and roughnessFactor.
Material convert_gltf_material(const tinygltf::Material& material, int index,
                               const MetallicRoughnessMean& texture_mean = {});

// An image tinygltf decoded (any of 1-4 channels, 8 or 16 bits) as 8-bit RGBA, top row first. Throws
// a glint::Error (prefixed with `where`) when the image has no pixels, e.g. a missing external file.
Texture convert_gltf_image(const tinygltf::Image& image, const std::string& name, const std::string& where);

// Decoding of glTF images, installed with tinygltf::TinyGLTF::SetImageLoader in place of tinygltf's
// own stb call, so that glTF images get the same size limit and messages as texture files
// (texture_io's decode_texture): an image that cannot be decoded is left empty (the material stays
// untextured, with a warning) and its reason recorded here, by image index.
struct GltfImageFailures {
  std::map<int, std::string> reasons;
};
// A tinygltf::LoadImageDataFunction; `user_data` is a GltfImageFailures. Always returns true: a bad
// image is a warning, not a reason to refuse the whole file.
bool decode_gltf_image(tinygltf::Image* image, int image_index, std::string* error, std::string* warning,
                       int required_width, int required_height, const unsigned char* bytes, int size, void* user_data);

}  // namespace glint
