#include "scene/procedural/mesh_builder.h"

#include <algorithm>
#include <cmath>

namespace glint::procedural {

int segments_for(float length, float max_segment, int minimum) {
  return std::max(minimum, static_cast<int>(std::ceil(length / max_segment - 1e-4f)));
}

namespace {

// dP/du x dP/dv by central differences, one-sided at the patch border.
vec3 patch_normal(const SurfaceFn& surface, float u, float v) {
  constexpr float h = 1e-3f;
  const float u0 = std::max(0.0f, u - h), u1 = std::min(1.0f, u + h);
  const float v0 = std::max(0.0f, v - h), v1 = std::min(1.0f, v + h);
  const vec3 du = surface(u1, v) - surface(u0, v);
  const vec3 dv = surface(u, v1) - surface(u, v0);
  return glm::cross(du, dv);
}

vec3 safe_normalize(vec3 v, vec3 fallback) {
  const float length = glm::length(v);
  return length > 1e-20f ? v / length : fallback;
}

}  // namespace

void MeshBuilder::add_patch(int nu, int nv, const SurfaceFn& surface, const UvMap& uv, vec3 facing) {
  add_patch(nu, nv, surface, [uv](const vec3&, float u, float v) { return uv.offset + vec2(u, v) * uv.scale; }, facing);
}

void MeshBuilder::add_patch(int nu, int nv, const SurfaceFn& surface, const UvFn& uv, vec3 facing) {
  const bool flip = glm::dot(patch_normal(surface, 0.5f, 0.5f), facing) < 0.0f;
  const vec3 fallback = safe_normalize(facing, vec3(0, 1, 0));
  const auto base = static_cast<std::uint32_t>(mesh_.positions.size());
  for (int j = 0; j <= nv; ++j) {
    const float v = static_cast<float>(j) / static_cast<float>(nv);
    for (int i = 0; i <= nu; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(nu);
      const vec3 p = surface(u, v);
      mesh_.positions.push_back(p);
      const vec3 n = safe_normalize(patch_normal(surface, u, v), fallback);
      mesh_.normals.push_back(flip ? -n : n);
      mesh_.uvs.push_back(uv(p, u, v));
    }
  }
  const auto row = static_cast<std::uint32_t>(nu + 1);
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const std::uint32_t a = base + static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i);
      const std::uint32_t b = a + 1, c = a + row + 1, d = a + row;
      // (a, b, c) is counter-clockwise around dP/du x dP/dv; flipped patches reverse both triangles.
      if (!flip) mesh_.indices.insert(mesh_.indices.end(), {a, b, c, a, c, d});
      else mesh_.indices.insert(mesh_.indices.end(), {a, c, b, a, d, c});
    }
  }
}

void MeshBuilder::add_rectangle(vec3 corner, vec3 edge_u, vec3 edge_v, float max_segment, float uv_metres,
                                vec3 facing) {
  const float lu = glm::length(edge_u), lv = glm::length(edge_v);
  add_patch(segments_for(lu, max_segment), segments_for(lv, max_segment),
            [=](float u, float v) { return corner + u * edge_u + v * edge_v; },
            UvMap{vec2(0.0f), vec2(lu, lv) / uv_metres}, facing);
}

void MeshBuilder::add_box(vec3 lo, vec3 hi, float max_segment, float uv_metres, unsigned faces) {
  const vec3 e = hi - lo;
  const vec3 ex(e.x, 0, 0), ey(0, e.y, 0), ez(0, 0, e.z);
  if (faces & 1u) add_rectangle(lo, ez, ey, max_segment, uv_metres, vec3(-1, 0, 0));
  if (faces & 2u) add_rectangle(lo + ex, ez, ey, max_segment, uv_metres, vec3(1, 0, 0));
  if (faces & 4u) add_rectangle(lo, ex, ez, max_segment, uv_metres, vec3(0, -1, 0));
  if (faces & 8u) add_rectangle(lo + ey, ex, ez, max_segment, uv_metres, vec3(0, 1, 0));
  if (faces & 16u) add_rectangle(lo, ex, ey, max_segment, uv_metres, vec3(0, 0, -1));
  if (faces & 32u) add_rectangle(lo + ez, ex, ey, max_segment, uv_metres, vec3(0, 0, 1));
}

namespace {
// Grid coordinates along one edge: 0, every opening edge, the full length, and uniform
// subdivisions in between so no segment exceeds max_segment.
std::vector<float> breakpoints(float length, const std::vector<float>& cuts, float max_segment) {
  std::vector<float> fixed{0.0f, length};
  for (float c : cuts)
    if (c > 0.0f && c < length) fixed.push_back(c);
  std::sort(fixed.begin(), fixed.end());
  fixed.erase(std::unique(fixed.begin(), fixed.end(), [](float a, float b) { return std::abs(a - b) < 1e-4f; }),
              fixed.end());
  std::vector<float> result;
  for (std::size_t k = 0; k + 1 < fixed.size(); ++k) {
    const int n = segments_for(fixed[k + 1] - fixed[k], max_segment);
    for (int i = 0; i < n; ++i)
      result.push_back(fixed[k] + (fixed[k + 1] - fixed[k]) * static_cast<float>(i) / static_cast<float>(n));
  }
  result.push_back(length);
  return result;
}
}  // namespace

void MeshBuilder::add_wall(vec3 corner, vec3 edge_u, vec3 edge_v, const std::vector<Opening>& openings,
                           float max_segment, float uv_metres, vec3 facing) {
  const float lu = glm::length(edge_u), lv = glm::length(edge_v);
  const vec3 du = edge_u / lu, dv = edge_v / lv;
  std::vector<float> cuts_s, cuts_t;
  for (const Opening& o : openings) {
    cuts_s.insert(cuts_s.end(), {o.s0, o.s1});
    cuts_t.insert(cuts_t.end(), {o.t0, o.t1});
  }
  const std::vector<float> s = breakpoints(lu, cuts_s, max_segment), t = breakpoints(lv, cuts_t, max_segment);
  const bool flip = glm::dot(glm::cross(edge_u, edge_v), facing) < 0.0f;
  const vec3 normal = glm::normalize(flip ? -glm::cross(edge_u, edge_v) : glm::cross(edge_u, edge_v));
  const auto base = static_cast<std::uint32_t>(mesh_.positions.size());
  for (float tv : t)
    for (float su : s) {
      mesh_.positions.push_back(corner + su * du + tv * dv);
      mesh_.normals.push_back(normal);
      mesh_.uvs.push_back(vec2(su, tv) / uv_metres);
    }
  const auto row = static_cast<std::uint32_t>(s.size());
  for (std::size_t j = 0; j + 1 < t.size(); ++j)
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
      const float cs = 0.5f * (s[i] + s[i + 1]), ct = 0.5f * (t[j] + t[j + 1]);
      const bool in_opening = std::any_of(openings.begin(), openings.end(), [&](const Opening& o) {
        return cs > o.s0 && cs < o.s1 && ct > o.t0 && ct < o.t1;
      });
      if (in_opening) continue;
      const std::uint32_t a = base + static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i);
      const std::uint32_t b = a + 1, c = a + row + 1, d = a + row;
      if (!flip) mesh_.indices.insert(mesh_.indices.end(), {a, b, c, a, c, d});
      else mesh_.indices.insert(mesh_.indices.end(), {a, c, b, a, d, c});
    }
}

void MeshBuilder::add_lathe(vec3 base, const std::vector<vec2>& profile, int angular, float uv_metres) {
  // Arc length along the profile gives v, so the texture is not stretched on steep sections.
  std::vector<float> along{0.0f};
  for (std::size_t k = 1; k < profile.size(); ++k) along.push_back(along.back() + glm::length(profile[k] - profile[k - 1]));
  const float total = along.back();
  const auto segments = static_cast<int>(profile.size()) - 1;
  const float circumference = 6.28318530718f * std::max(profile.front().x, profile.back().x);
  const SurfaceFn surface = [&](float u, float v) {
    // Piecewise-linear in the profile, parametrised by arc length.
    const float target = v * total;
    int k = 0;
    while (k + 1 < segments && along[static_cast<std::size_t>(k) + 1] < target) ++k;
    const auto ks = static_cast<std::size_t>(k);
    const float span = std::max(along[ks + 1] - along[ks], 1e-6f);
    const vec2 rh = glm::mix(profile[ks], profile[ks + 1], std::clamp((target - along[ks]) / span, 0.0f, 1.0f));
    const float angle = 6.28318530718f * u;
    return base + vec3(rh.x * std::cos(angle), rh.y, -rh.x * std::sin(angle));
  };
  // One grid row per profile point: v = along[k] / total exactly, so the profile's corners are
  // grid lines. Built row by row (not through add_patch) because rows are not uniform in v.
  const auto first = static_cast<std::uint32_t>(mesh_.positions.size());
  for (std::size_t k = 0; k < profile.size(); ++k) {
    const float v = along[k] / total;
    // Profile tangent for the normal: average of the adjacent segments (smooth profile).
    const vec2 prev = profile[k > 0 ? k - 1 : k], next = profile[k + 1 < profile.size() ? k + 1 : k];
    const vec2 tangent = glm::normalize(next - prev);
    const vec2 outward(tangent.y, -tangent.x);  // rotate (dr, dy) clockwise: points away from the axis when going up
    for (int i = 0; i <= angular; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(angular);
      const float angle = 6.28318530718f * u;
      const vec3 radial(std::cos(angle), 0.0f, -std::sin(angle));
      mesh_.positions.push_back(surface(u, v));
      mesh_.normals.push_back(glm::normalize(radial * outward.x + vec3(0, outward.y, 0)));
      mesh_.uvs.push_back(vec2(u * circumference, along[k]) / uv_metres);
    }
  }
  const auto row = static_cast<std::uint32_t>(angular + 1);
  for (std::uint32_t k = 0; k + 1 < profile.size(); ++k)
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(angular); ++i) {
      const std::uint32_t a = first + k * row + i, b = a + 1, c = a + row + 1, d = a + row;
      // u runs counter-clockwise seen from above (angle measured towards -z), v upwards: (a, b, c)
      // is counter-clockwise seen from outside.
      mesh_.indices.insert(mesh_.indices.end(), {a, b, c, a, c, d});
    }
}

void MeshBuilder::compact() {
  std::vector<std::uint32_t> remap(mesh_.positions.size(), UINT32_MAX);
  std::uint32_t next = 0;
  for (std::uint32_t& index : mesh_.indices) {
    if (remap[index] == UINT32_MAX) remap[index] = next++;
    index = remap[index];
  }
  std::vector<vec3> positions(next), normals(next);
  std::vector<vec2> uvs(mesh_.uvs.empty() ? 0 : next);
  for (std::size_t old = 0; old < remap.size(); ++old) {
    if (remap[old] == UINT32_MAX) continue;
    positions[remap[old]] = mesh_.positions[old];
    normals[remap[old]] = mesh_.normals[old];
    if (!uvs.empty()) uvs[remap[old]] = mesh_.uvs[old];
  }
  mesh_.positions = std::move(positions);
  mesh_.normals = std::move(normals);
  mesh_.uvs = std::move(uvs);
}

}  // namespace glint::procedural
