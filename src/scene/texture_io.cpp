// PLACEHOLDER until texture loading lands (replaced by its implementation).
#include "scene/texture_io.h"
#include "core/error.h"
namespace glint {
Texture load_texture_or_placeholder(const std::filesystem::path& path, std::string_view) { fail("{}: textures are not supported yet", path.string()); }
Texture make_checker_texture(int, int) { fail("checker textures are not built yet"); }
}  // namespace glint
