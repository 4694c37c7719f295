// PLACEHOLDER until the scene JSON loader lands (replaced by its implementation).
#include "scene/sponza_preset.h"
#include "core/error.h"
namespace glint {
Scene make_sponza_preset(const LoadOptions&) { fail("sponza: the sponza preset is not built yet"); }
}  // namespace glint
