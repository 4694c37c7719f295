#include "scene/gltf_accessors.h"

#include "core/error.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <string_view>

namespace glint {
namespace {

std::size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return 8;
    default: return 0;
  }
}

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

std::string_view type_name(int components) {
  switch (components) {
    case 1: return "SCALAR";
    case 2: return "VEC2";
    case 3: return "VEC3";
    case 4: return "VEC4";
    default: return "?";
  }
}

// The accessor's checked layout: where element i starts in the buffer, and how it is encoded.
struct AccessorView {
  const tinygltf::Accessor* accessor = nullptr;
  const unsigned char* data = nullptr;  // null: no bufferView, every element is zero (glTF 2.0, 3.6.2.3)
  std::size_t stride = 0;
  std::size_t component_bytes = 0;
};

// a + b and a * b, or nullopt when they do not fit a size_t: every size below comes from the file,
// so any sum or product of them may wrap around.
std::optional<std::size_t> checked_add(std::size_t a, std::size_t b) {
  std::size_t sum = 0;
  if (__builtin_add_overflow(a, b, &sum)) return std::nullopt;
  return sum;
}
std::optional<std::size_t> checked_multiply(std::size_t a, std::size_t b) {
  std::size_t product = 0;
  if (__builtin_mul_overflow(a, b, &product)) return std::nullopt;
  return product;
}

AccessorView view_accessor(const tinygltf::Model& model, int accessor_index, int components, const std::string& where) {
  if (accessor_index < 0 || static_cast<std::size_t>(accessor_index) >= model.accessors.size())
    fail("{}: accessor {} does not exist ({} accessors)", where, accessor_index, model.accessors.size());
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(accessor_index)];
  const std::string at = fmt::format("{} (accessors[{}])", where, accessor_index);
  if (component_count(accessor.type) != components)
    fail("{}: expected a {} accessor", at, type_name(components));
  AccessorView view;
  view.accessor = &accessor;
  view.component_bytes = component_size(accessor.componentType);
  if (view.component_bytes == 0 || view.component_bytes == 8)
    fail("{}: unsupported component type {}", at, accessor.componentType);
  if (accessor.sparse.isSparse) fail("{}: sparse accessors are not supported", at);
  const std::size_t element_bytes = view.component_bytes * static_cast<std::size_t>(components);
  if (accessor.bufferView < 0) {
    // All zeros, with no bytes in the file to bound the count: only small ones are believed.
    if (accessor.count > kMaxZeroAccessorElements)
      fail("{}: count {} without a bufferView (all zeros) exceeds glint's limit of {} elements", at, accessor.count,
           kMaxZeroAccessorElements);
    return view;
  }

  if (static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size())
    fail("{}: bufferView {} does not exist ({} bufferViews)", at, accessor.bufferView, model.bufferViews.size());
  const tinygltf::BufferView& buffer_view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
  if (buffer_view.buffer < 0 || static_cast<std::size_t>(buffer_view.buffer) >= model.buffers.size())
    fail("{}: bufferViews[{}] refers to buffer {}, which does not exist", at, accessor.bufferView, buffer_view.buffer);
  const tinygltf::Buffer& buffer = model.buffers[static_cast<std::size_t>(buffer_view.buffer)];
  const std::optional<std::size_t> view_end = checked_add(buffer_view.byteOffset, buffer_view.byteLength);
  if (!view_end || *view_end > buffer.data.size())
    fail("{}: bufferViews[{}] (byteOffset {}, byteLength {}) runs past the end of buffers[{}] ({} bytes)", at,
         accessor.bufferView, buffer_view.byteOffset, buffer_view.byteLength, buffer_view.buffer, buffer.data.size());

  view.stride = buffer_view.byteStride != 0 ? buffer_view.byteStride : element_bytes;
  if (view.stride < element_bytes) fail("{}: byteStride {} is smaller than an element ({} bytes)", at, view.stride, element_bytes);
  if (accessor.byteOffset > buffer_view.byteLength)
    fail("{}: byteOffset {} is past the end of bufferViews[{}] ({} bytes)", at, accessor.byteOffset,
         accessor.bufferView, buffer_view.byteLength);
  if (accessor.count > 0) {
    // The last element ends at byteOffset + stride * (count - 1) + element bytes, which must fit the
    // view; computed without wrapping, before anything is allocated for the elements.
    std::optional<std::size_t> end = checked_multiply(view.stride, accessor.count - 1);
    if (end) end = checked_add(*end, accessor.byteOffset);
    if (end) end = checked_add(*end, element_bytes);
    if (!end || *end > buffer_view.byteLength)
      fail("{}: count {} (stride {} bytes, byteOffset {}) does not fit: bufferViews[{}] has {} bytes", at,
           accessor.count, view.stride, accessor.byteOffset, accessor.bufferView, buffer_view.byteLength);
  }
  view.data = buffer.data.data() + buffer_view.byteOffset + accessor.byteOffset;
  return view;
}

template <typename T>
T load(const unsigned char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof(T));  // glTF data is little-endian and may be unaligned
  return value;
}

// Component c of an element as a double, normalized per glTF 2.0 section 3.11 when asked.
double read_component(const unsigned char* bytes, int component_type, bool normalized) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return static_cast<double>(load<float>(bytes));
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? load<std::uint8_t>(bytes) / 255.0 : load<std::uint8_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return normalized ? load<std::uint16_t>(bytes) / 65535.0 : load<std::uint16_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return static_cast<double>(load<std::uint32_t>(bytes));
    case TINYGLTF_COMPONENT_TYPE_BYTE: return normalized ? std::max(load<std::int8_t>(bytes) / 127.0, -1.0) : load<std::int8_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return normalized ? std::max(load<std::int16_t>(bytes) / 32767.0, -1.0) : load<std::int16_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_INT: return static_cast<double>(load<std::int32_t>(bytes));
    default: return 0.0;
  }
}

}  // namespace

std::vector<float> read_float_accessor(const tinygltf::Model& model, int accessor_index, int components,
                                       const std::string& where) {
  const AccessorView view = view_accessor(model, accessor_index, components, where);
  const tinygltf::Accessor& accessor = *view.accessor;
  std::vector<float> out(accessor.count * static_cast<std::size_t>(components), 0.0f);
  if (view.data == nullptr) return out;
  for (std::size_t i = 0; i < accessor.count; ++i)
    for (int c = 0; c < components; ++c) {
      const unsigned char* bytes = view.data + i * view.stride + static_cast<std::size_t>(c) * view.component_bytes;
      out[i * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] =
          static_cast<float>(read_component(bytes, accessor.componentType, accessor.normalized));
    }
  return out;
}

std::vector<std::uint32_t> read_index_accessor(const tinygltf::Model& model, int accessor_index, const std::string& where) {
  const AccessorView view = view_accessor(model, accessor_index, 1, where);
  const tinygltf::Accessor& accessor = *view.accessor;
  const int type = accessor.componentType;
  if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    fail("{} (accessors[{}]): indices must be unsigned bytes, shorts or ints (component type {})", where,
         accessor_index, type);
  std::vector<std::uint32_t> out(accessor.count, 0u);
  if (view.data == nullptr) return out;
  for (std::size_t i = 0; i < accessor.count; ++i) {
    const unsigned char* bytes = view.data + i * view.stride;
    if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) out[i] = load<std::uint8_t>(bytes);
    else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) out[i] = load<std::uint16_t>(bytes);
    else out[i] = load<std::uint32_t>(bytes);
  }
  return out;
}

}  // namespace glint
