#include "scene/polygon_triangulation.h"

#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>

namespace glint {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

double cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// The polygon's corners in 2D coordinates of its plane, oriented so that the polygon's winding is
// counter-clockwise there; empty when the polygon has no area (no plane to project into).
std::vector<glm::dvec2> project_into_own_plane(std::span<const vec3> corners) {
  // Relative to the first corner, so that a face far from the origin keeps its precision.
  const glm::dvec3 origin(corners[0]);
  std::vector<glm::dvec3> relative;
  relative.reserve(corners.size());
  for (const vec3& corner : corners) relative.push_back(glm::dvec3(corner) - origin);
  // Newell's normal: the polygon's vector area, right-handed with its winding (also for a
  // non-planar or concave polygon, where one corner's cross product can point the wrong way).
  glm::dvec3 normal(0.0);
  for (std::size_t i = 0; i < relative.size(); ++i) normal += glm::cross(relative[i], relative[(i + 1) % relative.size()]);
  const double length = glm::length(normal);
  if (!(length > 0.0) || !std::isfinite(length)) return {};
  normal /= length;
  // u, v, normal right-handed: a polygon counter-clockwise about the normal is counter-clockwise in (u, v).
  const glm::dvec3 axis = std::abs(normal.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(axis, normal));
  const glm::dvec3 v = glm::cross(normal, u);
  std::vector<glm::dvec2> projected;
  projected.reserve(relative.size());
  for (const glm::dvec3& point : relative) projected.emplace_back(glm::dot(point, u), glm::dot(point, v));
  return projected;
}

// The remaining polygon as a doubly linked ring over the corners.
class EarClipper {
public:
  explicit EarClipper(std::vector<glm::dvec2> points) : points_(std::move(points)), prev_(points_.size()), next_(points_.size()) {
    const std::size_t n = points_.size();
    for (std::size_t i = 0; i < n; ++i) {
      prev_[i] = static_cast<std::uint32_t>((i + n - 1) % n);
      next_[i] = static_cast<std::uint32_t>((i + 1) % n);
    }
    remaining_ = n;
  }

  std::vector<Triangle> run(std::uint32_t start) {
    std::vector<Triangle> triangles;
    triangles.reserve(points_.size() - 2);
    std::uint32_t cursor = start;
    std::size_t misses = 0;
    while (remaining_ > 3) {
      if (is_ear(cursor)) {
        cursor = clip(cursor, triangles);
        misses = 0;
      } else if (++misses <= remaining_) {
        cursor = next_[cursor];
      } else {
        // A whole turn without an ear: the polygon crosses itself or is numerically flat. Drop a
        // corner on a straight line if there is one (no area lost), else clip this corner anyway.
        const std::optional<std::uint32_t> after_removal = remove_straight_corner(cursor);
        cursor = after_removal ? *after_removal : clip(cursor, triangles);
        misses = 0;
      }
    }
    triangles.push_back({prev_[cursor], cursor, next_[cursor]});
    return triangles;
  }

private:
  enum class Turn { left, straight, right };

  Turn turn_at(std::uint32_t i) const {
    const glm::dvec2 in = points_[i] - points_[prev_[i]], out = points_[next_[i]] - points_[i];
    const double turn = cross(in, out);
    // Relative to the edges' lengths, so that a face's units do not matter.
    if (std::abs(turn) <= 1e-12 * glm::length(in) * glm::length(out)) return Turn::straight;
    return turn > 0.0 ? Turn::left : Turn::right;
  }

  // A convex corner whose triangle holds no other remaining corner (only corners that do not turn
  // left can be inside it); corners at the same place as the triangle's own do not count.
  bool is_ear(std::uint32_t i) const {
    if (turn_at(i) != Turn::left) return false;
    const glm::dvec2 &a = points_[prev_[i]], &b = points_[i], &c = points_[next_[i]];
    for (std::uint32_t j = next_[next_[i]]; j != prev_[i]; j = next_[j]) {
      const glm::dvec2& p = points_[j];
      if (p == a || p == b || p == c || turn_at(j) == Turn::left) continue;
      if (cross(b - a, p - a) >= 0.0 && cross(c - b, p - b) >= 0.0 && cross(a - c, p - c) >= 0.0) return false;
    }
    return true;
  }

  std::uint32_t clip(std::uint32_t i, std::vector<Triangle>& triangles) {
    triangles.push_back({prev_[i], i, next_[i]});
    return unlink(i);
  }

  std::optional<std::uint32_t> remove_straight_corner(std::uint32_t from) {
    std::uint32_t i = from;
    do {
      if (turn_at(i) == Turn::straight) return unlink(i);
      i = next_[i];
    } while (i != from);
    return std::nullopt;
  }

  std::uint32_t unlink(std::uint32_t i) {
    next_[prev_[i]] = next_[i];
    prev_[next_[i]] = prev_[i];
    --remaining_;
    return next_[i];
  }

  std::vector<glm::dvec2> points_;
  std::vector<std::uint32_t> prev_, next_;
  std::size_t remaining_ = 0;
};

}  // namespace

std::vector<Triangle> triangulate_polygon(std::span<const vec3> corners) {
  const std::size_t n = corners.size();
  if (n < 3) return {};
  if (n == 3) return {Triangle{0, 1, 2}};
  std::vector<glm::dvec2> points = project_into_own_plane(corners);
  if (points.empty()) {  // no area: a fan, whose zero-area triangles the loader drops
    std::vector<Triangle> fan;
    for (std::uint32_t i = 1; i + 1 < n; ++i) fan.push_back({0, i, i + 1});
    return fan;
  }
  // A quad's first ear decides its diagonal: corner 1 gives 0-2, corner 0 gives 1-3. Trying the
  // shorter one's first splits a convex quad as tinyobjloader did (and keeps its triangles fat).
  const auto squared_distance = [&](std::size_t a, std::size_t b) {
    const glm::dvec3 d = glm::dvec3(corners[b]) - glm::dvec3(corners[a]);
    return glm::dot(d, d);
  };
  const std::uint32_t start = n == 4 && squared_distance(0, 2) < squared_distance(1, 3) ? 1 : 0;
  return EarClipper(std::move(points)).run(start);
}

}  // namespace glint
