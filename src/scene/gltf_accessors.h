#pragma once
// Reading glTF accessors (typed views into binary buffers) with every bound checked, for the glTF
// loader. Internal to the scene module: it exposes tinygltf types. `where` is a prefix for errors,
// e.g. "model.gltf: meshes[0].primitives[1].attributes.POSITION".
#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

namespace glint {

// An accessor without a bufferView is all zeros (glTF 2.0, 3.6.2.3); with no bytes in the file to
// bound its count, a larger count than this (2^20 elements, 64 MiB of floats at most) is an error.
inline constexpr std::size_t kMaxZeroAccessorElements = std::size_t{1} << 20;

// The accessor's elements as floats, `components` per element (2 for VEC2, 3 for VEC3); integer
// components are converted, scaled to 0..1 / -1..1 when the accessor is normalized. Throws a
// glint::Error when the accessor index, its type or its byte range is invalid (every size is checked
// against the bufferView's bytes without overflow before anything is allocated), or it is sparse.
std::vector<float> read_float_accessor(const tinygltf::Model& model, int accessor_index, int components,
                                       const std::string& where);

// A SCALAR accessor of unsigned bytes, shorts or ints, as 32-bit indices.
std::vector<std::uint32_t> read_index_accessor(const tinygltf::Model& model, int accessor_index,
                                               const std::string& where);

}  // namespace glint
