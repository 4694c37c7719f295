#include "app/frame_image_files.h"

#include "render/tone_map.h"

#include <string>

namespace glint {

bool writes_linear_images(const RenderOptions& options) { return options.format == "exr"; }

void set_image_capture(const RenderOptions& options, FrameLoopOptions& loop_options) {
  const bool images = !options.timings_only;
  // --video takes the 8-bit frames; the CLI allows it with png only.
  loop_options.capture_final = images && !writes_linear_images(options);
  loop_options.capture_linear = images && writes_linear_images(options);
}

void write_frame_image_files(ImageWriterThread& writer, const OutputFolder& out, const RenderOptions& options,
                             FrameMeasurement& measured, const render::FramePipeline& pipeline) {
  const std::string_view extension = options.format;
  if (measured.final_image) writer.write(out.frame_path(measured.frame, extension), std::move(*measured.final_image));
  if (measured.linear_image)
    writer.write(out.frame_path(measured.frame, extension), std::move(*measured.linear_image),
                 ExrText{{std::string(render::kExrToneMapAttribute), options.tone_map}});
  if (!options.debug_views) return;
  for (render::DebugView& view : pipeline.read_debug_views()) {
    const std::filesystem::path path = out.debug_view_path(measured.frame, view.name, extension);
    if (writes_linear_images(options)) writer.write(path, std::move(view.linear));
    else writer.write(path, std::move(view.image));
  }
}

}  // namespace glint
