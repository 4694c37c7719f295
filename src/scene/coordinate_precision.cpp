#include "scene/coordinate_precision.h"

#include "core/log.h"
#include "core/untrusted_text.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint {

void warn_about_coarse_coordinates(const Scene& scene) {
  std::size_t coarse = 0;
  double fewest_steps = std::numeric_limits<double>::infinity();
  const Instance* worst = nullptr;
  float worst_extent = 0.0f, worst_coordinate = 0.0f, worst_step = 0.0f;
  for (const Instance& instance : scene.instances) {
    const Aabb box = transform_aabb(instance.transform, scene.meshes[instance.mesh].bounds());
    if (box.empty()) continue;
    const vec3 extent = box.extent();
    const float largest_extent = std::max({extent.x, extent.y, extent.z});
    const float coordinate = box.largest_abs_coordinate();
    const float step = std::nextafter(coordinate, std::numeric_limits<float>::infinity()) - coordinate;
    if (!(largest_extent > 0.0f) || !std::isfinite(step)) continue;
    const double steps = static_cast<double>(largest_extent) / static_cast<double>(step);
    if (steps >= kMinCoordinateStepsAcross) continue;
    ++coarse;
    if (steps < fewest_steps) {
      fewest_steps = steps;
      worst = &instance;
      worst_extent = largest_extent;
      worst_coordinate = coordinate;
      worst_step = step;
    }
  }
  if (worst == nullptr) return;
  log_warning("{}: '{}' is {:.3g} units across but {:.3g} from the origin, where float coordinates are {:.2g} apart: "
              "{:.0f} steps across it, so it is drawn coarsely (blocky, triangles lost){}; move the model nearer the "
              "origin in its file (positions are read as floats)",
              scene.source, untrusted_text(worst->name), worst_extent, worst_coordinate, worst_step, fewest_steps,
              coarse > 1 ? fmt::format(" ({} of {} instances are this coarse)", coarse, scene.instances.size()) : "");
}

}  // namespace glint
