// PLACEHOLDER until the OBJ loader lands (replaced by its implementation).
#include "scene/obj_loader.h"
#include "core/error.h"
namespace glint {
Scene load_obj(const std::filesystem::path& path, const LoadOptions&) { fail("{}: OBJ loading is not built yet", path.string()); }
}  // namespace glint
