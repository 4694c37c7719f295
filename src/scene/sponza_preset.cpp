#include "scene/sponza_preset.h"

#include "core/error.h"
#include "scene/embedded_sponza_scene.h"
#include "scene/scene_json_loader.h"

#include <string>

namespace glint {

Scene make_sponza_preset(const LoadOptions& options) {
  // The embedded text stands for the file at its source-tree path: its "assets": "../../shared/assets"
  // resolves from there, and options.assets_dir / $GLINT_ASSETS override it (find_assets_dir), so the
  // preset also works for an installed binary once GLINT_ASSETS is set.
  const std::filesystem::path origin{std::string(kEmbeddedSponzaScenePath)};
  try {
    return load_scene_json_text(kEmbeddedSponzaSceneText, origin, options);
  } catch (const Error& e) {
    const std::string message = e.what();
    if (message.find("assets folder not found") != std::string::npos)
      fail("sponza: the preset needs the shared meshes (Dabrovic Sponza, armadillo, blub, spot): {}", message);
    fail("sponza: {}", message);
  }
}

}  // namespace glint
