// A regression guard on the whole frame: one atrium frame at low resolution against a stored image.
// Rendering differs slightly between GL implementations (rasterisation rules, texture filtering,
// float precision), so the comparison is by SSIM and PSNR with thresholds that llvmpipe and NVIDIA
// both meet with margin (docs/render.md lists the values measured on each); a broken pass (no
// shadows, no reflections, wrong lighting) drops far below them.
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
constexpr double kMinimumSsim = 0.90;
constexpr double kMinimumPsnr = 24.0;

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
  EXPECT_GE(comparison.ssim.luma, kMinimumSsim);
  EXPECT_GE(comparison.error.psnr, kMinimumPsnr);
}

}  // namespace
}  // namespace glint::render
