#pragma once
// Builds small glTF 2.0 files for tests: binary data is appended to one buffer through add_*(), the
// JSON document (meshes, nodes, materials, ...) is edited directly, and the result comes out as .gltf
// text with a base64 data: URI, .gltf text plus a separate .bin, or a .glb.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace glint::testing {

std::string base64_encode(const std::vector<std::uint8_t>& bytes);

// An RGBA8 PNG, rows top first.
std::vector<std::uint8_t> encode_png(int width, int height, const std::vector<std::uint8_t>& rgba);

class GltfBuilder {
public:
  GltfBuilder();

  nlohmann::json json;  // "asset" is set; add the rest

  // Each appends its data (4-byte aligned) as a new bufferView and accessor; returns the accessor index.
  int add_vec3(const std::vector<float>& xyz);
  int add_vec2(const std::vector<float>& st);
  int add_indices_u8(const std::vector<std::uint8_t>& indices);
  int add_indices_u16(const std::vector<std::uint16_t>& indices);
  int add_indices_u32(const std::vector<std::uint32_t>& indices);
  // An image stored in the buffer (bufferView + mimeType); returns the image index.
  int add_png_image(const std::vector<std::uint8_t>& png);

  // A single-primitive mesh node: adds mesh {"primitives": [primitive]} and a node using it; returns
  // the node index.
  int add_mesh_node(const nlohmann::json& primitive, const nlohmann::json& node_extras = nlohmann::json::object());

  std::string gltf_text() const;                       // buffer embedded as a data: URI
  std::string gltf_text_with_bin(const std::string& bin_uri) const;  // buffer in `bin_uri`
  const std::vector<std::uint8_t>& bin() const { return bin_; }
  std::vector<std::uint8_t> glb() const;

private:
  int add_view(const void* data, std::size_t bytes);
  int add_accessor(int view, int component_type, std::size_t count, const char* type);
  nlohmann::json with_buffer(const nlohmann::json& buffer) const;
  std::vector<std::uint8_t> bin_;
};

// The three vertices of a unit right triangle in the xy plane (CCW seen from +z).
inline std::vector<float> unit_triangle() { return {0, 0, 0, 1, 0, 0, 0, 1, 0}; }

}  // namespace glint::testing
