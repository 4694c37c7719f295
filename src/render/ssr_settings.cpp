#include "render/ssr_settings.h"

#include "core/error.h"

#include <cmath>

namespace glint::render {

void validate(const SsrSettings& s) {
  if (s.max_steps < 1 || s.max_steps > 65536) fail("ssr settings: max_steps {} is outside 1..65536", s.max_steps);
  if (!(s.thickness > 0.0f && s.thickness <= 1.0f))
    fail("ssr settings: thickness {} is outside (0, 1] (a fraction of the view depth)", s.thickness);
  if (!std::isfinite(s.max_distance) || s.max_distance < 0.0f)
    fail("ssr settings: max_distance {} must be >= 0 (0 = no limit)", s.max_distance);
  if (!(s.confidence_threshold >= 0.0f && s.confidence_threshold <= 1.0f))
    fail("ssr settings: confidence_threshold {} is outside 0..1", s.confidence_threshold);
  if (!(s.edge_fade >= 0.0f && s.edge_fade < 0.5f)) fail("ssr settings: edge_fade {} is outside [0, 0.5)", s.edge_fade);
  if (!(s.min_hit_cosine >= 0.0f && s.min_hit_cosine < 1.0f))
    fail("ssr settings: min_hit_cosine {} is outside [0, 1)", s.min_hit_cosine);
  if (!(std::isfinite(s.silhouette_footprints) && s.silhouette_footprints > 0.0f))
    fail("ssr settings: silhouette_footprints {} must be > 0", s.silhouette_footprints);
  if (!(s.empty_behind > 0.0f)) fail("ssr settings: empty_behind {} must be > 0 (a fraction of the view depth)", s.empty_behind);
  if (!(std::isfinite(s.max_screen_fraction) && s.max_screen_fraction > 0.0f))
    fail("ssr settings: max_screen_fraction {} must be > 0", s.max_screen_fraction);
}

}  // namespace glint::render
