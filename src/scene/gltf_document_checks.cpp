#include "scene/gltf_document_checks.h"

#include "core/error.h"
#include "core/untrusted_text.h"

#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>
#include <system_error>
#include <string_view>

namespace glint {
namespace {

std::uint32_t little_endian_u32(const std::array<unsigned char, 4>& bytes) {
  return std::uint32_t{bytes[0]} | (std::uint32_t{bytes[1]} << 8) | (std::uint32_t{bytes[2]} << 16) |
         (std::uint32_t{bytes[3]} << 24);
}

// The JSON text of a .gltf (the whole file) or a .glb (its first chunk, glTF 2.0 section 4.4);
// nullopt when the file is too short or its GLB header does not hold together.
std::optional<std::string> json_text(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return std::nullopt;
  std::array<unsigned char, 4> word{};
  const auto read_word = [&]() -> std::optional<std::uint32_t> {
    if (!file.read(reinterpret_cast<char*>(word.data()), 4)) return std::nullopt;
    return little_endian_u32(word);
  };
  const std::optional<std::uint32_t> magic = read_word();
  if (magic != 0x46546C67u) {  // not "glTF": a text .gltf
    file.clear();
    file.seekg(0);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  }
  const std::optional<std::uint32_t> version = read_word(), total = read_word(), chunk_length = read_word(),
                                     chunk_type = read_word();
  if (!version || !total || !chunk_length || chunk_type != 0x4E4F534Au) return std::nullopt;  // "JSON"
  // The chunk must lie inside the file (not only inside the length its header declares), so a crafted
  // length cannot make this allocate more than the file holds.
  std::error_code error;
  const std::uintmax_t file_bytes = std::filesystem::file_size(path, error);
  if (error || file_bytes < 20 || *chunk_length > file_bytes - 20) return std::nullopt;
  std::string text(*chunk_length, '\0');
  if (!file.read(text.data(), static_cast<std::streamsize>(text.size()))) return std::nullopt;
  return text;
}

// "<label>: <where>: <value> must be a non-negative integer" unless `value` is one.
void check_non_negative_integer(const nlohmann::json& object, std::string_view key, const std::string& label,
                                const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end() || it->is_number_unsigned()) return;
  fail("{}: {}.{}: {} must be a non-negative integer", label, where, key, untrusted_text(it->dump()));
}

void check_each(const nlohmann::json& document, std::string_view array, std::initializer_list<std::string_view> keys,
                const std::string& label) {
  const auto items = document.find(array);
  if (items == document.end() || !items->is_array()) return;
  for (std::size_t i = 0; i < items->size(); ++i) {
    const nlohmann::json& item = (*items)[i];
    if (!item.is_object()) continue;  // tinygltf reports it
    for (std::string_view key : keys) check_non_negative_integer(item, key, label, fmt::format("{}[{}]", array, i));
  }
}

// The non-negative integer at `object[key]`, `fallback` when absent, nullopt when not one.
std::optional<std::uint64_t> unsigned_at(const nlohmann::json& object, std::string_view key, std::uint64_t fallback) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_number_unsigned()) return std::nullopt;
  return it->get<std::uint64_t>();
}

// tinygltf hands an image stored in a bufferView to the image decoder as (buffer data + byteOffset,
// byteLength) without checking that range against the buffer (a heap over-read); buffers hold exactly
// their declared byteLength (tinygltf checks that), so the declared sizes decide.
void check_image_buffer_views(const nlohmann::json& document, const std::string& label) {
  const auto images = document.find("images");
  const auto views = document.find("bufferViews");
  const auto buffers = document.find("buffers");
  if (images == document.end() || !images->is_array()) return;
  for (std::size_t i = 0; i < images->size(); ++i) {
    const nlohmann::json& image = (*images)[i];
    if (!image.is_object() || !image.contains("bufferView") || !image["bufferView"].is_number_unsigned()) continue;
    const auto view_index = image["bufferView"].get<std::uint64_t>();
    if (views == document.end() || !views->is_array() || view_index >= views->size()) continue;  // tinygltf reports it
    const nlohmann::json& view = (*views)[view_index];
    if (!view.is_object()) continue;
    const std::optional<std::uint64_t> buffer_index = unsigned_at(view, "buffer", ~std::uint64_t{0});
    const std::optional<std::uint64_t> offset = unsigned_at(view, "byteOffset", 0), length = unsigned_at(view, "byteLength", 0);
    if (!buffer_index || !offset || !length || buffers == document.end() || !buffers->is_array() ||
        *buffer_index >= buffers->size() || !(*buffers)[*buffer_index].is_object())
      continue;
    const std::optional<std::uint64_t> buffer_length = unsigned_at((*buffers)[*buffer_index], "byteLength", 0);
    if (!buffer_length) continue;
    if (*offset > *buffer_length || *length > *buffer_length - *offset)
      fail("{}: images[{}]: bufferViews[{}] (byteOffset {}, byteLength {}) runs past the end of buffers[{}] ({} "
           "bytes)",
           label, i, view_index, *offset, *length, *buffer_index, *buffer_length);
  }
}

}  // namespace

void check_gltf_document(const std::filesystem::path& path, const std::string& label) {
  const std::optional<std::string> text = json_text(path);
  if (!text) return;
  const nlohmann::json document = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
  if (!document.is_object()) return;  // malformed: tinygltf says how

  if (const auto required = document.find("extensionsRequired"); required != document.end() && required->is_array())
    for (std::size_t i = 0; i < required->size(); ++i) {
      const nlohmann::json& name = (*required)[i];
      const std::string shown = name.is_string() ? name.get<std::string>() : name.dump();
      const bool supported =
          name.is_string() && std::ranges::find(kSupportedRequiredGltfExtensions, shown) !=
                                  std::end(kSupportedRequiredGltfExtensions);
      if (!supported)
        fail("{}: extensionsRequired[{}]: the file requires the extension \"{}\", which glint does not implement "
             "(supported: {})",
             label, i, untrusted_text(shown), fmt::join(kSupportedRequiredGltfExtensions, ", "));
    }
  check_each(document, "accessors", {"byteOffset", "count"}, label);
  check_each(document, "bufferViews", {"byteOffset"}, label);
  check_image_buffer_views(document, label);
}

}  // namespace glint
