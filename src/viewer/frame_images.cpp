#include "viewer/frame_images.h"

#include "core/error.h"
#include "metrics/error_heatmap.h"
#include "metrics/image_comparison.h"

namespace glint::viewer {

const ImageRgba8* FrameImages::find(const std::string& view) const {
  if (view == "final") return final_image ? &*final_image : nullptr;
  if (view == "difference") return difference ? &difference->heatmap : nullptr;
  for (const render::DebugView& debug : views)
    if (debug.name == view) return &debug.image;
  return nullptr;
}

DifferenceFromRt difference_from_reference(const ImageRgba8& final_image, const ImageRgba8& reference) {
  const metrics::ImageComparison comparison = metrics::compare_images(final_image, reference, "view", "rt reference");
  return {metrics::luma_error_heatmap(final_image, reference, {}, "view", "rt reference"), comparison.ssim.luma,
          comparison.error.psnr};
}

std::vector<std::filesystem::path> write_screenshot(const std::filesystem::path& path, const FrameImages& images) {
  std::vector<std::filesystem::path> written;
  const auto sibling = [&](const std::string& name) {
    return path.parent_path() / (path.stem().string() + "_" + name + ".png");
  };
  if (!images.final_image) fail("{}: the final image was not read", path.string());
  write_png(path, *images.final_image);
  written.push_back(path);
  for (const render::DebugView& view : images.views) {
    write_png(sibling(view.name), view.image);
    written.push_back(sibling(view.name));
  }
  if (images.difference) {
    write_png(sibling("difference"), images.difference->heatmap);
    written.push_back(sibling("difference"));
  }
  return written;
}

}  // namespace glint::viewer
