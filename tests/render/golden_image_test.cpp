// A regression guard on the whole frame: one atrium frame at low resolution (the pipeline's default
// settings: ssr reflections, cube shadows, raster G-buffer) against a stored image made on llvmpipe.
// Rendering differs slightly between GL implementations (rasterisation rules, texture filtering,
// float precision), so the comparison is by SSIM and PSNR, with two sets of thresholds (their reasons
// and the values measured on each renderer: docs/render.md, "Golden image"): on llvmpipe, where only
// float noise separates a run from the stored image, tight enough to catch a change of the SSR image
// like the trusted march's (SSIM 0.968, 26.2 dB); on other renderers (NVIDIA) looser, above what a
// different renderer alone costs. A broken pass (no shadows, no reflections) drops far below both.
//
// After an intended change of the image: GLINT_UPDATE_GOLDEN=1 glint_tests --gtest_filter='GoldenImage*'
// rewrites the stored image (look at it before committing it).
#include "metrics/image_comparison.h"
#include "render/frame_pipeline.h"
#include "scene/camera_path.h"
#include "scene/presets.h"
#include "support/test_paths.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace glint::render {
namespace {

using GoldenImage = testing::GlTest;

constexpr int kFrame = 2100;

struct Thresholds {
  double ssim;  // luma SSIM
  double psnr;  // dB
};
constexpr Thresholds kOnLlvmpipe{0.99, 35.0};
constexpr Thresholds kOnOtherRenderers{0.98, 30.0};

TEST_F(GoldenImage, AtriumFrame2100MatchesTheStoredImage) {
  const std::filesystem::path golden = testing::source_dir() / "tests/data/golden/atrium_frame02100_128x72.png";
  Scene scene = make_preset("atrium");
  const WalkthroughAnimation animation(scene);
  FramePipeline pipeline(scene, 128, 72);
  pipeline.render(animation.at(kFrame));
  const ImageRgba8 image = pipeline.read_final();

  const char* update = std::getenv("GLINT_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    write_png(golden, image);
    GTEST_SKIP() << "rewrote " << golden;
  }
  const metrics::ImageComparison comparison = metrics::compare_images(image, read_png(golden));
  std::printf("golden image: SSIM %.4f, PSNR %.2f dB on %s\n", comparison.ssim.luma, comparison.error.psnr,
              context().renderer().c_str());
  const bool llvmpipe = context().renderer().find("llvmpipe") != std::string::npos;
  const Thresholds minimum = llvmpipe ? kOnLlvmpipe : kOnOtherRenderers;
  EXPECT_GE(comparison.ssim.luma, minimum.ssim);
  EXPECT_GE(comparison.error.psnr, minimum.psnr);
}

}  // namespace
}  // namespace glint::render
