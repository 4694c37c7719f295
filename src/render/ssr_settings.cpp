#include "render/ssr_settings.h"

#include "core/error.h"

#include <cmath>

namespace glint::render {

void validate(const SsrSettings& s) {
  if (s.max_steps < 1 || s.max_steps > 65536) fail("ssr settings: max_steps {} is outside 1..65536", s.max_steps);
  if (!std::isfinite(s.stride) || s.stride < 1.0f) fail("ssr settings: stride {} must be >= 1 pixel", s.stride);
  if (s.refinement_steps < 0 || s.refinement_steps > 16)
    fail("ssr settings: refinement_steps {} is outside 0..16", s.refinement_steps);
  if (!std::isfinite(s.thickness) || s.thickness <= 0.0f) fail("ssr settings: thickness {} must be > 0", s.thickness);
  if (!std::isfinite(s.max_distance) || s.max_distance <= 0.0f)
    fail("ssr settings: max_distance {} must be > 0", s.max_distance);
  if (!(s.confidence_threshold >= 0.0f && s.confidence_threshold <= 1.0f))
    fail("ssr settings: confidence_threshold {} is outside 0..1", s.confidence_threshold);
  if (!(s.edge_fade >= 0.0f && s.edge_fade < 0.5f)) fail("ssr settings: edge_fade {} is outside [0, 0.5)", s.edge_fade);
  if (!std::isfinite(s.self_hit_distance) || s.self_hit_distance < 0.0f)
    fail("ssr settings: self_hit_distance {} must be >= 0", s.self_hit_distance);
}

}  // namespace glint::render
