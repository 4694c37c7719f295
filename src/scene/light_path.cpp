#include "scene/light_path.h"

#include "core/error.h"

#include <algorithm>

namespace glint {

LightPath::LightPath(std::vector<vec3> points, int period_frames, vec3 rest_position) : period_frames_(period_frames) {
  if (period_frames <= 0) fail("light path: period_frames must be > 0, got {}", period_frames);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!is_finite(points[i])) fail("light path: point {} is not finite", i);
  if (points.empty() && !is_finite(rest_position)) fail("light path: the rest position is not finite");
  points_ = points.empty() ? std::vector<vec3>{rest_position} : std::move(points);
  cumulative_.assign(points_.size(), 0.0);
  for (std::size_t i = 1; i < points_.size(); ++i)
    cumulative_[i] = cumulative_[i - 1] + glm::distance(glm::dvec3(points_[i - 1]), glm::dvec3(points_[i]));
}

vec3 LightPath::at(int frame) const {
  const double total = cumulative_.back();
  if (points_.size() == 1 || total <= 0.0) return points_.front();
  // Phase in [0, 1) of the period; the triangle wave goes 0 -> 1 in the first half, back in the second.
  const int wrapped = ((frame % period_frames_) + period_frames_) % period_frames_;
  const double phase = double(wrapped) / double(period_frames_);
  const double wave = phase <= 0.5 ? 2.0 * phase : 2.0 - 2.0 * phase;
  const double s = wave * total;
  if (s >= total) return points_.back();
  // The polyline segment containing s (zero-length segments are skipped by upper_bound).
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  const std::size_t i = static_cast<std::size_t>(it - cumulative_.begin()) - 1;
  const double t = (s - cumulative_[i]) / (cumulative_[i + 1] - cumulative_[i]);
  return vec3(glm::mix(glm::dvec3(points_[i]), glm::dvec3(points_[i + 1]), t));
}

}  // namespace glint
