#include "scene/gltf_test_builder.h"

#include <stb/stb_image_write.h>

namespace glint::testing {

std::string base64_encode(const std::vector<std::uint8_t>& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t chunk = (std::uint32_t{bytes[i]} << 16) |
                                (i + 1 < bytes.size() ? std::uint32_t{bytes[i + 1]} << 8 : 0u) |
                                (i + 2 < bytes.size() ? std::uint32_t{bytes[i + 2]} : 0u);
    out += kAlphabet[(chunk >> 18) & 63];
    out += kAlphabet[(chunk >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(chunk >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[chunk & 63] : '=';
  }
  return out;
}

std::vector<std::uint8_t> encode_png(int width, int height, const std::vector<std::uint8_t>& rgba) {
  std::vector<std::uint8_t> png;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        out->insert(out->end(), bytes, bytes + size);
      },
      &png, width, height, 4, rgba.data(), width * 4);
  return png;
}

GltfBuilder::GltfBuilder() {
  json = {{"asset", {{"version", "2.0"}}}, {"bufferViews", nlohmann::json::array()},
          {"accessors", nlohmann::json::array()}};
}

int GltfBuilder::add_view(const void* data, std::size_t bytes) {
  while (bin_.size() % 4 != 0) bin_.push_back(0);
  const std::size_t offset = bin_.size();
  bin_.resize(offset + bytes);
  std::memcpy(bin_.data() + offset, data, bytes);
  json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
  return static_cast<int>(json["bufferViews"].size() - 1);
}

int GltfBuilder::add_accessor(int view, int component_type, std::size_t count, const char* type) {
  json["accessors"].push_back({{"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}});
  return static_cast<int>(json["accessors"].size() - 1);
}

int GltfBuilder::add_vec3(const std::vector<float>& xyz) {
  return add_accessor(add_view(xyz.data(), xyz.size() * 4), 5126, xyz.size() / 3, "VEC3");
}
int GltfBuilder::add_vec2(const std::vector<float>& st) {
  return add_accessor(add_view(st.data(), st.size() * 4), 5126, st.size() / 2, "VEC2");
}
int GltfBuilder::add_indices_u8(const std::vector<std::uint8_t>& indices) {
  return add_accessor(add_view(indices.data(), indices.size()), 5121, indices.size(), "SCALAR");
}
int GltfBuilder::add_indices_u16(const std::vector<std::uint16_t>& indices) {
  return add_accessor(add_view(indices.data(), indices.size() * 2), 5123, indices.size(), "SCALAR");
}
int GltfBuilder::add_indices_u32(const std::vector<std::uint32_t>& indices) {
  return add_accessor(add_view(indices.data(), indices.size() * 4), 5125, indices.size(), "SCALAR");
}

int GltfBuilder::add_png_image(const std::vector<std::uint8_t>& png) {
  json["images"].push_back({{"bufferView", add_view(png.data(), png.size())}, {"mimeType", "image/png"}});
  return static_cast<int>(json["images"].size() - 1);
}

int GltfBuilder::add_mesh_node(const nlohmann::json& primitive, const nlohmann::json& node_extras) {
  json["meshes"].push_back({{"primitives", nlohmann::json::array({primitive})}});
  nlohmann::json node = node_extras;
  node["mesh"] = json["meshes"].size() - 1;
  json["nodes"].push_back(node);
  return static_cast<int>(json["nodes"].size() - 1);
}

nlohmann::json GltfBuilder::with_buffer(const nlohmann::json& buffer) const {
  nlohmann::json document = json;
  document["buffers"] = nlohmann::json::array({buffer});
  return document;
}

std::string GltfBuilder::gltf_text() const {
  return with_buffer({{"byteLength", bin_.size()},
                      {"uri", "data:application/octet-stream;base64," + base64_encode(bin_)}})
      .dump(1);
}

std::string GltfBuilder::gltf_text_with_bin(const std::string& bin_uri) const {
  return with_buffer({{"byteLength", bin_.size()}, {"uri", bin_uri}}).dump(1);
}

std::vector<std::uint8_t> GltfBuilder::glb() const {
  // GLB (glTF 2.0 spec, section 4.4): 12-byte header, a JSON chunk padded with spaces, a BIN chunk
  // padded with zeros; every length little-endian.
  std::string text = with_buffer({{"byteLength", bin_.size()}}).dump();
  while (text.size() % 4 != 0) text += ' ';
  std::vector<std::uint8_t> bin = bin_;
  while (bin.size() % 4 != 0) bin.push_back(0);
  std::vector<std::uint8_t> out;
  const auto put32 = [&out](std::uint32_t value) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
  };
  put32(0x46546C67u);  // "glTF"
  put32(2);
  put32(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
  put32(static_cast<std::uint32_t>(text.size()));
  put32(0x4E4F534Au);  // "JSON"
  out.insert(out.end(), text.begin(), text.end());
  put32(static_cast<std::uint32_t>(bin.size()));
  put32(0x004E4942u);  // "BIN\0"
  out.insert(out.end(), bin.begin(), bin.end());
  return out;
}

}  // namespace glint::testing
