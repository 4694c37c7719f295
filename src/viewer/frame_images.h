#pragma once
// The pictures of one rendered view, by the names `set view` and the Views panel use: the final
// image, the pipeline's debug views (render/debug_views.h says how each is made viewable) and,
// when asked for, the difference from the rt reference (a luma heat map with SSIM and PSNR,
// metrics/). Screenshots write them all.
#include "core/image.h"
#include "render/frame_pipeline.h"
#include "viewer/viewer_session.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint::viewer {

struct DifferenceFromRt {
  ImageRgba8 heatmap;  // metrics::luma_error_heatmap, full scale 64 luma levels
  double ssim = 0.0;   // luma SSIM against the reference
  double psnr = 0.0;   // dB, +inf for identical images
};

struct FrameImages {
  // Read from the pipeline only when needed (screenshots, the difference): the viewer shows the
  // final image from its GL texture.
  std::optional<ImageRgba8> final_image;
  std::vector<render::DebugView> views;
  std::optional<DifferenceFromRt> difference;

  // The picture named `view` ("final", a debug view's name or "difference"); null when this frame
  // has none of that name (an SSR view with rt reflections, say) or the final image was not read.
  const ImageRgba8* find(const std::string& view) const;
};

// Compares `final_image` with the rt reference of the same view.
DifferenceFromRt difference_from_reference(const ImageRgba8& final_image, const ImageRgba8& reference);

// Writes the final image (which must have been read) to `path` and every other picture to "<stem>_<name>.png" beside it, each
// through a temporary (write_png), so an interrupted screenshot leaves whole files only. Returns the
// paths written.
std::vector<std::filesystem::path> write_screenshot(const std::filesystem::path& path, const FrameImages& images);

}  // namespace glint::viewer
