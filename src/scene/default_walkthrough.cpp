#include "scene/default_walkthrough.h"

#include "core/error.h"
#include "core/log.h"
#include "scene/camera_path.h"
#include "scene/scene_ray_probe.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace glint {
namespace {

// How the default camera and light are placed. A scene that comes without a walkthrough can be an
// interior (a room, a hall: the camera belongs inside), an object (a statue, a cube on a plane: the
// camera belongs around it), or flat (a floor plan, one triangle: the camera belongs above it), and
// the loader cannot tell which. So a few candidate camera loops and light positions of each kind are
// tried against the scene's own triangles with rays (SceneRayProbe), and the best is kept:
//  - a position is in free space when at most a quarter of the rays cast from it in all directions
//    hit a back face (from inside a closed object whose faces point outwards, all of them do; from
//    inside a room whose walls face the room, none do) and no surface is nearer than kClearance of
//    the scene's diagonal;
//  - a camera loop is scored by how much of the view its positions see geometry (a grid of view
//    rays), less when the median view distance is under kCloseUp of the diagonal (a close-up of one
//    surface); every position of the loop must be in free space;
//  - a light is scored by how well it lights the points the camera sees: 0 where it is on the other
//    side of the surface or something is in between, else 0.5 plus half the cosine of incidence (so
//    lighting more counts most, and a light above a floor beats one grazing it); it must be in free
//    space too. Lights that
//    follow the camera, lifted above it, come first: a fixed light cannot light every side of an
//    object the camera circles.
// Candidates are tried in a fixed order, the earlier kept unless a later one is clearly better
// (kClearlyBetter), so the result is deterministic and an interior keeps the classic loop. Every
// length is a fraction of the scene's bounds, so scaling or moving the scene moves the result with it.

constexpr int kSphereRays = 64;          // rays that look around a candidate position
constexpr float kBackFacing = 0.25f;     // most back-face hits a position in free space may have
constexpr float kClearance = 0.01f;      // nearest surface a position may have, times the diagonal
constexpr int kLoopSamples = 24;         // positions of a camera loop that are checked
constexpr int kLoopControlPoints = 12;   // the loop's spline points (closed by repeating the first)
constexpr std::size_t kInteriorLoops = 12;  // camera_candidates: 4 heights x 3 sizes inside the bounds
constexpr int kViewRaysPerSide = 5;      // view rays per candidate camera position: 5 x 5
constexpr float kAspect = 16.0f / 9.0f;  // the default image, 1280x720
constexpr float kCloseUp = 0.08f;        // median view distance, times the diagonal, below which a view is a close-up
constexpr int kLightSamples = 192;
// The default light's radiant intensity: with the renderer's albedo / pi diffuse term (docs/render.md)
// a white surface facing it well within `range` (the diagonal) gets a radiance of about 1.5, which the
// tone map keeps out of saturation. PointLight's own default (20) washes such a scene out to white.
constexpr float kDefaultIntensity = 5.0f;       // most camera-seen points a light candidate is tested against
constexpr float kClearlyBetter = 0.05f;  // a later candidate must beat an earlier one by this much
// Some 10^5 probe rays place the walkthrough. Above this SAH cost per ray (geometry that overlaps
// itself everywhere, a crafted file: real scenes cost 60 to 90, the atrium, Sponza and the Dabrovic
// Sponza alone) that would take seconds to minutes, so the classic candidates are taken unchecked.
constexpr double kMostRayCost = 1000.0;
constexpr float kGoodEnough = 0.95f;     // a candidate this good ends the search (none can be clearly better)

// Points spread evenly over the unit sphere (a Fibonacci spiral), the same every time.
std::vector<vec3> sphere_directions(int count) {
  std::vector<vec3> directions;
  const float golden_angle = glm::pi<float>() * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < count; ++i) {
    const float y = 1.0f - 2.0f * (static_cast<float>(i) + 0.5f) / static_cast<float>(count);
    const float ring = std::sqrt(std::max(0.0f, 1.0f - y * y));
    const float angle = golden_angle * static_cast<float>(i);
    directions.emplace_back(ring * std::cos(angle), y, ring * std::sin(angle));
  }
  return directions;
}

// What the scene's bounds say about its size and where its surface lies.
struct SceneFrame {
  Aabb bounds;
  vec3 centre{0.0f};
  vec3 extent{0.0f};
  float diagonal = 1.0f;
  vec3 centroid{0.0f};   // area-weighted centre of the triangles: on the geometry for a flat scene
  float fov_y_degrees = 60.0f;  // the camera's, kept
  float tolerance = 0.0f;  // distances closer than this are equal (1e-3 of the diagonal, or float's
                           // own precision at the scene's coordinates when that is coarser)
};

SceneFrame scene_frame(const Scene& scene) {
  SceneFrame frame;
  frame.bounds = scene.world_bounds();
  frame.centre = frame.bounds.center();
  frame.extent = frame.bounds.extent();
  frame.diagonal = glm::length(frame.extent);
  frame.fov_y_degrees = scene.walkthrough.camera.fov_y_degrees;
  glm::dvec3 weighted(0.0);
  double area = 0.0;
  for (const Instance& instance : scene.instances) {
    if (instance.mesh >= scene.meshes.size()) continue;
    const Mesh& mesh = scene.meshes[instance.mesh];
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      glm::dvec3 corner[3];
      for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t index = mesh.indices[i + k];
        if (index >= mesh.positions.size()) return frame;  // Scene::validate reports it
        corner[k] = glm::dvec3(instance.transform * vec4(mesh.positions[index], 1.0f));
      }
      const double a = 0.5 * glm::length(glm::cross(corner[1] - corner[0], corner[2] - corner[0]));
      weighted += a * (corner[0] + corner[1] + corner[2]) / 3.0;
      area += a;
    }
  }
  frame.centroid = area > 0.0 && std::isfinite(area) ? vec3(weighted / area) : frame.centre;
  frame.tolerance = std::max(1e-3f * frame.diagonal,
                             8.0f * frame.bounds.largest_abs_coordinate() * std::numeric_limits<float>::epsilon());
  return frame;
}

// Whether each of `points` is in free space (see the comment at the top).
std::vector<bool> in_free_space(const SceneRayProbe& probe, const SceneFrame& frame, const std::vector<vec3>& points) {
  static const std::vector<vec3> directions = sphere_directions(kSphereRays);
  std::vector<accel::Ray> rays;
  rays.reserve(points.size() * directions.size());
  for (const vec3& p : points)
    for (const vec3& d : directions) rays.push_back({p, 0.0f, d, accel::kInfinity});
  const std::vector<ProbeHit> hits = probe.closest(rays);
  std::vector<bool> free(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    int back = 0;
    float nearest = accel::kInfinity;
    for (std::size_t k = 0; k < directions.size(); ++k) {
      const ProbeHit& hit = hits[i * directions.size() + k];
      if (!hit.hit) continue;
      if (glm::dot(hit.normal, directions[k]) > 0.0f) ++back;
      nearest = std::min(nearest, hit.distance);
    }
    free[i] = back <= static_cast<int>(kBackFacing * kSphereRays) && nearest >= kClearance * frame.diagonal;
  }
  return free;
}

// A point the camera sees, and from where.
struct SeenPoint {
  vec3 point;
  vec3 normal;
  std::uint32_t triangle;
  vec3 camera;
  std::size_t sample;  // index of the camera position that sees it
  float distance;      // from the camera
};

// Where a camera is and what it looks at.
struct CameraView {
  vec3 position;
  vec3 target;
};

// Casts a 5 x 5 grid of view rays (the scene's fov, 16:9) from each camera; returns what they hit
// and the share of rays that hit anything.
std::vector<SeenPoint> view_samples(const SceneRayProbe& probe, const SceneFrame& frame,
                                    const std::vector<CameraView>& cameras, float& coverage) {
  const float half_height = std::tan(glm::radians(frame.fov_y_degrees) / 2.0f);
  std::vector<accel::Ray> rays;
  for (const CameraView& camera : cameras) {
    const vec3 forward = glm::normalize(camera.target - camera.position);
    vec3 right = glm::cross(forward, vec3(0.0f, 1.0f, 0.0f));
    right = glm::length(right) > 1e-3f ? glm::normalize(right) : vec3(1.0f, 0.0f, 0.0f);
    const vec3 up = glm::cross(right, forward);
    for (int row = 0; row < kViewRaysPerSide; ++row)
      for (int column = 0; column < kViewRaysPerSide; ++column) {
        // Cell centres of the grid over the image, in [-1, 1].
        const float x = (2.0f * static_cast<float>(column) + 1.0f) / kViewRaysPerSide - 1.0f;
        const float y = (2.0f * static_cast<float>(row) + 1.0f) / kViewRaysPerSide - 1.0f;
        const vec3 d = glm::normalize(forward + x * half_height * kAspect * right + y * half_height * up);
        rays.push_back({camera.position, 0.0f, d, accel::kInfinity});
      }
  }
  const std::vector<ProbeHit> hits = probe.closest(rays);
  std::vector<SeenPoint> seen;
  constexpr std::size_t kRaysPerCamera = kViewRaysPerSide * kViewRaysPerSide;
  for (std::size_t i = 0; i < hits.size(); ++i)
    if (hits[i].hit)
      seen.push_back({hits[i].point, hits[i].normal, hits[i].triangle, cameras[i / kRaysPerCamera].position,
                      i / kRaysPerCamera, hits[i].distance});
  coverage = hits.empty() ? 0.0f : static_cast<float>(seen.size()) / static_cast<float>(hits.size());
  return seen;
}

// A closed camera loop: an ellipse around `centre` in its horizontal plane, every position looking
// at `target`.
struct CameraLoop {
  vec3 centre;
  vec2 radius;  // along x and z
  vec3 target;

  vec3 at(float turn) const {
    const float angle = glm::two_pi<float>() * turn;
    return centre + vec3(radius.x * std::cos(angle), 0.0f, radius.y * std::sin(angle));
  }
};

struct LoopScore {
  int free = -1;          // positions in free space, of kLoopSamples
  float coverage = 0.0f;  // share of view rays that hit geometry
  float view = 0.0f;      // coverage, less for a close-up (see score_loop)
};

bool clearly_better(int free, float score, int best_free, float best_score) {
  return free > best_free || (free == best_free && score > best_score + kClearlyBetter);
}

LoopScore score_loop(const SceneRayProbe& probe, const SceneFrame& frame, const CameraLoop& loop) {
  std::vector<vec3> positions;
  std::vector<CameraView> cameras;
  for (int i = 0; i < kLoopSamples; ++i) {
    positions.push_back(loop.at(static_cast<float>(i) / kLoopSamples));
    cameras.push_back({positions.back(), loop.target});
  }
  LoopScore score;
  const std::vector<bool> free = in_free_space(probe, frame, positions);
  score.free = static_cast<int>(std::count(free.begin(), free.end(), true));
  std::vector<SeenPoint> seen = view_samples(probe, frame, cameras, score.coverage);
  // A view filled by one surface at arm's length (a loop hugging an object) covers the frame but
  // shows little: below a median distance of kCloseUp diagonals the score falls in proportion.
  float closeness = 0.0f;
  if (!seen.empty()) {
    auto middle = seen.begin() + static_cast<std::ptrdiff_t>(seen.size() / 2);
    std::nth_element(seen.begin(), middle, seen.end(),
                     [](const SeenPoint& a, const SeenPoint& b) { return a.distance < b.distance; });
    closeness = std::min(1.0f, middle->distance / (kCloseUp * frame.diagonal));
  }
  score.view = score.coverage * closeness;
  return score;
}

// Interior loops first, the classic one (40 % of the half-extents, a third of the height up, looking
// level) leading; then loops around the geometry's centroid, above it, looking down at it.
std::vector<CameraLoop> camera_candidates(const SceneFrame& frame) {
  std::vector<CameraLoop> loops;
  const vec3& c = frame.centre;
  const vec3& e = frame.extent;
  for (const float height : {1.0f / 3.0f, 0.5f, 0.2f, 0.7f})
    for (const float spread : {0.4f, 0.25f, 0.1f}) {
      const vec3 centre(c.x, frame.bounds.min.y + height * e.y, c.z);
      loops.push_back({centre, spread * 0.5f * vec2(e.x, e.z), centre});
    }
  const float half = 0.5f * frame.diagonal;
  for (const float distance : {1.0f, 0.6f, 1.4f})
    for (const float height : {0.5f, 0.25f, 0.8f}) {
      const vec3 centre = frame.centroid + vec3(0.0f, height * half, 0.0f);
      loops.push_back({centre, vec2(distance * half), frame.centroid});
    }
  return loops;
}

CameraPathSpec camera_path(const CameraLoop& loop, float fov_y_degrees) {
  CameraPathSpec camera;
  camera.fov_y_degrees = fov_y_degrees;
  for (int i = 0; i <= kLoopControlPoints; ++i)
    camera.points.push_back(loop.at(static_cast<float>(i % kLoopControlPoints) / kLoopControlPoints));
  camera.targets = {loop.target};
  return camera;
}

// The camera at kLoopSamples + 1 evenly spaced fractions of its path (first to last), or nothing when
// the camera cannot be animated (Scene::validate reports why).
std::vector<CameraView> camera_views(const CameraPathSpec& camera) {
  Walkthrough walkthrough;
  walkthrough.camera = camera;
  walkthrough.frame_count = kLoopSamples + 1;
  std::vector<CameraView> views;
  try {
    const WalkthroughAnimation animation(walkthrough, vec3(0.0f));
    for (int i = 0; i <= kLoopSamples; ++i) {
      const CameraState state = animation.at(i).camera;
      views.push_back({state.position, state.target});
    }
  } catch (const Error&) {
    views.clear();
  }
  return views;
}

// How well a light at lights[i] lights seen[i]: 0.5 + 0.5 * the cosine of incidence when it is on
// the side the camera sees and nothing is in between, else 0. Lit at all counts most; lit head-on
// rather than grazing breaks ties.
std::vector<float> lighting(const SceneRayProbe& probe, const SceneFrame& frame, const std::vector<vec3>& lights,
                            const std::vector<const SeenPoint*>& seen) {
  std::vector<float> result(seen.size(), 0.0f);
  std::vector<accel::Ray> rays;
  std::vector<std::size_t> pair;  // the pair of each ray
  std::vector<float> distance;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    const SeenPoint& s = *seen[i];
    // A light behind a wall does not light its front.
    const float camera_side = glm::dot(s.normal, s.camera - s.point);
    const float light_side = glm::dot(s.normal, lights[i] - s.point);
    if (!(camera_side * light_side > 0.0f)) continue;
    const vec3 to_point = s.point - lights[i];
    const float length = glm::length(to_point);
    if (!(length > frame.tolerance)) continue;
    rays.push_back({lights[i], 0.0f, to_point / length, length + frame.tolerance});
    pair.push_back(i);
    distance.push_back(length);
  }
  const std::vector<ProbeHit> hits = probe.closest(rays);
  for (std::size_t r = 0; r < hits.size(); ++r) {
    // Nothing in between: the first hit is the point's own triangle, or no nearer than the point.
    const ProbeHit& hit = hits[r];
    const SeenPoint& s = *seen[pair[r]];
    if (!hit.hit || hit.triangle == s.triangle || hit.distance >= distance[r] - frame.tolerance)
      result[pair[r]] = 0.5f + 0.5f * std::abs(glm::dot(s.normal, rays[r].direction));
  }
  return result;
}

// A candidate light. One that follows the camera is at positions[k] while the camera is at view k;
// a sweeping (or fixed) one passes all its positions whatever the camera does.
struct LightCandidate {
  std::vector<vec3> positions;
  bool follows_camera = false;
};

// The mean lighting of `seen` (see lighting()); a sweep counts its worst position. -1 when a position
// is not in free space.
float light_score(const SceneRayProbe& probe, const SceneFrame& frame, const LightCandidate& light,
                  const std::vector<const SeenPoint*>& seen) {
  const std::vector<bool> free = in_free_space(probe, frame, light.positions);
  if (std::find(free.begin(), free.end(), false) != free.end()) return -1.0f;
  if (seen.empty()) return 0.0f;
  const auto mean = [&](const std::vector<vec3>& lights) {
    const std::vector<float> lit = lighting(probe, frame, lights, seen);
    double sum = 0.0;
    for (const float value : lit) sum += value;
    return static_cast<float>(sum / static_cast<double>(lit.size()));
  };
  if (light.follows_camera) {
    std::vector<vec3> lights;
    for (const SeenPoint* s : seen) lights.push_back(light.positions[s->sample]);
    return mean(lights);
  }
  float worst = accel::kInfinity;
  for (const vec3& position : light.positions) worst = std::min(worst, mean(std::vector<vec3>(seen.size(), position)));
  return worst;
}

// Lights that follow the camera, lifted above it, first (they light what it sees wherever it goes,
// even the far side of an object it circles); then sweeps along the longer horizontal axis (0.35 or
// 0.15 of it each way) and fixed points, centred on a 3 x 3 grid over the bounds at heights inside
// them and above them.
std::vector<LightCandidate> light_candidates(const SceneFrame& frame, const std::vector<CameraView>& views) {
  std::vector<LightCandidate> lights;
  const vec3& lo = frame.bounds.min;
  const vec3& e = frame.extent;
  // The height scale of lifts: the scene's height, or a tenth of its diagonal for a flat scene.
  const float vertical = std::max(e.y, 0.1f * frame.diagonal);
  if (!views.empty())
    for (const float lift : {0.4f, 0.25f, 0.55f}) {
      LightCandidate light;
      light.follows_camera = true;
      for (const CameraView& view : views) light.positions.push_back(view.position + vec3(0.0f, lift * vertical, 0.0f));
      lights.push_back(std::move(light));
    }
  const vec3 axis = e.x >= e.z ? vec3(e.x, 0.0f, 0.0f) : vec3(0.0f, 0.0f, e.z);
  std::vector<float> heights;
  for (const float fraction : {0.8f, 0.95f, 0.6f, 0.35f}) heights.push_back(lo.y + fraction * e.y);
  for (const float above : {0.15f, 0.4f}) heights.push_back(frame.bounds.max.y + above * frame.diagonal);
  for (const float height : heights)
    for (const float fx : {0.5f, 0.25f, 0.75f})
      for (const float fz : {0.5f, 0.25f, 0.75f})
        for (const float sweep : {0.35f, 0.15f, 0.0f}) {
          const vec3 centre(lo.x + fx * e.x, height, lo.z + fz * e.z);
          LightCandidate light;
          if (sweep == 0.0f) light.positions = {centre};
          else
            for (const float t : {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f}) light.positions.push_back(centre + t * sweep * axis);
          lights.push_back(std::move(light));
        }
  return lights;
}

// The light for the scene's camera: the candidate that lights what the camera sees best (the earlier
// unless a later one is clearly better).
void place_light(Scene& scene, const SceneRayProbe& probe, const SceneFrame& frame) {
  const std::vector<CameraView> views = camera_views(scene.walkthrough.camera);
  float coverage = 0.0f;
  const std::vector<SeenPoint> seen = view_samples(probe, frame, views, coverage);
  const std::size_t stride = std::max<std::size_t>(1, seen.size() / kLightSamples);
  std::vector<const SeenPoint*> samples;
  for (std::size_t i = 0; i < seen.size(); i += stride) samples.push_back(&seen[i]);

  const std::vector<LightCandidate> lights = light_candidates(frame, views);
  std::size_t chosen = 0;
  float best = -2.0f;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const float score = light_score(probe, frame, lights[i], samples);
    if (i == 0 || score > best + kClearlyBetter) {
      chosen = i;
      best = score;
    }
    if (best >= kGoodEnough) break;
  }
  const LightCandidate& light = lights[chosen];
  LightPathSpec& path = scene.walkthrough.light;
  if (light.follows_camera) {
    // Sampled at equal fractions of the camera's arc length and traversed once, first to last, over
    // the walkthrough (half a ping-pong period), so it keeps step with the camera.
    path.points = light.positions;
    path.period_frames = 2 * std::max(1, scene.walkthrough.frame_count - 1);
    if (std::all_of(path.points.begin(), path.points.end(), [&](const vec3& p) { return p == path.points.front(); }))
      path.points.resize(1);  // a fixed camera: a fixed light
  } else if (light.positions.size() == 1) {
    path.points = light.positions;
  } else {
    path.points = {light.positions.front(), light.positions.back()};
  }
  scene.light.position = path.points.front();
  scene.light.range = frame.diagonal;
  scene.light.intensity = kDefaultIntensity;
  log_info("{}: default light: {} (candidate {} of {}), lighting score {:.0f} % of what the camera sees",
           scene.source,
           light.follows_camera ? "following the camera"
                                : (light.positions.size() == 1 ? "fixed" : "sweeping"),
           chosen + 1, lights.size(), 100.0f * std::max(best, 0.0f));
}

}  // namespace

void assign_default_walkthrough(Scene& scene, const std::optional<CameraPathSpec>& camera) {
  const SceneFrame frame = scene_frame(scene);
  if (frame.bounds.empty() || !(frame.diagonal > 0.0f) || !std::isfinite(frame.diagonal)) return;
  const SceneRayProbe probe(scene);
  if (probe.ray_cost() > kMostRayCost) {
    log_warning("{}: the geometry overlaps itself so much (SAH cost {:.0f} per ray) that the default camera and "
                "light are placed from the scene's bounds alone, unchecked",
                scene.source, probe.ray_cost());
    if (camera) scene.walkthrough.camera = *camera;
    else scene.walkthrough.camera = camera_path(camera_candidates(frame).front(), frame.fov_y_degrees);
    const std::vector<LightCandidate> lights = light_candidates(frame, {});
    scene.walkthrough.light.points = {lights.front().positions.front(), lights.front().positions.back()};
    scene.light.position = 0.5f * (lights.front().positions.front() + lights.front().positions.back());
    scene.light.range = frame.diagonal;
  scene.light.intensity = kDefaultIntensity;
    return;
  }

  if (camera) {
    scene.walkthrough.camera = *camera;
  } else {
    const std::vector<CameraLoop> loops = camera_candidates(frame);
    std::size_t chosen = 0;
    LoopScore best;
    for (std::size_t i = 0; i < loops.size(); ++i) {
      const LoopScore score = score_loop(probe, frame, loops[i]);
      if (i == 0 || clearly_better(score.free, score.view, best.free, best.view)) {
        chosen = i;
        best = score;
      }
      if (best.free == kLoopSamples && best.view >= kGoodEnough) break;
    }
    scene.walkthrough.camera = camera_path(loops[chosen], frame.fov_y_degrees);
    log_info("{}: default camera: loop {} of {} ({}), {} of {} positions in free space, {:.0f} % of the view on "
             "geometry",
             scene.source, chosen + 1, loops.size(), chosen < kInteriorLoops ? "inside the bounds" : "around the geometry",
             best.free, kLoopSamples, 100.0f * best.coverage);
  }
  place_light(scene, probe, frame);
}

}  // namespace glint
