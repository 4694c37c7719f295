#include "render/scene_reflection_fade.h"

#include <cmath>

namespace glint::render {

DistanceFade scene_reflection_fade(const Scene& scene) {
  if (scene.reflection_fade) return *scene.reflection_fade;
  const float diagonal = length(scene.world_bounds().extent());
  if (!std::isfinite(diagonal) || !(diagonal > 0.0f)) return {};
  return {kFadeStartFraction * diagonal, kFadeEndFraction * diagonal};
}

ResolveSettings with_scene_fade(const ResolveSettings& settings, const Scene& scene) {
  ResolveSettings fitted = settings;
  if (!settings.fade_from_scene || !(settings.fade_end > 0.0f)) return fitted;
  const DistanceFade fade = scene_reflection_fade(scene);
  fitted.fade_start = fade.start;
  fitted.fade_end = fade.end;
  return fitted;
}

}  // namespace glint::render
