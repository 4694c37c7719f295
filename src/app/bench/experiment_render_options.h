#pragma once
// The render settings every frame of bench's quality experiments (adaptive, glossy) starts from: the
// scene and backend measured, with bench's size, shadow and G-buffer flags, timings only. Each
// experiment then sets what its configurations vary (reflections, budgets, glossy, denoiser).
#include "app/bench_command.h"
#include "app/render_command.h"

#include <string>

namespace glint::bench {

RenderOptions experiment_render_options(const std::string& scene, const std::string& backend,
                                        const BenchOptions& options);

}  // namespace glint::bench
