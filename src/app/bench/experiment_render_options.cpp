#include "app/bench/experiment_render_options.h"

namespace glint::bench {

RenderOptions experiment_render_options(const std::string& scene, const std::string& backend,
                                        const BenchOptions& options) {
  RenderOptions render;
  render.scene = scene;
  render.backend = backend;
  render.width = options.width;
  render.height = options.height;
  render.timings_only = true;
  render.shadow_map_size = options.shadow_map_size;
  render.gbuffer = options.gbuffer;
  render.shadows = options.shadows;
  render.command_line = options.command_line;
  return render;
}

}  // namespace glint::bench
