#pragma once
// The walkthrough's light: a polyline traversed at constant speed from its first point to its last
// and back (a triangle wave in arc length), once every `period_frames` frames. Frame 0 is at the
// first point and frame period/2 at the last. A polyline rather than a spline because the paper moves
// its light back and forth along straight lines, and a ping-pong has to retrace its corners anyway.
#include "core/math.h"

#include <vector>

namespace glint {

class LightPath {
public:
  // One point: a fixed light. No points: the light stays at `rest_position`. Throws glint::Error when
  // period_frames <= 0 or a point is not finite.
  LightPath(std::vector<vec3> points, int period_frames, vec3 rest_position);

  vec3 at(int frame) const;  // any frame, negative ones included (the wave is periodic)
  float length() const { return static_cast<float>(cumulative_.empty() ? 0.0 : cumulative_.back()); }  // one way

private:
  std::vector<vec3> points_;
  std::vector<double> cumulative_;  // arc length at each point; cumulative_[0] = 0
  int period_frames_ = 1;
};

}  // namespace glint
