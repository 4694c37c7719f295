#pragma once
// Checks of a glTF file's JSON that tinygltf does not make, run before tinygltf reads the file:
// tinygltf silently reads a negative byteOffset as 0 and ignores extensionsRequired, so a file
// glint would render wrongly (Draco-compressed meshes, shifted vertices) would load without a word.
// Internal to the glTF loader.
#include <filesystem>
#include <string>

namespace glint {

// The glTF extensions a file may require: KHR_mesh_quantization only widens the accessor component
// types, which gltf_accessors reads anyway. Every other required extension is refused.
inline constexpr const char* kSupportedRequiredGltfExtensions[] = {"KHR_mesh_quantization"};

// Throws a glint::Error "<label>: <JSON path>: <problem>" when the document requires an extension
// not in kSupportedRequiredGltfExtensions, or an accessor's or bufferView's byteOffset (or an
// accessor's count) is not a non-negative integer, or an image stored in a bufferView whose byte
// range runs past its buffer (tinygltf would read past the buffer's end). `path` is a .gltf or a .glb (its JSON chunk is
// read); a file whose JSON cannot be found or parsed is left to tinygltf, which reports it.
void check_gltf_document(const std::filesystem::path& path, const std::string& label);

}  // namespace glint
