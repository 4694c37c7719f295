#pragma once
// PrimaryVisibility::automatic: which of the id draw and the compute rasteriser makes the visibility
// G-buffer's ids faster on this GL device and scene. The answer differs by machine, not by a rule
// one could write down: on the H100 only 4 of 132 SMs run fragment shaders, so the compute
// rasteriser takes 0.17 ms where the id draw takes 1.16 (atrium, 1280x720); a GPU whose every SM
// rasterises may go either way. So on a GPU both are timed, once, on the first frame (GL time
// queries): each runs twice, alternating, and its quicker run counts. The compute rasteriser
// replaces the id draw only when it is faster by kComputeRasterMargin: the id draw is the GPU's own
// rasteriser, and the compute one's ids may differ from it where a pixel centre lies within 1/64
// pixel of an edge or two surfaces meet at equal depth (docs/render.md "Compute-rasterised primary
// visibility"), so it must pay clearly, and the margin keeps timing noise from flipping the choice
// from run to run.
//
// On Mesa's software rasterisers (llvmpipe) the id draw is kept untimed. Their "GPU" is the host's
// cores, shared with glint's own host work, and the same 100 ms of ids timed 89 to 145 ms from run to
// run (atrium, 96x54 to 640x360): timing there would flip the choice, and with it edge pixels, between
// runs of the same command. The id draw is never much slower there and 3 times faster at 1280x720
// (0.13 against 0.39 s).
#include "render/raster_settings.h"

#include <functional>
#include <optional>
#include <string_view>

namespace glint::render {

struct PrimaryVisibilityChoice {
  PrimaryVisibility method = PrimaryVisibility::raster;  // raster or compute
  // Each method's quicker timed run; nullopt when nothing was timed (a software renderer).
  std::optional<double> raster_ms;
  std::optional<double> compute_ms;
};

// How much faster the compute rasteriser must be: its time x this < the id draw's.
inline constexpr double kComputeRasterMargin = 1.25;
// Runs of each candidate timed: the first may pay one-off costs (a driver's lazy allocations and
// shader compiles), which the second does not.
inline constexpr int kPrimaryVisibilityTimedRuns = 2;

// The rule on two measured times: compute when compute_ms x kComputeRasterMargin < raster_ms.
PrimaryVisibility faster_primary_visibility(double raster_ms, double compute_ms);

// The choice made without timing anything: the id draw on a software renderer (`gl_renderer`, a
// GL_RENDERER string, that software_gl_renderer names); nullopt on a GPU, where
// choose_primary_visibility times both.
std::optional<PrimaryVisibilityChoice> untimed_primary_visibility(std::string_view gl_renderer);

// The choice on a GPU: `id_draw` and `compute_raster` run alternately, kPrimaryVisibilityTimedRuns
// times each, timed by GL time queries (none may be active), and faster_primary_visibility decides.
// Each candidate must write a complete id image, so the caller may run the winner again or keep what
// it wrote.
PrimaryVisibilityChoice choose_primary_visibility(const std::function<void()>& id_draw,
                                                  const std::function<void()>& compute_raster);

}  // namespace glint::render
