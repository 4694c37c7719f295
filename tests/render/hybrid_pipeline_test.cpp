// The ray-traced complement inside the whole frame (raster, SSR, ray list, trace, hit shading,
// resolve) on scenes built in code and on the atrium: which pixels get rays, that hybrid leaves SSR's
// pixels alone, that rays find what screen space cannot, and that the choice of backend and update
// policy does not change the image.
#include "metrics/rmse_psnr.h"
#include "metrics/ssim.h"
#include "cuda/device_query.h"
#include "cuda/gl_buffer_interop.h"
#include "render/frame_pipeline.h"
#include "render/gpu_deformation.h"
#include "raster_test_scene.h"
#include "scene/presets.h"
#include "scene/sine_deformer.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint::render {
namespace {

using HybridPipelineTest = testing::GlTest;
using testing::camera_looking_down_the_floor;
using testing::mirror_floor_with_wall;

constexpr int kWidth = 96;
constexpr int kHeight = 64;

// No blur, no fade, no tone curve: a pixel's final colour depends on its own reflection only.
FramePipelineSettings unfiltered(ReflectionMode mode) {
  FramePipelineSettings settings;
  settings.reflections = mode;
  settings.resolve.blur_radius = 0;
  settings.resolve.fade_end = 0.0f;
  settings.resolve.tone_map = ToneMap::none;
  return settings;
}

struct RenderedFrame {
  ImageRgba8 image;
  std::optional<SsrCounts> ssr_counts;
  std::optional<RayTraceFrameStats> ray_stats;
  std::vector<std::uint8_t> failed;  // failure mask per pixel (top row first); empty without SSR
};

RenderedFrame render_frame(const Scene& scene, const FramePipelineSettings& settings, const FrameState& frame,
                           int width = kWidth, int height = kHeight) {
  FramePipeline pipeline(scene, width, height, settings);
  pipeline.render(frame);
  RenderedFrame result{pipeline.read_final(), pipeline.read_counts(), pipeline.ray_trace_stats(), {}};
  for (const DebugView& view : pipeline.read_debug_views())
    if (view.name == "failure_mask")
      for (const auto& p : view.image.pixels) result.failed.push_back(p.x > 127 ? 1 : 0);
  return result;
}

// Pixels clearly redder than grey: the emissive red surfaces' colour added to a grey floor.
int count_red(const ImageRgba8& image) {
  int red = 0;
  for (const auto& p : image.pixels) red += p.x > 150 && p.x > p.y + 80 && p.x > p.z + 80;
  return red;
}

TEST_F(HybridPipelineTest, RaysAreTracedForExactlyTheFailedPixels) {
  const Scene scene = mirror_floor_with_wall(-4.0f);
  const RenderedFrame hybrid = render_frame(scene, unfiltered(ReflectionMode::hybrid), camera_looking_down_the_floor());
  ASSERT_TRUE(hybrid.ssr_counts && hybrid.ray_stats);
  int mask_sum = 0;
  for (const std::uint8_t failed : hybrid.failed) mask_sum += failed;
  EXPECT_GT(mask_sum, 0) << "the sky beyond the wall is not on screen as a reflection";
  EXPECT_EQ(hybrid.ray_stats->rays_traced, static_cast<std::uint32_t>(mask_sum));
  EXPECT_EQ(hybrid.ray_stats->rays_traced, hybrid.ssr_counts->failed);
  EXPECT_EQ(hybrid.ray_stats->reflective_pixels, hybrid.ssr_counts->reflective);
}

TEST_F(HybridPipelineTest, HybridKeepsEverySsrPixelExactly) {
  const Scene scene = mirror_floor_with_wall(-4.0f);
  const RenderedFrame ssr = render_frame(scene, unfiltered(ReflectionMode::ssr), camera_looking_down_the_floor());
  const RenderedFrame hybrid = render_frame(scene, unfiltered(ReflectionMode::hybrid), camera_looking_down_the_floor());
  ASSERT_EQ(ssr.failed, hybrid.failed) << "SSR is deterministic: both runs fail on the same pixels";
  int compared = 0, traced_differ = 0;
  for (std::size_t i = 0; i < ssr.image.pixels.size(); ++i) {
    if (ssr.failed[i] == 0) {
      ASSERT_EQ(ssr.image.pixels[i], hybrid.image.pixels[i]) << "pixel " << i << " did not fail SSR";
      ++compared;
    } else {
      traced_differ += ssr.image.pixels[i] != hybrid.image.pixels[i];
    }
  }
  EXPECT_GT(compared, kWidth * kHeight / 2);
  EXPECT_GT(traced_differ, 0) << "traced pixels receive a reflection SSR did not give them";
}

TEST_F(HybridPipelineTest, WithoutSsrFailuresHybridEqualsSsr) {
  const Scene scene = testing::mirror_strip_before_wall();
  const FrameState frame = testing::look_at(vec3(0.0f, 1.0f, 6.0f), vec3(0.0f, 1.0f, -4.0f), vec3(0.0f, 3.0f, 2.0f));
  const RenderedFrame ssr = render_frame(scene, unfiltered(ReflectionMode::ssr), frame);
  const RenderedFrame hybrid = render_frame(scene, unfiltered(ReflectionMode::hybrid), frame);
  ASSERT_TRUE(ssr.ssr_counts && hybrid.ray_stats);
  ASSERT_GT(ssr.ssr_counts->reflective, 100u);
  ASSERT_EQ(ssr.ssr_counts->failed, 0u) << "the scene is meant to have no SSR failure";
  EXPECT_EQ(hybrid.ray_stats->rays_traced, 0u);
  EXPECT_EQ(ssr.image.pixels, hybrid.image.pixels);
}

TEST_F(HybridPipelineTest, CeilingBehindTheCameraAppearsInHybridAndRtButNotSsr) {
  const Scene scene = testing::mirror_floor_under_ceiling();
  const FrameState frame = testing::camera_looking_steeply_down();
  const RenderedFrame ssr = render_frame(scene, unfiltered(ReflectionMode::ssr), frame);
  const RenderedFrame hybrid = render_frame(scene, unfiltered(ReflectionMode::hybrid), frame);
  const RenderedFrame rt = render_frame(scene, unfiltered(ReflectionMode::rt), frame);
  EXPECT_EQ(count_red(ssr.image), 0);
  EXPECT_GT(count_red(hybrid.image), kWidth * kHeight / 4) << "the floor mirrors the ceiling behind the camera";
  EXPECT_GT(count_red(rt.image), kWidth * kHeight / 4);
  // Every reflective pixel fails SSR here, so hybrid traces the same rays as rt: same image.
  ASSERT_TRUE(hybrid.ssr_counts && rt.ray_stats);
  EXPECT_EQ(hybrid.ssr_counts->failed, hybrid.ssr_counts->reflective);
  EXPECT_EQ(rt.ray_stats->rays_traced, hybrid.ssr_counts->reflective) << "rt traces every reflective pixel";
  EXPECT_EQ(hybrid.image.pixels, rt.image.pixels);
}

// The atrium at a small size, both dinosaurs posed at `frame`.
struct AtriumFrame {
  Scene scene = make_preset("atrium");
  FrameState frame;
  explicit AtriumFrame(int frame_number) {
    SceneDeformers(scene).apply(scene, frame_number);
    frame = WalkthroughAnimation(scene).at(frame_number);
  }
};

TEST_F(HybridPipelineTest, HybridIsCloserToRtThanSsrOnTheAtrium) {
  const AtriumFrame atrium(2100);
  FramePipelineSettings settings;  // the defaults: blur, fade and tone map as users get them
  const auto render_mode = [&](ReflectionMode mode) {
    settings.reflections = mode;
    return render_frame(atrium.scene, settings, atrium.frame, 192, 108).image;
  };
  const ImageRgba8 rt = render_mode(ReflectionMode::rt);
  const double ssr_ssim = metrics::colour_ssim(render_mode(ReflectionMode::ssr), rt).luma;
  const double hybrid_ssim = metrics::colour_ssim(render_mode(ReflectionMode::hybrid), rt).luma;
  EXPECT_GT(hybrid_ssim, ssr_ssim) << "rays fill in what SSR missed";
  EXPECT_GT(hybrid_ssim, 0.9);
}

// Renders the atrium at frame 2100 after the dinosaurs moved from their frame-2000 pose, the ray
// tracer updated by `policy`.
// With `deform_on_gpu` the GPU deformers pose the meshes (GL's vertices in a compute pass, the cuda
// backend's positions in CUDA) instead of the CPU one.
ImageRgba8 deformed_atrium(const std::string& backend, rt::UpdatePolicy policy, bool update_tracer = true,
                           ReflectionMode mode = ReflectionMode::rt, bool deform_on_gpu = false,
                           accel::BvhBuilder builder = accel::BvhBuilder::sah) {
  AtriumFrame atrium(2000);
  FramePipelineSettings settings = unfiltered(mode);
  settings.ray_tracing.backend = backend;
  settings.ray_tracing.update = policy;
  settings.ray_tracing.accel.builder = builder;
  FramePipeline pipeline(atrium.scene, 160, 90, settings);
  if (deform_on_gpu) {
    const SceneDeformers deformers(atrium.scene);
    GpuDeformation gpu_deformer(deformers, pipeline);
    const std::vector<std::uint32_t> dirty = gpu_deformer.apply(2100);
    EXPECT_FALSE(dirty.empty());
    if (update_tracer) pipeline.update_ray_tracer_on_device(dirty);
    pipeline.render(WalkthroughAnimation(atrium.scene).at(2100));
    return pipeline.read_final();
  }
  const std::vector<std::uint32_t> dirty = SceneDeformers(atrium.scene).apply(atrium.scene, 2100);
  EXPECT_FALSE(dirty.empty());
  pipeline.upload_meshes(dirty);
  if (update_tracer) pipeline.update_ray_tracer(dirty);
  pipeline.render(WalkthroughAnimation(atrium.scene).at(2100));
  return pipeline.read_final();
}

TEST_F(HybridPipelineTest, RefitAndRebuildGiveTheSameImage) {
  const ImageRgba8 rebuilt = deformed_atrium("cpu", rt::UpdatePolicy::rebuild);
  const ImageRgba8 refitted = deformed_atrium("cpu", rt::UpdatePolicy::refit);
  EXPECT_GE(metrics::rmse_psnr(refitted, rebuilt).psnr, 50.0);
}

TEST_F(HybridPipelineTest, TheTracerFollowsTheDeformation) {
  const ImageRgba8 updated = deformed_atrium("cpu", rt::UpdatePolicy::refit);
  const ImageRgba8 stale = deformed_atrium("cpu", rt::UpdatePolicy::refit, /*update_tracer=*/false);
  int differing = 0;
  for (std::size_t i = 0; i < updated.pixels.size(); ++i) differing += updated.pixels[i] != stale.pixels[i];
  EXPECT_GT(differing, 0) << "reflections traced against the old pose differ from the new pose's";
}

TEST_F(HybridPipelineTest, CpuAndEmbreeBackendsGiveTheSameImage) {
  const ImageRgba8 cpu = deformed_atrium("cpu", rt::UpdatePolicy::refit);
  const ImageRgba8 embree = deformed_atrium("embree", rt::UpdatePolicy::refit);
  EXPECT_GE(metrics::rmse_psnr(embree, cpu).psnr, 50.0);
}

// The bar for the cuda backend: its frames equal the cpu backend's within PSNR 50 dB, for
// rt and hybrid, refit and rebuild, GPU-built and uploaded structures, and with the deformation done
// on the GPU (GL vertices and the tracer's positions written by CUDA, no host copy).
TEST_F(HybridPipelineTest, CudaBackendGivesTheCpuBackendsImage) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  for (ReflectionMode mode : {ReflectionMode::rt, ReflectionMode::hybrid}) {
    const ImageRgba8 cpu = deformed_atrium("cpu", rt::UpdatePolicy::refit, true, mode);
    for (rt::UpdatePolicy policy : {rt::UpdatePolicy::refit, rt::UpdatePolicy::rebuild})
      for (accel::BvhBuilder builder : {accel::BvhBuilder::lbvh, accel::BvhBuilder::ploc, accel::BvhBuilder::sah})
        EXPECT_GE(metrics::rmse_psnr(deformed_atrium("cuda", policy, true, mode, false, builder), cpu).psnr, 50.0)
            << rt::update_policy_name(policy) << " " << accel::builder_name(builder);
    EXPECT_GE(metrics::rmse_psnr(deformed_atrium("cuda", rt::UpdatePolicy::refit, true, mode, true), cpu).psnr, 50.0)
        << "deformed on the GPU";
  }
}

// Issue 7's bar: the optix backend's frames equal the cuda backend's within PSNR 50 dB (hybrid and
// rt, refit and rebuild, deformed on the GPU).
TEST_F(HybridPipelineTest, OptixBackendGivesTheCudaBackendsImage) {
  if (!GLINT_HAVE_OPTIX) GTEST_SKIP() << "glint was built without OptiX";
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  for (ReflectionMode mode : {ReflectionMode::rt, ReflectionMode::hybrid}) {
    for (rt::UpdatePolicy policy : {rt::UpdatePolicy::refit, rt::UpdatePolicy::rebuild}) {
      const ImageRgba8 cuda = deformed_atrium("cuda", policy, true, mode, true, accel::BvhBuilder::lbvh);
      const ImageRgba8 optix = deformed_atrium("optix", policy, true, mode, true);
      EXPECT_GE(metrics::rmse_psnr(optix, cuda).psnr, 50.0) << rt::update_policy_name(policy);
    }
  }
}

TEST_F(HybridPipelineTest, TheCudaTracerFollowsTheGpuDeformation) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const ImageRgba8 updated = deformed_atrium("cuda", rt::UpdatePolicy::refit, true, ReflectionMode::rt, true);
  const ImageRgba8 stale = deformed_atrium("cuda", rt::UpdatePolicy::refit, false, ReflectionMode::rt, true);
  int differing = 0;
  for (std::size_t i = 0; i < updated.pixels.size(); ++i) differing += updated.pixels[i] != stale.pixels[i];
  EXPECT_GT(differing, 0) << "reflections traced against the rest pose differ from the deformed pose's";
}

// docs/render.md "One hand-over a frame": on a device backend the shadow rays, the reflection rays
// and the hits' shadow rays of a frame are traced in one GL-CUDA-GL round trip (two before: each
// costs 0.3-0.5 ms on an H100), and the frame is still the cpu backend's.
TEST_F(HybridPipelineTest, EveryTraceOfAFrameSharesOneGlCudaRoundTrip) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = mirror_floor_with_wall(-4.0f);
  for (ReflectionMode mode : {ReflectionMode::off, ReflectionMode::ssr, ReflectionMode::hybrid, ReflectionMode::rt}) {
    FramePipelineSettings settings = unfiltered(mode);
    settings.shadows.method = ShadowMethod::rt;
    settings.ray_tracing.backend = "cpu";
    FramePipeline on_cpu(scene, kWidth, kHeight, settings);
    on_cpu.render(camera_looking_down_the_floor());
    settings.ray_tracing.backend = "cuda";
    FramePipeline on_gpu(scene, kWidth, kHeight, settings);
    constexpr int kFrames = 3;
    const std::uint64_t before = cuda::GlBufferInterop::round_trips();
    for (int frame = 0; frame < kFrames; ++frame) on_gpu.render(camera_looking_down_the_floor());
    EXPECT_EQ(cuda::GlBufferInterop::round_trips() - before, static_cast<std::uint64_t>(kFrames))
        << reflection_mode_name(mode);
    EXPECT_GE(metrics::rmse_psnr(on_gpu.read_final(), on_cpu.read_final()).psnr, 50.0) << reflection_mode_name(mode);
  }
}

}  // namespace
}  // namespace glint::render
