#pragma once
// One way to set up an SsrPass test (ssr_pass_test.cpp, ssr_trust_test.cpp): a synthetic scene
// (synthetic_gbuffer.h) ray cast on the CPU into a G-buffer, uploaded, SsrPass run over it, and its
// reflection, failure mask and counts read back next to the CPU G-buffer the checks compare with.
#include "render/ssr_pass.h"
#include "render/synthetic_gbuffer.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace glint::render::testing {

// A synthetic scene seen by a camera: its frame constants, CPU G-buffer and their GPU copy.
struct SyntheticFrame {
  FrameConstants constants;
  CpuGBuffer cpu;
  GpuGBuffer gpu;
};
// `frame` numbers the frame (the sampling sequence's jitter and seed: frame_constants_for).
SyntheticFrame synthetic_frame(const SyntheticScene& scene, const SyntheticCamera& camera, int width, int height,
                               int frame = 0);

struct SsrRun {
  FrameConstants constants;
  CpuGBuffer cpu;
  std::vector<vec4> reflection;  // SsrPass::reflection(), rows bottom first
  std::vector<std::uint8_t> mask;  // SsrPass::failure_mask()
  SsrCounts counts;
};
// How run_ssr dispatches SsrPass: run() (one dispatch), or march() without the lit image and then
// shade() (FramePipeline's order around one GL-CUDA hand-over).
enum class SsrDispatch { run, march_then_shade };
// SsrPass with `settings` over synthetic_frame(scene, camera, width, height, frame).
SsrRun run_ssr(const SyntheticScene& scene, const SyntheticCamera& camera, int width, int height, int frame,
               const SsrSettings& settings = {}, SsrDispatch dispatch = SsrDispatch::run);

// Pixel i shows a surface that reflects (SSR marches it).
bool reflective(const CpuGBuffer& gbuffer, std::size_t i);

}  // namespace glint::render::testing
