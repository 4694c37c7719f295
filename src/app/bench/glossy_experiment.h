#pragma once
// `glint bench --experiment glossy` (docs/bench.md "glossy", docs/glossy.md): glossy reflections
// (--glossy on) of ssr, hybrid and rt at 1 sample per pixel, each with the paper's blur and with the
// denoiser, plus mirror hybrid (the paper's frame, the cost baseline), against the converged reference
// (rt, --reference-spp samples, no denoiser; cached in DIR/references/<scene>/) on every scene given,
// at the quality frames below --frames. Per configuration and frame: SSIM and PSNR against the
// reference (metrics::compare_images, as glint compare), the reflection cost (the adaptive
// experiment's columns, app/bench/reflection_cost.h, plus the resolve), and flicker
// (metrics/flicker.h) along the --flicker-frames walkthrough frames ending at the measured frame and
// on the same frame held still (FrameLoop's hold frame) after as many frames of warm-up. Writes
// DIR/glossy.csv, DIR/summary.json (experiment "glossy") and DIR/report.md. Not resumable except for
// the references, which a run with the same settings reuses.
#include "app/bench_command.h"

#include <string>
#include <vector>

namespace glint::bench {

struct GlossyConfig {
  std::string label;        // "ssr", "ssr+denoise", ..., "hybrid-mirror"
  std::string reflections;  // glint render --reflections
  bool glossy = true;       // --glossy on
  bool denoise = false;     // --denoise on (else the paper's blur)
};

// hybrid-mirror, then ssr, hybrid, rt, each without and with the denoiser.
std::vector<GlossyConfig> glossy_configs();

// The walkthrough frames of the flicker series ending at `frame`: max(0, frame - flicker_frames) .. frame.
std::vector<int> walkthrough_series(int frame, int flicker_frames);

int run_glossy_experiment(const BenchOptions& options);

}  // namespace glint::bench
