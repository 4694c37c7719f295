// PLACEHOLDER until the glTF loader lands (replaced by its implementation).
#include "scene/gltf_loader.h"
#include "core/error.h"
namespace glint {
Scene load_gltf(const std::filesystem::path& path, const LoadOptions&) { fail("{}: glTF loading is not built yet", path.string()); }
}  // namespace glint
