#include "app/bench/floor_plan.h"

#include "app/bench/paper_matrix.h"
#include "scene/camera_path.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace glint::bench {
namespace {

nlohmann::json top(const vec3& p) { return {p.x, p.z}; }

// At most this many samples along a triangle's side (a 40 m wall in 0.1 m cells needs 800).
constexpr int kMaxSamplesPerSide = 2048;

class FloorGrid {
public:
  FloorGrid(const Aabb& bounds, float y0, float y1) : min_(bounds.min), y0_(y0), y1_(y1) {
    const float width = std::max(bounds.max.x - bounds.min.x, 1e-3f);
    const float depth = std::max(bounds.max.z - bounds.min.z, 1e-3f);
    cell_ = std::max(width, depth) / static_cast<float>(kFloorPlanCells);
    columns_ = std::max(1, static_cast<int>(std::ceil(width / cell_)));
    rows_ = std::max(1, static_cast<int>(std::ceil(depth / cell_)));
    cells_.assign(static_cast<size_t>(rows_), std::string(static_cast<size_t>(columns_), '.'));
  }

  // Marks the cells the triangle covers within the slab (every height when `deformable`), sampled
  // on a barycentric lattice at half a cell's spacing, so thin vertical walls leave a line.
  void add(const vec3& a, const vec3& b, const vec3& c, bool deformable) {
    if (!deformable && (std::max({a.y, b.y, c.y}) < y0_ || std::min({a.y, b.y, c.y}) > y1_)) return;
    const float longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    const int n = std::clamp(static_cast<int>(std::ceil(2.0f * longest / cell_)), 1, kMaxSamplesPerSide);
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const vec3 p = a + (b - a) * (static_cast<float>(i) / static_cast<float>(n)) +
                       (c - a) * (static_cast<float>(j) / static_cast<float>(n));
        if (!deformable && (p.y < y0_ || p.y > y1_)) continue;
        mark(p, deformable ? 'd' : '#');
      }
    }
  }

  nlohmann::json json() const {
    return {{"origin", {min_.x, min_.z}}, {"cell", cell_},  {"columns", columns_}, {"rows", rows_},
            {"slab", {y0_, y1_}},         {"cells", cells_}};
  }

private:
  void mark(const vec3& p, char value) {
    const int column = std::clamp(static_cast<int>((p.x - min_.x) / cell_), 0, columns_ - 1);
    const int row = std::clamp(static_cast<int>((p.z - min_.z) / cell_), 0, rows_ - 1);
    char& cell = cells_[static_cast<size_t>(row)][static_cast<size_t>(column)];
    if (cell != 'd') cell = value;  // the deforming meshes stay visible over what stands around them
  }

  vec3 min_;
  float y0_, y1_;
  float cell_ = 1.0f;
  int columns_ = 1, rows_ = 1;
  std::vector<std::string> cells_;
};

}  // namespace

nlohmann::json floor_plan_json(const Scene& scene, const std::string& scene_name) {
  const WalkthroughAnimation walkthrough(scene);
  const Aabb bounds = scene.world_bounds();
  const int frames = walkthrough.frame_count();
  const int step = std::max(1, frames / 500);
  nlohmann::json camera = nlohmann::json::array(), light = nlohmann::json::array();
  float eye_low = std::numeric_limits<float>::infinity(), eye_high = -eye_low;
  for (int frame = 0; frame < frames; frame += step) {
    const FrameState state = walkthrough.at(frame);
    camera.push_back(top(state.camera.position));
    light.push_back(top(state.light_position));
    eye_low = std::min(eye_low, state.camera.position.y);
    eye_high = std::max(eye_high, state.camera.position.y);
  }
  if ((frames - 1) % step != 0) {
    const FrameState last = walkthrough.at(frames - 1);
    camera.push_back(top(last.camera.position));
    light.push_back(top(last.light_position));
  }
  const float floor = bounds.min.y;
  // A camera at or below the floor (an odd walkthrough): the middle third of the scene's height.
  const bool eye_above = eye_low > floor;
  const float y0 = eye_above ? floor + 0.1f * (eye_low - floor) : floor + (bounds.max.y - floor) / 3.0f;
  const float y1 = eye_above ? floor + 1.5f * (eye_high - floor) : floor + 2.0f * (bounds.max.y - floor) / 3.0f;

  FloorGrid grid(bounds, y0, y1);
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[instance.mesh];
    std::vector<vec3> world(mesh.positions.size());
    for (size_t v = 0; v < world.size(); ++v) world[v] = vec3(instance.transform * vec4(mesh.positions[v], 1.0f));
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
      grid.add(world[mesh.indices[t]], world[mesh.indices[t + 1]], world[mesh.indices[t + 2]], mesh.deformable);
  }

  nlohmann::json marked = nlohmann::json::array();
  for (const int frame : quality_frames(frames)) {
    const FrameState state = walkthrough.at(frame);
    marked.push_back({{"frame", frame}, {"camera", top(state.camera.position)}, {"target", top(state.camera.target)}});
  }
  return {{"scene", scene_name},
          {"bounds", {{"min", {bounds.min.x, bounds.min.y, bounds.min.z}}, {"max", {bounds.max.x, bounds.max.y, bounds.max.z}}}},
          {"grid", grid.json()},
          {"camera", camera},
          {"light", light},
          {"path_step", step},
          {"marked_frames", marked}};
}

}  // namespace glint::bench
