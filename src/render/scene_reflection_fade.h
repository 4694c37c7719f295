#pragma once
// The reflections' distance fade fitted to a scene (docs/ssr.md, "Distance fade"). The paper gives
// the fade for its atrium in world units (15 to 30); a scene of another size needs the same fade
// relative to its size, or a scene scaled by 1000 loses every reflection (and one scaled by 0.001
// never fades). So:
//   a scene's own fade (Scene::reflection_fade: a scene file's "reflection_fade", or the atrium
//   presets' 15 and 30, the paper's): as given, in world units;
//   otherwise: kFadeStartFraction and kFadeEndFraction of the scene's bounds diagonal, the paper's
//   distances over the atrium's diagonal (46.09), rounded (they give it 14.98 and 29.96).
#include "render/resolve_settings.h"
#include "scene/scene.h"

namespace glint::render {

inline constexpr float kFadeStartFraction = 0.325f;
inline constexpr float kFadeEndFraction = 0.65f;

// The fade for `scene` (see above). A scene whose bounds have no finite, positive diagonal gets no
// fade ({0, 0}).
DistanceFade scene_reflection_fade(const Scene& scene);

// `settings` with fade_start and fade_end set to scene_reflection_fade(scene) when fade_from_scene
// is true and the fade is on (fade_end > 0); unchanged otherwise.
ResolveSettings with_scene_fade(const ResolveSettings& settings, const Scene& scene);

}  // namespace glint::render
