#include "render/resolve_settings.h"

#include "core/error.h"

#include <cmath>

namespace glint::render {

void validate(const ResolveSettings& s) {
  if (!std::isfinite(s.fade_start) || !std::isfinite(s.fade_end))
    fail("resolve settings: fade_start {} and fade_end {} must be finite", s.fade_start, s.fade_end);
  if (s.fade_end > 0.0f && !(s.fade_start >= 0.0f && s.fade_start < s.fade_end))
    fail("resolve settings: fade needs 0 <= fade_start < fade_end, got fade_start {} and fade_end {}", s.fade_start,
         s.fade_end);
  if (s.blur_radius < 0 || s.blur_radius > 32) fail("resolve settings: blur_radius {} is outside 0..32", s.blur_radius);
  if (!std::isfinite(s.exposure) || s.exposure <= 0.0f) fail("resolve settings: exposure {} must be > 0", s.exposure);
  const int tone_map = static_cast<int>(s.tone_map);
  if (tone_map < 0 || tone_map > static_cast<int>(ToneMap::aces))
    fail("resolve settings: tone_map {} is not a ToneMap", tone_map);
}

}  // namespace glint::render
