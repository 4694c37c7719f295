#pragma once
// An independent centripetal Catmull-Rom sampler (Barry-Goldman form) with arc-length lookup, so
// the tests can check where the walkthrough's camera is at a given frame without depending on the
// renderer's own spline code. End segments use mirrored phantom points.
#include "core/math.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace glint::testing {

class CatmullRomSampler {
public:
  explicit CatmullRomSampler(const std::vector<vec3>& points, int samples_per_segment = 200) {
    if (points.size() < 2) {
      samples_.assign(2, points.empty() ? vec3(0.0f) : points.front());
      lengths_ = {0.0f, 0.0f};
      return;
    }
    std::vector<vec3> p;
    p.push_back(2.0f * points[0] - points[1]);
    p.insert(p.end(), points.begin(), points.end());
    p.push_back(2.0f * points.back() - points[points.size() - 2]);
    for (std::size_t s = 1; s + 2 < p.size(); ++s)
      for (int i = 0; i < samples_per_segment; ++i)
        samples_.push_back(segment(p[s - 1], p[s], p[s + 1], p[s + 2], static_cast<float>(i) / static_cast<float>(samples_per_segment)));
    samples_.push_back(points.back());
    lengths_.push_back(0.0f);
    for (std::size_t i = 1; i < samples_.size(); ++i) lengths_.push_back(lengths_.back() + glm::distance(samples_[i], samples_[i - 1]));
  }

  const std::vector<vec3>& samples() const { return samples_; }
  float length() const { return lengths_.back(); }

  // The point at `fraction` (0..1) of the arc length.
  vec3 at_fraction(float fraction) const {
    const float target = std::clamp(fraction, 0.0f, 1.0f) * length();
    const auto it = std::lower_bound(lengths_.begin(), lengths_.end(), target);
    const std::size_t i = std::clamp<std::size_t>(static_cast<std::size_t>(it - lengths_.begin()), 1, lengths_.size() - 1);
    const float span = lengths_[i] - lengths_[i - 1];
    return glm::mix(samples_[i - 1], samples_[i], span > 0.0f ? (target - lengths_[i - 1]) / span : 0.0f);
  }

private:
  static vec3 segment(vec3 p0, vec3 p1, vec3 p2, vec3 p3, float u) {
    auto knot = [](float t, vec3 a, vec3 b) { return t + std::max(std::sqrt(glm::distance(a, b)), 1e-4f); };
    const float t0 = 0.0f, t1 = knot(t0, p0, p1), t2 = knot(t1, p1, p2), t3 = knot(t2, p2, p3);
    const float t = glm::mix(t1, t2, u);
    const vec3 a1 = ((t1 - t) * p0 + (t - t0) * p1) / (t1 - t0);
    const vec3 a2 = ((t2 - t) * p1 + (t - t1) * p2) / (t2 - t1);
    const vec3 a3 = ((t3 - t) * p2 + (t - t2) * p3) / (t3 - t2);
    const vec3 b1 = ((t2 - t) * a1 + (t - t0) * a2) / (t2 - t0);
    const vec3 b2 = ((t3 - t) * a2 + (t - t1) * a3) / (t3 - t1);
    return ((t2 - t) * b1 + (t - t1) * b2) / (t2 - t1);
  }

  std::vector<vec3> samples_;
  std::vector<float> lengths_;
};

}  // namespace glint::testing
