#include "scene/presets.h"

#include "core/error.h"
#include "scene/procedural/atrium.h"
#include "scene/sponza_preset.h"

namespace glint {

std::vector<std::string> preset_names() { return {"atrium", "atrium-simple", "sponza"}; }

bool is_preset_name(std::string_view name) {
  for (const std::string& preset : preset_names())
    if (preset == name) return true;
  return false;
}

Scene make_preset(std::string_view name, const LoadOptions& options) {
  if (name == "atrium") return procedural::make_atrium(procedural::AtriumDetail::full);
  if (name == "atrium-simple") return procedural::make_atrium(procedural::AtriumDetail::simple);
  if (name == "sponza") return make_sponza_preset(options);
  fail("unknown built-in scene '{}' (known: atrium, atrium-simple, sponza)", name);
}

}  // namespace glint
