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
  const DenoiseSettings& d = s.denoiser;
  if (!(d.max_history >= 1.0f && d.max_history <= 1024.0f))
    fail("resolve settings: denoiser max_history {} is outside 1..1024", d.max_history);
  if (!(d.clamp_sigma > 0.0f) || !(d.depth_tolerance > 0.0f) || !(d.depth_sigma > 0.0f) || !(d.roughness_sigma > 0.0f))
    fail("resolve settings: denoiser clamp_sigma {}, depth_tolerance {}, depth_sigma {} and roughness_sigma {} must be > 0",
         d.clamp_sigma, d.depth_tolerance, d.depth_sigma, d.roughness_sigma);
  if (!(d.max_sigma >= 0.0f) || !(d.normal_power >= 0.0f))
    fail("resolve settings: denoiser max_sigma {} and normal_power {} must be >= 0", d.max_sigma, d.normal_power);
  if (d.iterations < 1 || d.iterations > 5) fail("resolve settings: denoiser iterations {} is outside 1..5", d.iterations);
  const int tone_map = static_cast<int>(s.tone_map);
  if (tone_map < 0 || tone_map > static_cast<int>(ToneMap::aces))
    fail("resolve settings: tone_map {} is not a ToneMap", tone_map);
}

}  // namespace glint::render
