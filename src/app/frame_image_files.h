#pragma once
// The image files `glint render` writes for a frame (its final image and, with --debug-views, the
// debug views) in the run's --format: 8-bit sRGB PNGs, or linear EXRs holding the colour before the
// tone map (frame) and the values the views show (core/exr_image.h, render/debug_views.h), the
// frame's EXR naming its tone map (render::kExrToneMapAttribute). Encoding happens on the writer's
// worker threads, off the frame path. Shared by the single-process and the MPI render.
#include "app/frame_loop.h"
#include "app/image_writer_thread.h"
#include "app/output_folder.h"
#include "app/render_command.h"
#include "render/frame_pipeline.h"

namespace glint {

// Whether `options` asks for linear EXRs (--format exr) rather than PNGs.
bool writes_linear_images(const RenderOptions& options);

// What the frame loop must read back for the images of `options` (capture_final, capture_linear);
// nothing with --timings-only.
void set_image_capture(const RenderOptions& options, FrameLoopOptions& loop_options);

// Queues `measured`'s image (moved out) and, with --debug-views, the pipeline's debug views (read
// now: the pipeline must still hold the frame) on `writer`, named by `out` in the run's format.
void write_frame_image_files(ImageWriterThread& writer, const OutputFolder& out, const RenderOptions& options,
                             FrameMeasurement& measured, const render::FramePipeline& pipeline);

}  // namespace glint
