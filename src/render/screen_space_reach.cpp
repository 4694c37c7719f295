#include "render/screen_space_reach.h"

#include "core/error.h"
#include "render/glossy_sampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint::render {
namespace {

bool reflective_at(const ReachGBuffer& g, std::size_t i) {
  return g.world_position.pixels[i].w != 0.0f && g.albedo_reflectivity.pixels[i].w > 0.0f;
}

// The world-space normal of the hit's triangle (unnormalised; only its side matters).
vec3 geometric_normal(const Scene& scene, const accel::Hit& hit) {
  const Instance& instance = scene.instances.at(hit.instance);
  const Mesh& mesh = scene.meshes.at(instance.mesh);
  const std::size_t base = 3 * static_cast<std::size_t>(hit.prim);
  vec3 corner[3];
  for (std::size_t k = 0; k < 3; ++k)
    corner[k] = vec3(instance.transform * vec4(mesh.positions.at(mesh.indices.at(base + k)), 1.0f));
  return glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
}

// Whether the surface the G-buffer shows at `pixel` meets the camera ray through the hit (at
// `to_hit` from the camera, view depth `hit_depth`) within the tolerance: the pixel's tangent plane
// cut by that ray, its depth clamped to [d / 2, 2 d] around the pixel's own depth d as SSR's depth
// pyramid does (a plane seen edge-on would reach any depth).
bool shows_surface_at(const ReachGBuffer& g, const FrameConstants& frame, std::size_t pixel, vec3 to_hit,
                      float hit_depth) {
  const vec4 position = g.world_position.pixels[pixel];
  if (position.w == 0.0f) return false;  // background
  const vec3 normal = vec3(g.world_normal.pixels[pixel]);
  if (!(glm::dot(normal, normal) > 0.0f)) return false;
  const vec3 from_camera = vec3(position) - vec3(frame.camera_position);
  const float depth = (frame.relative_view_projection * vec4(from_camera, 1.0f)).w;
  const float along = glm::dot(normal, from_camera);
  const float across = glm::dot(normal, to_hit);
  const float scale = across != 0.0f ? along / across : std::numeric_limits<float>::infinity();
  if (!(scale > 0.0f)) return false;  // the plane is behind the camera along that ray
  const float plane_depth = std::clamp(scale * hit_depth, 0.5f * depth, 2.0f * depth);
  return std::abs(plane_depth - hit_depth) <= kReachDepthTolerance * hit_depth;
}

ReachClass classify(const Scene& scene, const ReachGBuffer& g, const FrameConstants& frame, const accel::Ray& ray,
                    const accel::Hit& hit) {
  const mat4& clip_from_relative = frame.relative_view_projection;
  if (!hit.valid()) return ReachClass::miss;
  const vec3 to_hit = ray.origin + hit.t * ray.direction - vec3(frame.camera_position);
  const vec4 clip = clip_from_relative * vec4(to_hit, 1.0f);
  const bool in_frustum = clip.w > 0.0f && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w &&
                          std::abs(clip.z) <= clip.w;
  if (!in_frustum) return ReachClass::off_screen;
  // The ray meets the face from one side; the camera must look at that same side.
  const vec3 normal = geometric_normal(scene, hit);
  if (glm::dot(normal, ray.direction) * glm::dot(normal, to_hit) < 0.0f) return ReachClass::occluded;

  const int width = g.world_position.width, height = g.world_position.height;
  const auto pixel_of = [](float ndc, int size) {
    return std::clamp(static_cast<int>(std::floor((ndc * 0.5f + 0.5f) * static_cast<float>(size))), 0, size - 1);
  };
  const int column = pixel_of(clip.x / clip.w, width);
  const int row = height - 1 - pixel_of(clip.y / clip.w, height);  // the images are top row first
  const auto index = [width](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  };
  if (g.visibility_ids) {
    const vec4 id = g.visibility_ids->pixels[index(column, row)];
    if (id.x == static_cast<float>(hit.instance) + 1.0f && id.y == static_cast<float>(hit.prim))
      return ReachClass::on_screen;
  }
  // The pixel under the hit or a neighbour (the hit may lie anywhere in its pixel, the G-buffer was
  // sampled at the centres): a one-pixel margin that counts silhouettes as reachable, so the
  // bound stays a lower bound.
  for (int y = std::max(row - 1, 0); y <= std::min(row + 1, height - 1); ++y)
    for (int x = std::max(column - 1, 0); x <= std::min(column + 1, width - 1); ++x)
      if (shows_surface_at(g, frame, index(x, y), to_hit, clip.w)) return ReachClass::on_screen;
  return ReachClass::occluded;
}

// Whether a ray's direction stays in view (its point at infinity projects inside the viewport): only
// then can a march across the screen show that it leaves the scene without meeting anything.
bool direction_in_view(const FrameConstants& frame, vec3 direction) {
  const vec4 clip = frame.relative_view_projection * vec4(direction, 0.0f);
  return clip.w > 0.0f && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w;
}

}  // namespace

double ScreenSpaceReach::percent(std::size_t count) const {
  return reflective > 0 ? 100.0 * static_cast<double>(count) / static_cast<double>(reflective) : 0.0;
}

ScreenSpaceReach measure_screen_space_reach(const Scene& scene, const rt::RayTracer& tracer, const ReachGBuffer& g,
                                            const FrameConstants& frame, float origin_offset, float fade_end) {
  const int width = g.world_position.width, height = g.world_position.height;
  const auto same_size = [&](const ImageRgbaF& image) { return image.width == width && image.height == height; };
  if (!same_size(g.world_normal) || !same_size(g.albedo_reflectivity) ||
      (g.visibility_ids && !same_size(*g.visibility_ids)))
    fail("screen-space reach: the G-buffer images differ in size (positions are {}x{})", width, height);

  // The ray list's rays (shaders/ray_list.comp.glsl), mirror directions only.
  const vec3 camera = vec3(frame.camera_position);
  std::vector<accel::Ray> rays;
  std::vector<std::size_t> ray_pixels;
  for (std::size_t i = 0; i < g.world_position.pixels.size(); ++i) {
    if (!reflective_at(g, i)) continue;
    const vec3 position = vec3(g.world_position.pixels[i]);
    const vec3 incident = glm::normalize(position - camera);
    const vec3 n = glossy::facing_normal(incident, glm::normalize(vec3(g.world_normal.pixels[i])));
    accel::Ray ray;
    ray.origin = position + origin_offset * n;
    ray.direction = glossy::reflection_direction(incident, n, 0.0f, vec2(0.0f));  // the mirror
    rays.push_back(ray);
    ray_pixels.push_back(i);
  }
  std::vector<accel::Hit> hits(rays.size());
  tracer.trace_closest(rays, hits);

  ScreenSpaceReach reach;
  reach.classes.assign(g.world_position.pixels.size(), ReachClass::not_reflective);
  reach.reflective = rays.size();
  for (std::size_t r = 0; r < rays.size(); ++r) {
    const ReachClass c = classify(scene, g, frame, rays[r], hits[r]);
    reach.classes[ray_pixels[r]] = c;
    const bool shown = !(fade_end > 0.0f) || hits[r].t < fade_end;  // t: world distance (unit direction)
    if ((c == ReachClass::off_screen || c == ReachClass::occluded) && shown) ++reach.must_trace_within_fade;
    switch (c) {
      case ReachClass::on_screen: ++reach.on_screen; break;
      case ReachClass::off_screen: ++reach.off_screen; break;
      case ReachClass::occluded: ++reach.occluded; break;
      case ReachClass::miss:
        ++reach.miss;
        if (!direction_in_view(frame, rays[r].direction)) ++reach.miss_leaving_view;
        break;
      case ReachClass::not_reflective: break;
    }
  }
  return reach;
}

}  // namespace glint::render
