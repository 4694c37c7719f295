#include "render/ssr_test_run.h"

#include <utility>

namespace glint::render::testing {

SyntheticFrame synthetic_frame(const SyntheticScene& scene, const SyntheticCamera& camera, int width, int height,
                               int frame) {
  SyntheticFrame result;
  result.constants = frame_constants_for(camera, width, height, frame);
  result.cpu = rasterize(scene, result.constants, width, height);
  result.gpu = upload(result.cpu, result.constants);
  return result;
}

SsrRun run_ssr(const SyntheticScene& scene, const SyntheticCamera& camera, int width, int height, int frame,
               const SsrSettings& settings, SsrDispatch dispatch) {
  SyntheticFrame input = synthetic_frame(scene, camera, width, height, frame);
  SsrPass pass(width, height, settings);
  const SsrInputs inputs{input.gpu.albedo_reflectivity.id(), input.gpu.world_position.id(),
                         input.gpu.world_normal.id(), input.gpu.lit.id(), input.gpu.frame_constants.id()};
  if (dispatch == SsrDispatch::run) {
    pass.run(inputs);
  } else {
    SsrInputs without_lit = inputs;
    without_lit.lit = 0;  // the march must not need it: it runs before lighting
    pass.march(without_lit);
    pass.shade(inputs);
  }
  SsrRun run;
  run.constants = input.constants;
  run.cpu = std::move(input.cpu);
  run.reflection = read_rgba_float(pass.reflection(), width, height);
  run.mask = read_r8ui(pass.failure_mask(), width, height);
  run.counts = pass.read_counts();
  return run;
}

bool reflective(const CpuGBuffer& gbuffer, std::size_t i) {
  return gbuffer.quad[i] >= 0 && gbuffer.albedo_reflectivity[i].w > 0;
}

}  // namespace glint::render::testing
