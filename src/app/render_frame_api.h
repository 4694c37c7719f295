#pragma once
// One frame of `glint render`, into memory instead of a PNG: for callers that embed glint (the
// Python module's glint.render, python/module.cpp). It runs what run_render_command runs for a
// one-frame selection (render_pipeline_settings, load_scene, the backend and GPU checks, a headless
// GL context, FrameLoop with the final image captured), so the image equals the PNG
// `glint render <scene> --frames <frame>` writes with the same options. Of RenderOptions, the ones
// that shape a frame are used; the output ones (out, overwrite, debug_views, video, timings_only,
// profile_scopes, command_line) are ignored, and a fixed camera (camera, target) is a glint::Error.
#include "app/render_command.h"
#include "core/image.h"

namespace glint {

// RGBA, top row first, options.width x options.height. glint::Error for bad options (the CLI's one-line
// messages), a frame past the walkthrough, or a GPU backend without a CUDA GPU.
ImageRgba8 render_frame(const RenderOptions& options, int frame);

}  // namespace glint
